#!/usr/bin/env bash
# Installs what is needed, builds, and runs every test (GoogleTest through ctest); then builds
# again with AddressSanitizer + UndefinedBehaviorSanitizer and runs the suite under them
# (scripts/sanitize.sh; SANITIZE=0 skips that stage).
# Tests on the real measurements read ../shared/data and skip with a reason when it is absent.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/setup.sh"
bash "$root/scripts/build.sh"
(cd "${BUILD_DIR:-$root/build}" && ctest --output-on-failure -j "$(nproc)")
if [[ "${SANITIZE:-1}" != 0 ]]; then
  bash "$root/scripts/sanitize.sh"
fi
