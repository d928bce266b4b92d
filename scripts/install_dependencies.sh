#!/usr/bin/env bash
# Installs the Debian packages DF_L1_skeleton needs, if any is missing, and the extra
# packages named as arguments (e.g. imagemagick for the quality script's contact sheets).
# Uses apt-get directly as root, sudo otherwise, and says what it does.
set -euo pipefail
packages=(cmake g++ make libcgal-dev libeigen3-dev libboost-graph-dev libtbb-dev catch2 doxygen librsvg2-bin "$@")
# the Python module and its tests (python/; for /usr/bin/python3)
packages+=(python3-dev python3-pybind11 python3-numpy python3-pytest python3-dask python3-distributed python3-networkx python3-matplotlib)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "dependencies: all installed"
  exit 0
fi
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "error: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
  sudo_cmd=(sudo)
fi
echo "dependencies: installing ${missing[*]} with apt-get"
"${sudo_cmd[@]}" apt-get update -qq
DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq "${missing[@]}"
