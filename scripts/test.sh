#!/usr/bin/env bash
# Installs what is needed, builds, and runs every test (GoogleTest through ctest).
# Tests on the real measurements read ../shared/data and skip with a reason when it is absent.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/setup.sh"
bash "$root/scripts/build.sh"
cd "${BUILD_DIR:-$root/build}"
ctest --output-on-failure -j "$(nproc)"
