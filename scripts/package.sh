#!/usr/bin/env bash
# Builds Sortie (Release) and makes its Debian package with CPack: dist/sortie_<version>_<arch>.deb,
# holding the programs, the .desktop file and the icon, with Depends from dpkg-shlibdeps plus the QML
# modules and Qt plugins the client loads at run time. Install it with: sudo apt install ./dist/sortie_*.deb
# Usage: scripts/package.sh   (SORTIE_BUILD_DIR picks the build folder, default build)
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
build="${SORTIE_BUILD_DIR:-build}"
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build"
mkdir -p dist
rm -f dist/sortie_*.deb
cpack --config "$build/CPackConfig.cmake" -B "$PWD/dist" >/dev/null
rm -rf dist/_CPack_Packages
deb=$(ls dist/sortie_*.deb)
echo "package: $deb ($(du -h "$deb" | cut -f1))"
dpkg-deb --field "$deb" Package Version Architecture Depends
