#!/usr/bin/env bash
# Every single-lobe fit alone, as a user runs one: `brdfkit fit FILE -m MODEL --report ngan -o …`, a
# whole process (load, fit, the fitting metric reported), one after the other, on each RGL and
# Cornell file of ../shared/data. Prints the CPU time (user + sys) of the slowest ten and every fit
# above its limit: 10 s on an RGL file, 1 s on a Cornell file. Measure on an idle machine (the load
# average is printed); the fits' own threads count in their CPU time, not in their wall time.
# Reproduce with (warm build):
#   bash bench/single_fit_cpu.sh [OUT_DIR]        (MODELS=, DATA_DIR=, BUILD_DIR= override)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin="${BUILD_DIR:-$root/build}/brdfkit"
data=${DATA_DIR:-$(cd "$root/.." && pwd)/shared/data}
out=${1:-$(mktemp -d)}
[ -x "$bin" ] || { echo "single_fit_cpu.sh: $bin not built (bash scripts/build.sh)" >&2; exit 2; }
[ -d "$data/rgl" ] && [ -d "$data/cornell" ] || { echo "single_fit_cpu.sh: no RGL/Cornell data in $data" >&2; exit 2; }
mkdir -p "$out"
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg)"
models_spec=${MODELS:-single-lobe}
mapfile -t models < <("$bin" models ${models_spec//,/ } --names)
[ ${#models[@]} -gt 0 ] || { echo "single_fit_cpu.sh: no model in MODELS=$models_spec" >&2; exit 2; }
csv="$out/cpu.csv"
echo "kind,material,model,cpu_s,wall_s,limit_s" >"$csv"
for kind in rgl cornell; do
  limit=$([ "$kind" = rgl ] && echo 10 || echo 1)
  for file in "$data/$kind"/*; do
    material=$(basename "${file%.*}")
    for model in "${models[@]}"; do
      /usr/bin/time -f '%U %S %e' -o "$out/time.txt" "$bin" fit "$file" -m "$model" --report ngan \
        -o "$out/$material.$model.json" >/dev/null 2>"$out/$material.$model.err" ||
        { echo "single_fit_cpu.sh: $material $model failed: $(tail -1 "$out/$material.$model.err")" >&2; exit 1; }
      awk -v k="$kind" -v m="$material" -v d="$model" -v l="$limit" \
        '{ printf "%s,%s,%s,%.2f,%.2f,%s\n", k, m, d, $1 + $2, $3, l }' "$out/time.txt" >>"$csv"
    done
  done
done
echo "fits: $(($(wc -l <"$csv") - 1)); ten highest CPU times (s):"
tail -n +2 "$csv" | sort -t, -k4,4 -g -r | head -10 | awk -F, '{ printf "  %7.2f  %s %s (%s)\n", $4, $2, $3, $1 }'
over=$(tail -n +2 "$csv" | awk -F, '$4 > $6')
echo "above the limit (10 s RGL, 1 s Cornell): $(printf '%s' "$over" | grep -c . || true)"
printf '%s\n' "$over" | awk -F, 'NF { printf "  %7.2f  %s %s (limit %s s)\n", $4, $2, $3, $6 }'
echo "per-fit times: $csv"
