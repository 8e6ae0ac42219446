#!/usr/bin/env bash
# Builds every libFuzzer target (tests/fuzz/fuzz_*.cpp) with clang under ASan and UBSan and runs each
# for a bounded time on its seed corpus. Usage: scripts/fuzz.sh [seconds per target, default 30]
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
seconds="${1:-30}"
source scripts/sanitized-build.sh
require_symbolizer
build="$sanitized_build"
configure_sanitized_build
targets=$(find tests/fuzz -maxdepth 1 -name 'fuzz_*.cpp' -printf '%f\n' | sed 's/\.cpp$//' | sort)
cmake --build "$build" --target $targets
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:external_symbolizer_path=$ASAN_SYMBOLIZER_PATH" UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
failed=0
for t in $targets; do
  corpus="tests/fuzz/${t#fuzz_}-corpus"
  work=$(mktemp -d)
  [ -d "$corpus" ] && cp -r "$corpus"/. "$work"/
  echo "== $t: ${seconds}s on $(ls "$work" | wc -l) seeds"
  mkdir -p "$build/artifacts"
  if "$build/tests/fuzz/$t" -artifact_prefix="$build/artifacts/" -max_total_time="$seconds" -print_final_stats=1 -max_len=65536 "$work" \
       > "$work.log" 2>&1; then
    grep -E 'stat::number_of_executed_units|Done' "$work.log" | tail -2
  else
    failed=1
    tail -40 "$work.log"
  fi
  rm -rf "$work" "$work.log"
done
[ "$failed" = 0 ] && echo "fuzz: all targets clean" || { echo "fuzz: a target failed"; exit 1; }
