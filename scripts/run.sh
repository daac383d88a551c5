#!/usr/bin/env bash
# Installs what is needed, builds, and runs brdfkit's main job on the default data:
# the real measurements in ../shared/data when present, else a material brdfkit tabulates itself.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/setup.sh"
bash "$root/scripts/build.sh"
out=${OUT_DIR:-$root/results}
mkdir -p "$out"
"${BUILD_DIR:-$root/build}/brdfkit" main --data "${DATA_DIR:-$root/../shared/data}" -o "$out"
