#!/usr/bin/env bash
# Installs the Debian packages sscc builds with, where they are missing (root or sudo).
set -euo pipefail

packages=(build-essential cmake libeigen3-dev libgmp-dev catch2 libfcl-dev libccd-dev gnuplot-nox libspectra-dev libtet1.5-dev libopenmesh-dev libsndfile1-dev
          python3-dev pybind11-dev python3-numpy python3-pytest python3-matplotlib python3-distributed
          python3-venv python3-pip python3-setuptools-whl python3-wheel-whl ccache doxygen
          clang libclang-rt-14-dev libomp-dev clang-format)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all packages present"
  exit 0
fi
echo "setup: installing ${missing[*]}"
sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
