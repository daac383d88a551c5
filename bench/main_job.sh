#!/usr/bin/env bash
# The README's main job as a benchmark: `fit-all` of every single-lobe model over the default data
# (RGL and Cornell of ../shared/data, 2 jobs), then `brdfkit report` of the fits. Prints wall and
# CPU time and peak RSS of each step, the ten slowest fits, and each fit's fitting-metric error
# against bench/main_job_reference.csv (the last full run's table, 4 significant digits): the count
# of fits worse than 1.005 x the reference, and each of them.
# Reproduce with (warm build):
#   bash bench/main_job.sh [OUT_DIR]        (MODELS=, JOBS=, DATA_DIR=, BUILD_DIR= override)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin="${BUILD_DIR:-$root/build}/brdfkit"
data=${DATA_DIR:-$(cd "$root/.." && pwd)/shared/data}
out=${1:-$(mktemp -d)/main-job}
[ -x "$bin" ] || { echo "main_job.sh: $bin not built (bash scripts/build.sh)" >&2; exit 2; }
[ -d "$data/rgl" ] && [ -d "$data/cornell" ] || { echo "main_job.sh: no RGL/Cornell data in $data" >&2; exit 2; }
[ ! -e "$out" ] || { echo "main_job.sh: $out exists; give a new folder (a rerun would resume, not measure)" >&2; exit 2; }
mkdir -p "$out"

# Runs "$@" under GNU time, its stdout and stderr into $out/<label>.out and .err; prints
# "<label>: wall W s, CPU C s, peak RSS R MB".
measure() {
  local label=$1; shift
  /usr/bin/time -f '%e %U %S %M' -o "$out/$label.time" "$@" >"$out/$label.out" 2>"$out/$label.err" ||
    { echo "main_job.sh: $label failed (exit $?); see $out/$label.err" >&2; return 1; }
  awk -v l="$label" '{ printf "%s: wall %.1f s, CPU %.1f s, peak RSS %.0f MB\n", l, $1, $2 + $3, $4 / 1024 }' \
    "$out/$label.time"
}

measure fit-all "$bin" fit-all "$data/rgl" "$data/cornell" --models "${MODELS:-single-lobe}" --jobs "${JOBS:-2}" \
  -o "$out/fits"
env_args=()
[ -f "$data/envmaps/studio.exr" ] && env_args=(--env "$data/envmaps/studio.exr")
measure report "$bin" report "$out/fits" "${env_args[@]}" -q
python3 "$root/bench/main_job_compare.py" "$out/fits/summary.csv" "$root/bench/main_job_reference.csv"
echo "results: $out/fits; report: $(cat "$out/report.out")"
