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
# The Khronos glTF validator (npm), for the glTF export test; the test skips without it.
root=$(cd "$(dirname "$0")/.." && pwd)
if command -v npm >/dev/null && [[ ! -f "$root/tools/node_modules/gltf-validator/index.js" ]]; then
  npm install --silent --no-audit --no-fund --prefix "$root/tools" gltf-validator@2.0.0-dev.3.10 >/dev/null 2>&1 ||
    echo "setup: npm could not install gltf-validator (the glTF export test will skip the validator)"
fi
echo "setup: all ${#packages[@]} packages present"
