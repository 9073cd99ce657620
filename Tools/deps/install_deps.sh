#!/usr/bin/env bash
# Installs what the platform needs from Debian 12, and the Python packages of Tools/deps/requirements.txt
# into the project's virtual environment (.venv).
# Non-interactive and idempotent: prints what it installs, installs nothing when all is present.
set -euo pipefail

DEBIAN_PACKAGES=(
  build-essential pkg-config
  luajit libluajit-5.1-dev lua-busted lua-check
  libode-dev libeigen3-dev libopencv-dev
  libusb-1.0-0-dev liburdfdom-dev libreadline-dev
  clang libclang-rt-14-dev
  libpng-dev libzstd-dev zlib1g-dev python3 python3-venv
  libturbojpeg0-dev             # the recorder encodes camera frames to JPEG straight from YUYV
  protobuf-c-compiler libprotobuf-c-dev protobuf-compiler libprotobuf-dev
  chromium                      # the live view's tests drive it headless (Tests/view, Playwright)
)

missing=()
for pkg in "${DEBIAN_PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$pkg")
  fi
done

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi

if [ "${#missing[@]}" -gt 0 ]; then
  echo "deps: installing Debian packages: ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
else
  echo "deps: all Debian packages present"
fi

# Python packages from PyPI go into the project's own virtual environment, made by Debian's Python
# (never into Debian's site-packages): .venv at the project's root.
ROOT="$(cd "$(dirname "$0")/../.." && pwd)"
VENV="$ROOT/.venv"
REQ="$ROOT/Tools/deps/requirements.txt"
if [ ! -x "$VENV/bin/python3" ]; then
  echo "deps: creating the project's Python environment $VENV"
  /usr/bin/python3 -m venv "$VENV"
fi
# pip is asked only when requirements.txt changed since the last successful install
if ! cmp -s "$REQ" "$VENV/.installed-requirements" 2>/dev/null; then
  echo "deps: installing Python packages into $VENV (Tools/deps/requirements.txt)"
  "$VENV/bin/pip" install -q --disable-pip-version-check -r "$REQ"
  cp "$REQ" "$VENV/.installed-requirements"
else
  echo "deps: all Python packages present"
fi
