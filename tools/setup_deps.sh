#!/usr/bin/env bash
# Installs the Debian packages BeamSolid builds against, when missing.
# As root it installs them; otherwise it prints the exact line and stops.
set -euo pipefail
packages=(g++ libeigen3-dev libsuitesparse-dev libspectra-dev libgtest-dev libmetis-dev libopenblas0-pthread)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
line="apt-get update && apt-get install -y ${missing[*]}"
if [ "$(id -u)" -eq 0 ]; then
  echo "setup: installing ${missing[*]}"
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${missing[@]}"
else
  echo "setup: missing Debian packages: ${missing[*]}" >&2
  echo "setup: run as root:  sudo sh -c '$line'" >&2
  exit 1
fi
