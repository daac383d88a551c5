#!/usr/bin/env bash
# Installs what is needed, builds, and runs brdfkit's main job on the default data: `fit-all` of
# every single-lobe model to the real measurements of ../shared/data (RGL and Cornell), printing
# the table of errors (models x materials) and saving one JSON per fit, summary.csv and table.txt,
# then `brdfkit report` of those fits (renders under ../shared/data/envmaps/studio.exr when present)
# into results/fits/report; the last line printed is the path of its index.html.
# Rerunning resumes: finished fits are kept. Without the shared data, a material brdfkit tabulates
# itself is fitted instead. Exit status: 0 when the batch ran (fits that failed are listed with
# their reason under the table and in summary.csv), 2 on bad input.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/setup.sh"
bash "$root/scripts/build.sh"
bin="${BUILD_DIR:-$root/build}/brdfkit"
out=${OUT_DIR:-$root/results}
data=${DATA_DIR:-$(cd "$root/.." && pwd)/shared/data}
mkdir -p "$out"
inputs=()
for sub in rgl cornell; do
  [ -d "$data/$sub" ] && inputs+=("$data/$sub")
done
if [ ${#inputs[@]} -eq 0 ]; then
  echo "run.sh: no measured data in $data; fitting a material brdfkit tabulates itself" >&2
  "$bin" tabulate cook-torrance-ggx --param kd=0.3,0.2,0.1 --param alpha=0.15 -o "$out/tabulated-ggx.binary"
  inputs=("$out/tabulated-ggx.binary")
fi
status=0
"$bin" fit-all "${inputs[@]}" --models "${MODELS:-single-lobe}" --jobs "${JOBS:-2}" -o "$out/fits" || status=$?
if [ "$status" -ge 2 ]; then exit "$status"; fi
echo "run.sh: results are in $out/fits (summary.csv, table.txt, <material>/<model>.json)"
env_args=()
[ -f "$data/envmaps/studio.exr" ] && env_args=(--env "$data/envmaps/studio.exr")
"$bin" report "$out/fits" "${env_args[@]}"
