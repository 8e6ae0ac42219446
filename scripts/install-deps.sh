#!/usr/bin/env bash
# Installs the Debian 12 packages Sortie needs to build, run and test. Idempotent: installs only what is missing.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config git
  ccache  # the build compiles through it when present (CMakeLists.txt SORTIE_CCACHE): a second build or clone reuses the objects
  dpkg-dev file libzip-dev libzstd-dev  # dpkg-shlibdeps and file: CPack's Debian package; libzip: WPML's KMZ archives; zstd: bench_flightlog
  qt6-base-dev qt6-base-dev-tools qt6-declarative-dev qt6-declarative-dev-tools
  qt6-serialport-dev qt6-positioning-dev qt6-tools-dev qt6-tools-dev-tools
  libqt6sql6-sqlite libqt6opengl6-dev libgl-dev libxkbcommon-dev
  qml6-module-qtquick qml6-module-qtquick-controls qml6-module-qtquick-layouts
  qml6-module-qtquick-templates qml6-module-qtquick-window qml6-module-qtquick-shapes
  qml6-module-qtquick-dialogs qml6-module-qtqml-workerscript qml6-module-qtqml-models
  qml6-module-qttest qml6-module-qtquick-tooling qml6-module-qtcore qml6-module-qt-labs-settings
  qml6-module-qt-labs-platform
  qml6-module-qt-labs-folderlistmodel  # Qt Quick's own FileDialog (used where no native one is) lists folders with it
  libprotobuf-dev protobuf-compiler nlohmann-json3-dev libbenchmark-dev
  libboost-dev  # Boost.Geometry (header-only): the airspace check's shapes and R-tree, the DEM folder index
  libproj-dev proj-data  # PROJ and its EGM96 grid (egm96_15.gtx): ellipsoidal heights to AMSL
  gdal-bin  # gdal_translate, gdaladdo: tests/fuzz/make-raster-seeds.sh writes fuzz_raster's seeds
  libgdal-dev  # GDAL: DEM rasters (GeoTIFF, COG, Copernicus, .hgt...) and orthophotos in any CRS (core/raster)
  libexiv2-dev  # exiv2: photos' EXIF and XMP read and their geotagged copies written (core/geotag, sortie-log geotag)
  libgstreamer1.0-dev libgstreamer-plugins-base1.0-dev  # GStreamer: the vehicles' video (core/video), frames from an appsink
  gstreamer1.0-plugins-base gstreamer1.0-plugins-good gstreamer1.0-plugins-bad gstreamer1.0-libav  # RTSP, RTP, MPEG-TS, H.264/H.265 decoders
  gstreamer1.0-plugins-ugly libgstrtspserver-1.0-dev  # x264enc and the RTSP server: sortie-sim's camera streams
  gstreamer1.0-tools  # gst-launch-1.0: the video latency benchmark's reference receiver
  libsdl2-dev  # SDL2: gamepads (core/gamepad), tested with SDL's virtual joysticks
  qt6-quick3d-dev qml6-module-quick3d qml6-module-quick3d-helpers  # Qt Quick 3D: the 3D view (ui/view3d)
  qt6-shadertools-dev  # qt6-quick3d-dev's CMake package asks for Qt6ShaderTools without depending on it
  libgl1-mesa-dri  # Mesa's llvmpipe: the 3D view's tests render with OpenGL under Xvfb
  qtkeychain-qt6-dev libsecret-1-0  # the remembered password in the OS keyring (QtKeychain loads libsecret)
  dbus-daemon gnome-keyring libglib2.0-bin libsecret-tools  # tst_keyring: a session bus, a keyring, gdbus, secret-tool
  clang libclang-rt-14-dev
  llvm-14  # llvm-symbolizer: the sanitizer scripts need it to match the leak suppressions
  lld  # LLVM's linker: every build links with it (CMakeLists.txt, SORTIE_LLD), 3-4 times faster than GNU ld
  xvfb xauth  # scripts/bench-idle.sh: the client on a virtual X display (a benchmark, not a test)
  qt6-translations-l10n  # Qt's own words (qtbase_<lang>.qm: a dialog's "Cancel") in the operator's language; tst_translations checks them
  qt6-l10n-tools  # lupdate and lrelease: the translations (resources/i18n) compiled into the program
  python3  # the translation checks run by ctest (tests/i18n: visible strings, complete .ts files)
  openssl  # the TLS tests make their certificates and keys at test time (tests/support/TestCertificates.h)
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
SUDO=""
[ "$(id -u)" -ne 0 ] && SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
