#!/usr/bin/env bash
# Prints the N slowest tests of the last ctest run in BUILD (from CTest's own cost data: the
# seconds each test took last), so a CI log says where its test time went.
# Usage: scripts/slowest-tests.sh BUILD [N=10]
build="${1:?usage: slowest-tests.sh BUILD [N]}"
n="${2:-10}"
costs="$build/Testing/Temporary/CTestCostData.txt"
if [ ! -f "$costs" ]; then
  echo "slowest-tests: no $costs (ctest has not run in $build)"
  exit 0
fi
echo "slowest tests in $build (seconds, last run):"
# Lines are "name runs cost" until a line of dashes (the failed tests follow it).
awk '/^---/ {exit} NF == 3 {printf "%9.1f  %s\n", $3, $1}' "$costs" | sort -rn | head -n "$n"
