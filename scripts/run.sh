#!/usr/bin/env bash
# Installs what is needed, builds, and runs brdfkit's main job on the default data:
# the real measurements in ../shared/data when present, else a material brdfkit tabulates itself.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/setup.sh"
bash "$root/scripts/build.sh"
out=${OUT_DIR:-$root/results}
mkdir -p "$out"
# `info`: what each measured file holds and its directional albedo (human table on stdout, JSON saved).
"${BUILD_DIR:-$root/build}/brdfkit" info --data "${DATA_DIR:-$(cd "$root/.." && pwd)/shared/data}" --out "$out/info.json"
echo "run.sh: results are in $out/info.json"
