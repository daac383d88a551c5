#!/usr/bin/env bash
# Configures and builds brdfkit into ${BUILD_DIR:-build} (Release, Ninja). Extra args go to cmake.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${BUILD_DIR:-$root/build}
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=${BUILD_TYPE:-Release} "$@" >/dev/null
ninja -C "$build" ${NINJA_JOBS:+-j "$NINJA_JOBS"}
