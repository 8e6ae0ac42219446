#!/usr/bin/env bash
# Installs what is missing, builds, and launches Sortie on its embedded simulator.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
build="${SORTIE_BUILD_DIR:-build}"
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build "$build"
exec "$build/app/sortie" --demo "$@"
