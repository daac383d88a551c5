#!/usr/bin/env bash
# Installs every Debian 12 package brdfkit needs to build, test and benchmark (idempotent).
set -euo pipefail
packages=(
  build-essential cmake ninja-build pkg-config
  libeigen3-dev libceres-dev libboost-dev libboost-math-dev
  libcli11-dev nlohmann-json3-dev libfmt-dev libtbb-dev libpng-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libssl-dev
  libopenexr-dev libstb-dev
  chromium
  libtinygltf-dev glslang-tools libosmesa6-dev
  python3 time
  python3-dev pybind11-dev python3-numpy python3-pytest python3-scipy python3-distributed python3-matplotlib
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

# Web parts (package.json, package-lock.json): Apache ECharts, compiled into brdfkit and shipped in
# every report; playwright-core, which drives Debian's chromium in the report test; the Khronos
# glTF validator, which checks the glTF export in its test. Node.js and
# npm from Debian where the machine has none.
root=$(cd "$(dirname "$0")/.." && pwd)
if ! command -v npm >/dev/null; then
  if [[ $(id -u) -ne 0 ]]; then SUDO=sudo; else SUDO=; fi
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends nodejs npm
fi
if [[ ! -f "$root/node_modules/.package-lock.json" || "$root/package-lock.json" -nt "$root/node_modules/.package-lock.json" ]]; then
  (cd "$root" && npm ci --no-audit --no-fund --loglevel=error)
fi
echo "setup: npm packages present ($(cd "$root" && node -p "Object.keys(require('./package-lock.json').packages).length - 1") from package-lock.json)"
