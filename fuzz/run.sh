#!/usr/bin/env bash
# Fuzzes brdfkit's readers with libFuzzer.
#
#   fuzz/run.sh [SECONDS]      (default 600 per target; all targets run at once)
#
# Configures and builds build-fuzz/ (clang-14, the readers' sources under ASan + UBSan, see
# fuzz/CMakeLists.txt), writes the seed corpus (fuzz/make_corpus.py), then runs every fuzz_*
# target for SECONDS under `nice -n 19` with -rss_limit_mb=2048 (an input that makes a reader
# allocate more is a bug) and -timeout=10 (a run that long is a hang). Prints per target: wall
# seconds, executions, executions per second, corpus size and the crash files found; exits 1 if
# there is any.
#
# Targets: fuzz_merl (MERL .binary), fuzz_rgl (RGL .bsdf), fuzz_cornell (.brdf), fuzz_alta
# (.alta slices), fuzz_fit_record (saved fit JSON), fuzz_published_fits (published-fits JSON),
# fuzz_cli_options (the CLI's fit/eval/tabulate options). An InputError is the expected answer to
# bad input; any other exception, a sanitizer report, a crash, a hang or a huge allocation is a
# bug. What each target feeds its reader is in the comment at the top of its file.
#
# Folders, all under build-fuzz/fuzz-work/ (git-ignored): seeds/<target>, corpus/<target> (grows
# across runs), artifacts/<target>/crash-*|timeout-*|oom-*|leak-* (the inputs that failed), and
# logs/<target>.log. Reproduce a failure: build-fuzz/fuzz/<target> <artifact file>. A timeout that
# does not reproduce alone (well under -timeout) was the machine, not the reader: the targets run
# at the lowest priority. The MERL target reads a 35 MB file per full-size input, so it runs a few
# inputs per second where the others run hundreds.
#
# Sanitizer options are built into the targets (sanitizer_options.cpp); ubsan_suppressions.txt
# lists the UB reports skipped because their bug lies outside the readers. Each bug the fuzzers
# found has a regression test in tests/fuzz_regressions/ (brdfkit_fuzz_regressions_tests in the
# main build); build-fuzz also builds them under ASan + UBSan as brdfkit_fuzz_regressions_sanitized.
#
# Environment: BRDFKIT_FUZZ_TARGETS="fuzz_rgl fuzz_alta" runs a subset; BRDFKIT_FUZZ_JOBS sets
# the build's parallelism (default 1: the machine is shared).
set -euo pipefail

seconds=${1:-600}
root=$(cd "$(dirname "$0")/.." && pwd)
build=$root/build-fuzz
work=$build/fuzz-work
targets=${BRDFKIT_FUZZ_TARGETS:-fuzz_merl fuzz_rgl fuzz_cornell fuzz_alta fuzz_fit_record fuzz_published_fits fuzz_cli_options}

CXX=clang++-14 cmake -S "$root" -B "$build" -G Ninja -DBRDFKIT_FUZZ=ON -DBRDFKIT_TESTS=OFF -DBRDFKIT_BENCH=OFF \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
# shellcheck disable=SC2086  # the target list splits on spaces
nice -n 10 ninja -C "$build" -j"${BRDFKIT_FUZZ_JOBS:-1}" $targets

python3 "$root/fuzz/make_corpus.py" "$work/seeds" >/dev/null
mkdir -p "$work/logs"
for t in $targets; do
  mkdir -p "$work/corpus/$t" "$work/artifacts/$t"
  # New inputs go to the first folder (corpus); the seeds are read only.
  (
    start=$(date +%s)
    nice -n 19 "$build/fuzz/$t" -max_total_time="$seconds" -rss_limit_mb=2048 -timeout=10 -print_final_stats=1 \
      -artifact_prefix="$work/artifacts/$t/" "$work/corpus/$t" "$work/seeds/$t" >"$work/logs/$t.log" 2>&1 || true
    echo "$(($(date +%s) - start))" >"$work/logs/$t.wall"
  ) &
done
wait

status=0
printf '%-20s %7s %12s %9s %8s  %s\n' target wall_s execs execs/s corpus crashes
for t in $targets; do
  log=$work/logs/$t.log
  execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo '?')
  rate=$(grep -o 'stat::average_exec_per_sec: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo '?')
  corpus=$(find "$work/corpus/$t" -type f | wc -l)
  crashes=$(find "$work/artifacts/$t" -type f | sort)
  printf '%-20s %7s %12s %9s %8s  %s\n' "$t" "$(cat "$work/logs/$t.wall")" "$execs" "$rate" "$corpus" \
    "$( [ -z "$crashes" ] && echo none || echo "$crashes" | tr '\n' ' ')"
  if [ -n "$crashes" ]; then
    status=1
    grep -m1 -E 'ERROR: (AddressSanitizer|libFuzzer|UndefinedBehaviorSanitizer|LeakSanitizer)|runtime error|uncaught exception|terminate called' "$log" |
      sed "s|^|    $t: |" || true
  fi
done
exit $status
