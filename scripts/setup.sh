#!/usr/bin/env bash
# Installs every Debian 12 package brdfkit needs to build, test and benchmark (idempotent).
set -euo pipefail
packages=(
  build-essential cmake ninja-build pkg-config
  libeigen3-dev libceres-dev libboost-dev libboost-math-dev
  libcli11-dev nlohmann-json3-dev libfmt-dev libtbb-dev libpng-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libssl-dev
  libtinygltf-dev glslang-tools libosmesa6-dev
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  if [[ $(id -u) -ne 0 ]]; then SUDO=sudo; else SUDO=; fi
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
echo "setup: all ${#packages[@]} packages present"
