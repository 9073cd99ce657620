#!/usr/bin/env bash
# Installs what the platform needs from Debian 12 (and two Python packages for tests).
# Non-interactive and idempotent: prints what it installs, installs nothing when all is present.
set -euo pipefail

DEBIAN_PACKAGES=(
  build-essential pkg-config
  luajit libluajit-5.1-dev lua-busted lua-check
  libode-dev libeigen3-dev libopencv-dev
  libusb-1.0-0-dev liburdfdom-dev libreadline-dev
  clang libclang-rt-14-dev
  libpng-dev python3 python3-numpy python3-pip
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

# The python3 on PATH may not be Debian's (pyenv, venv): make sure it has numpy and the
# ROBOTIS SDK used as a protocol peer in the Dynamixel tests.
PY=python3
py_missing=()
$PY -c 'import numpy' 2>/dev/null || py_missing+=(numpy)
$PY -c 'import dynamixel_sdk' 2>/dev/null || py_missing+=(dynamixel-sdk==4.1.0)
$PY -c 'import matplotlib' 2>/dev/null || py_missing+=(matplotlib)   # walk plots (Tests/motion)
if [ "${#py_missing[@]}" -gt 0 ]; then
  echo "deps: installing Python packages for $($PY -c 'import sys; print(sys.executable)'): ${py_missing[*]}"
  $PY -m pip install -q "${py_missing[@]}" 2>/dev/null \
    || $PY -m pip install -q --break-system-packages "${py_missing[@]}"
else
  echo "deps: all Python packages present"
fi
