#!/usr/bin/env bash
# Refreshes the screenshots in docs/images: renders each view offscreen (software scene graph,
# Fusion style) with the UI tests that also check them (tst_mainwindow; tst_uiflows against the
# embedded simulator; tst_flight for the fly view in flight; tst_offlinearea for a drawn offline area;
# tst_resumeview for the offer to resume a mission), writing the PNGs into docs/images.
set -euo pipefail
cd "$(dirname "$0")/.."
build="${SORTIE_BUILD_DIR:-build}"
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" --target tst_mainwindow tst_uiflows tst_flight tst_offlinearea tst_resumeview
mkdir -p docs/images
export QT_QPA_PLATFORM=offscreen SORTIE_SCREENSHOT_DIR="$PWD/docs/images"
"$build/tests/ui/tst_mainwindow" screenshots followsADarkPalette
"$build/tests/ui/tst_uiflows" badPasswordThenGood areaScanOnTheMap liveTelemetryAndCommands
"$build/tests/ui/tst_flight" flyTheDemoRouteOnAnHciVehicle
"$build/tests/ui/tst_offlinearea" drawnOnTheMap
"$build/tests/resume/tst_resumeview"
ls -l docs/images/*.png
