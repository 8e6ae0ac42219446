#!/usr/bin/env bash
# An idle client's cost: launches sortie on its embedded simulator under Xvfb in two scenes and prints
# the client process's CPU (utime + stime from /proc/PID/stat) and the frames it drew over a window.
#   parked: the mission page, the server's three vehicles on the ground, nothing else (--demo-scene parked)
#   flying: the fly view following one vehicle flying, its telemetry at 10 Hz (--demo-scene flying)
# The simulator runs inside the client (as in --demo): its share is in the figures.
# Usage: scripts/bench-idle.sh path/to/sortie [seconds measured (20)] [seconds to settle (15)] [scene...]
# Also registered as the CTest benchmark bench_idle (label bench); docs/performance.md has the figures.
set -euo pipefail

sortie=${1:?usage: bench-idle.sh path/to/sortie [seconds] [settle] [parked|flying ...]}
seconds=${2:-20}
settle=${3:-15}
shift $(( $# < 3 ? $# : 3 ))
scenes=("${@:-}")
[ -z "${scenes[0]}" ] && scenes=(parked flying)

work=$(mktemp -d)
xvfb_pid=""
app_pid=""
cleanup() {
  [ -n "$app_pid" ] && kill "$app_pid" 2>/dev/null && wait "$app_pid" 2>/dev/null || true
  [ -n "$xvfb_pid" ] && kill "$xvfb_pid" 2>/dev/null && wait "$xvfb_pid" 2>/dev/null || true
  rm -rf "$work"
}
trap cleanup EXIT

# A free display number.
display=99
while [ -e "/tmp/.X${display}-lock" ] || [ -e "/tmp/.X11-unix/X${display}" ]; do display=$((display + 1)); done
Xvfb ":${display}" -screen 0 1280x1024x24 -nolisten tcp >"$work/xvfb.log" 2>&1 &
xvfb_pid=$!
for _ in $(seq 50); do [ -e "/tmp/.X11-unix/X${display}" ] && break; sleep 0.1; done

ticks=$(getconf CLK_TCK)
cpu_ticks() { awk '{ print $14 + $15 }' "/proc/$1/stat"; }  # utime + stime (the name has no spaces)
frames() { grep -o 'frames [0-9]*' "$1" | tail -n 1 | cut -d' ' -f2; }

for scene in "${scenes[@]}"; do
  # A home of its own: no settings, autosaves or keyring of the person running it.
  mkdir -p "$work/$scene/home"
  log="$work/$scene/sortie.log"
  HOME="$work/$scene/home" XDG_CONFIG_HOME="$work/$scene/home/.config" XDG_DATA_HOME="$work/$scene/home/.local/share" \
  XDG_RUNTIME_DIR="$work/$scene" DBUS_SESSION_BUS_ADDRESS="unix:path=$work/no-bus" \
  SORTIE_AUTOSAVE_DIR="$work/$scene/autosave" SORTIE_FLIGHTLOG_DIR="$work/$scene/logs" \
  DISPLAY=":${display}" QT_QPA_PLATFORM=xcb QT_LOGGING_RULES="sortie.frames.debug=true" \
    "$sortie" --demo-scene "$scene" >"$log" 2>&1 &
  app_pid=$!
  sleep "$settle"
  if ! kill -0 "$app_pid" 2>/dev/null; then
    echo "bench-idle: sortie --demo-scene $scene stopped early:" >&2
    cat "$log" >&2
    exit 1
  fi
  cpu0=$(cpu_ticks "$app_pid"); frames0=$(frames "$log"); t0=$(date +%s.%N)
  sleep "$seconds"
  cpu1=$(cpu_ticks "$app_pid"); frames1=$(frames "$log"); t1=$(date +%s.%N)
  kill "$app_pid"; wait "$app_pid" 2>/dev/null || true
  app_pid=""
  awk -v s="$scene" -v c0="$cpu0" -v c1="$cpu1" -v f0="${frames0:-0}" -v f1="${frames1:-0}" -v t0="$t0" -v t1="$t1" -v hz="$ticks" \
    'BEGIN { wall = t1 - t0; printf "%-7s cpu %5.1f %% of a core, %5.1f frames/s (%d frames in %.1f s)\n", s, 100 * (c1 - c0) / hz / wall, (f1 - f0) / wall, f1 - f0, wall }'
done
