#!/usr/bin/env bash
# Runs the UI tests N times in a row, as CI runs them (headless, two at a time), and prints which
# failed how often and where (each QtTest FAIL! with its file and line), so that a test which fails
# one run in five is caught before CI catches it. Exits 1 when any run failed.
# Usage: scripts/repeat-ui-tests.sh N [pattern]
#   N        how many runs
#   pattern  a ctest -R pattern instead of every test labelled ui (e.g. 'tst_uiflows|tst_flight')
# SORTIE_BUILD_DIR picks the build folder (default build), SORTIE_REPEAT_JOBS the tests run at once (2).
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:?usage: scripts/repeat-ui-tests.sh N [ctest -R pattern]}
build="${SORTIE_BUILD_DIR:-build}"
select=(-L ui -LE bench)
[ $# -ge 2 ] && select=(-R "$2" -LE bench)
export QT_QPA_PLATFORM=offscreen
logs=$(mktemp -d)
trap 'rm -rf "$logs"' EXIT

failedRuns=0
for run in $(seq 1 "$runs"); do
  if ctest --test-dir "$build" "${select[@]}" -j "${SORTIE_REPEAT_JOBS:-2}" --output-on-failure > "$logs/$run.log" 2>&1; then
    echo "run $run of $runs: passed ($(grep -Eo '[0-9]+ tests passed|100% tests passed, 0 tests failed out of [0-9]+' "$logs/$run.log" | tail -1))"
  else
    failedRuns=$((failedRuns + 1))
    echo "run $run of $runs: FAILED: $(sed -n '/The following tests FAILED:/,$p' "$logs/$run.log" | grep -Eo '[^ ]+ \((Failed|Timeout|SEGFAULT|Subprocess aborted|Exception|Not Run)[^)]*\)' | tr '\n' ' ')"
  fi
done
grep -qE '^Total Test time|tests passed' "$logs/1.log" || { echo "repeat-ui-tests: ctest ran nothing (is $build built?)"; cat "$logs/1.log"; exit 2; }

echo
echo "== failures in $runs runs"
if [ "$failedRuns" = 0 ]; then
  echo "none"
  exit 0
fi
# Which test failed in how many runs, then each failing check (QtTest's FAIL! and its Loc line).
cat "$logs"/*.log | sed -n '/The following tests FAILED:/,/^Errors while running/p' \
  | grep -Eo '[^ ]+ \((Failed|Timeout|SEGFAULT|Subprocess aborted|Exception|Not Run)[^)]*\)' | sort | uniq -c | sort -rn \
  | awk -v runs="$runs" '{ count = $1; $1 = ""; printf "%s failed in %d of %d runs\n", substr($0, 2), count, runs }'
echo
echo "== the failing checks (how many times, the test function, where)"
cat "$logs"/*.log | awk '
  /FAIL!  :/ { fail = $0; sub(/^.*FAIL!  : /, "", fail); sub(/\(\).*$/, "()", fail); next }
  /Loc: \[/ && fail != "" { loc = $0; sub(/^.*Loc: \[/, "", loc); sub(/\]$/, "", loc); print fail "  " loc; fail = "" }
' | sort | uniq -c | sort -rn
exit 1
