# Shared by the scenario scripts that run several scenario programs and print one TAP sequence.
# tap_merge LOG LABEL RC: copies LOG's TAP lines into this script's sequence (the caller's k and
# failed counters), each test named after LABEL; a program that exited with RC != 0 is one more
# failure, shown with the log's tail.
tap_merge() {
  local log=$1 label=$2 rc=$3 line
  while IFS= read -r line; do
    if [[ $line =~ ^(not\ ok|ok)\ [0-9]+\ -\ (.*)$ ]]; then
      k=$((k + 1)); echo "${BASH_REMATCH[1]} $k - $label: ${BASH_REMATCH[2]}"
      [[ ${BASH_REMATCH[1]} == "not ok" ]] && failed=$((failed + 1))
    elif [[ $line == \#* ]]; then echo "$line"; fi
  done <"$log"
  if [ "$rc" -ne 0 ]; then
    k=$((k + 1)); failed=$((failed + 1))
    echo "not ok $k - $label: scenario script exited with status $rc (log $log)"
    tail -n 5 "$log" | sed 's/^/#   /'
  fi
  return 0
}
