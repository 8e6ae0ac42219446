#!/usr/bin/env bash
# Builds every libFuzzer target (tests/fuzz/fuzz_*.cpp) with clang under ASan and UBSan and runs each
# for a bounded time on its seed corpus, as many at a time as there are cores.
# Usage: scripts/fuzz.sh [seconds per target, default 30]    (SORTIE_FUZZ_JOBS: how many at a time)
#        scripts/fuzz.sh --budget SECONDS   the whole run's fuzzing time, shared out evenly over the
#                                           targets (at least 10 s each): what CI gives, so the run
#                                           stays as long as the number of targets grows
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
source scripts/sanitized-build.sh
require_symbolizer
build="$sanitized_build"
configure_sanitized_build
targets=$(find tests/fuzz -maxdepth 1 -name 'fuzz_*.cpp' -printf '%f\n' | sed 's/\.cpp$//' | sort)
jobs_max="${SORTIE_FUZZ_JOBS:-$(nproc)}"
count=$(echo $targets | wc -w)
if [ "${1:-}" = "--budget" ]; then
  budget="${2:?--budget needs a number of seconds}"
  seconds=$(( budget * jobs_max / count ))
  [ "$seconds" -lt 10 ] && seconds=10
  echo "fuzz.sh: a budget of ${budget}s for $count targets, $jobs_max at a time: ${seconds}s each"
else
  seconds="${1:-30}"
fi
start=$SECONDS
cmake --build "$build" --target $targets
echo "fuzz.sh: build done in $((SECONDS - start))s"
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:external_symbolizer_path=$ASAN_SYMBOLIZER_PATH" UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export LSAN_OPTIONS="suppressions=$PWD/tests/sanitizers/lsan.supp:print_suppressions=0"  # as sanitize.sh: leaks inside system libraries, each with why
mkdir -p "$build/artifacts"
results=$(mktemp -d)
trap 'rm -rf "$results"' EXIT

# One target on its seeds for the time given; its log and exit status into $results.
run_target() {
  local t=$1 corpus="tests/fuzz/${1#fuzz_}-corpus" work
  work=$(mktemp -d)
  [ -d "$corpus" ] && cp -r "$corpus"/. "$work"/
  echo "== $t: ${seconds}s on $(ls "$work" | wc -l) seeds" > "$results/$t.log"
  "$build/tests/fuzz/$t" -artifact_prefix="$build/artifacts/" -max_total_time="$seconds" -print_final_stats=1 -max_len=65536 "$work" \
    > "$results/$t.out" 2>&1 && echo 0 > "$results/$t.status" || echo 1 > "$results/$t.status"
  rm -rf "$work"
}

# Each fuzzer is one process on one core: as many at a time as there are cores (SORTIE_FUZZ_JOBS),
# each still for the whole time given, so a run of N targets takes N / cores times that.
start=$SECONDS
for t in $targets; do
  while [ "$(jobs -rp | wc -l)" -ge "$jobs_max" ]; do wait -n || true; done
  run_target "$t" &
done
wait
failed=0
for t in $targets; do
  cat "$results/$t.log"
  if [ "$(cat "$results/$t.status")" = 0 ]; then
    grep -E 'stat::number_of_executed_units|Done' "$results/$t.out" | tail -2
  else
    failed=1
    tail -40 "$results/$t.out"
  fi
done
echo "fuzz.sh: $count targets, ${seconds}s each, $jobs_max at a time, done in $((SECONDS - start))s"
[ "$failed" = 0 ] && echo "fuzz: all targets clean" || { echo "fuzz: a target failed"; exit 1; }
