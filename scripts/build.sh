#!/usr/bin/env bash
# Configures and builds brdfkit into ${BUILD_DIR:-build} (Release, Ninja). Extra args go to cmake.
# Installs the Python module for Debian's python3 ($PYTHON): a brdfkit.pth file in the user's
# site-packages puts <build>/python on its path, so `import brdfkit` works from any folder.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${BUILD_DIR:-$root/build}
python=${PYTHON:-/usr/bin/python3}
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=${BUILD_TYPE:-Release} -DPython_EXECUTABLE="$python" "$@" >/dev/null
ninja -C "$build" ${NINJA_JOBS:+-j "$NINJA_JOBS"}
if [[ -d "$build/python/brdfkit" ]]; then
  site=$("$python" -c 'import site; print(site.getusersitepackages())')
  mkdir -p "$site"
  echo "$build/python" > "$site/brdfkit.pth"
  echo "build: Python module installed for $python ($site/brdfkit.pth -> $build/python)"
fi
