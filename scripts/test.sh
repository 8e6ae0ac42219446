#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test headless. This is what CI runs.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
build="${SORTIE_BUILD_DIR:-build}"
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release
start=$SECONDS
cmake --build "$build"
echo "test.sh: build done in $((SECONDS - start))s"
start=$SECONDS
trap 'echo "test.sh: tests done in $((SECONDS - start))s"; bash scripts/slowest-tests.sh "$build" 10' EXIT
export QT_QPA_PLATFORM=offscreen
ctest --test-dir "$build" --output-on-failure -j 2 -LE bench "$@"
