#!/bin/sh
# Runs one test program inside a D-Bus session of its own, with a GNOME Keyring (Secret Service)
# started and unlocked for it, in a throw-away home folder: the test meets a real keyring and never
# the developer's. Works without a desktop, as root, in a container (CI). It cannot hang CI: the
# session is bounded by `timeout`, and the keyring daemon (which leaves the process group when it
# runs in the background) is stopped by its process id afterwards, whatever happened.
#   run-with-keyring.sh SECONDS PROGRAM [ARGS...]
set -u
limit=$1
shift
for tool in dbus-run-session gdbus gnome-keyring-daemon timeout; do
  command -v "$tool" >/dev/null 2>&1 || {
    echo "run-with-keyring: $tool is missing (Debian: bash scripts/install-deps.sh)" >&2
    exit 1
  }
done

home=$(mktemp -d "${TMPDIR:-/tmp}/sortie-keyring.XXXXXX") || exit 1
export HOME="$home" XDG_DATA_HOME="$home/data" XDG_CONFIG_HOME="$home/config" XDG_CACHE_HOME="$home/cache"
export XDG_RUNTIME_DIR="$home/run"
mkdir -p "$XDG_DATA_HOME" "$XDG_CONFIG_HOME" "$XDG_CACHE_HOME" "$XDG_RUNTIME_DIR"
chmod 700 "$XDG_RUNTIME_DIR"
unset DBUS_SESSION_BUS_ADDRESS GNOME_KEYRING_CONTROL

# Inside the session: the daemon reads the login keyring's password from stdin, creates that keyring
# (the default collection) unlocked and claims org.freedesktop.secrets; the test starts once the bus
# shows the name (before that, a request would have the bus start a second, locked daemon).
timeout --kill-after=5 "$limit" dbus-run-session -- sh -c '
  printf "sortie-test-keyring" | gnome-keyring-daemon --foreground --unlock --components=secrets >/dev/null &
  echo $! > "$HOME/keyring.pid"
  gdbus wait --session --timeout 15 org.freedesktop.secrets || {
    echo "run-with-keyring: gnome-keyring-daemon did not come up on the session bus" >&2
    exit 1
  }
  "$@"
' run-with-keyring "$@"
status=$?
[ "$status" -eq 124 ] && echo "run-with-keyring: stopped after $limit s" >&2
pid=$(cat "$home/keyring.pid" 2>/dev/null)
[ -n "$pid" ] && kill "$pid" 2>/dev/null
rm -rf "$home"
exit "$status"
