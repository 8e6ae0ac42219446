#!/usr/bin/env bash
# Checks the Debian package made by scripts/package.sh without touching the system: its Depends
# resolve against the archive (apt-get --simulate), it unpacks into a clean directory (dpkg -x) with
# the programs, the .desktop file and the icon, and the unpacked programs run: sortie --version,
# sortie-sim --help, sortie-plan and sortie-log reading files, and one offscreen launch of the client against its built-in simulator, which
# must show its first frame and quit cleanly.
# Usage: scripts/check-package.sh [dist/sortie_*.deb]
set -euo pipefail
cd "$(dirname "$0")/.."
deb="${1:-$(ls dist/sortie_*.deb | head -1)}"
root=$(mktemp -d)
trap 'rm -rf "$root"' EXIT

echo "check-package: $deb"
apt-get install --simulate --no-install-recommends "./$deb" >"$root/apt.log" 2>&1 \
  || { cat "$root/apt.log"; echo "check-package: the Depends do not resolve" >&2; exit 1; }
dpkg -x "$deb" "$root/install"
for f in usr/bin/sortie usr/bin/sortie-sim usr/bin/sortie-plan usr/bin/sortie-dump usr/bin/sortie-log \
         usr/share/applications/sortie.desktop usr/share/icons/hicolor/scalable/apps/sortie.svg; do
  [ -e "$root/install/$f" ] || { echo "check-package: $f is missing from the package" >&2; exit 1; }
done
bin="$root/install/usr/bin"
# Each program's output is read whole before it is searched: `prog | grep -q` under pipefail fails
# when grep has its match and leaves before prog has written the rest (SIGPIPE), as sortie-sim's
# help, longer than one pipe write, did.
out=$("$bin/sortie" --version) && grep -q '^sortie [0-9]' <<<"$out" \
  || { echo "check-package: sortie --version failed: $out" >&2; exit 1; }
out=$("$bin/sortie-sim" --help) && grep -q -i 'usage' <<<"$out" \
  || { echo "check-package: sortie-sim --help failed (exit $?): $out" >&2; exit 1; }
"$bin/sortie-plan" stats tests/data/samples/qgc/SectionTest.plan >/dev/null \
  || { echo "check-package: sortie-plan stats failed" >&2; exit 1; }
out=$("$bin/sortie-log" info tests/fuzz/sortielog-corpus/session-4-vehicles.sortielog) && grep -q '^vehicles: 4' <<<"$out" \
  || { echo "check-package: sortie-log info failed: $out" >&2; exit 1; }
# A home of its own: the launch writes settings and autosaves, never into the caller's.
mkdir -p "$root/home"
HOME="$root/home" XDG_CONFIG_HOME="$root/home/.config" XDG_DATA_HOME="$root/home/.local/share" \
  XDG_RUNTIME_DIR="$root/home" QT_QPA_PLATFORM=offscreen \
  timeout 120 "$bin/sortie" --demo --report-startup >"$root/launch.log" 2>&1 \
  || { cat "$root/launch.log"; echo "check-package: the installed client did not start and quit cleanly" >&2; exit 1; }
grep -q '^first-frame' "$root/launch.log" || { cat "$root/launch.log"; echo "check-package: no first frame" >&2; exit 1; }
echo "check-package: installed programs run ($(grep '^first-frame' "$root/launch.log"))"
