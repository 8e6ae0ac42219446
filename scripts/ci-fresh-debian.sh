#!/usr/bin/env bash
# Runs CI (.ci/run) the way a new machine would: in a clean Debian 12 chroot (debootstrap minbase plus
# git), from a fresh clone of a branch of this repository. Needs root and debootstrap. It installs
# everything else itself through scripts/install-deps.sh, so a package missing there fails here.
# Usage: sudo scripts/ci-fresh-debian.sh [chroot dir, default /var/tmp/sortie-ci-chroot] [branch, default current]
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
root="${1:-/var/tmp/sortie-ci-chroot}"
branch="${2:-$(git -C "$repo" rev-parse --abbrev-ref HEAD)}"
mirror="${SORTIE_DEBIAN_MIRROR:-http://deb.debian.org/debian}"

[ "$(id -u)" -eq 0 ] || { echo "ci-fresh-debian: needs root (debootstrap, chroot, mounts)" >&2; exit 2; }
command -v debootstrap >/dev/null || { echo "ci-fresh-debian: install debootstrap first" >&2; exit 2; }

if [ ! -x "$root/usr/bin/apt-get" ]; then
  debootstrap --variant=minbase bookworm "$root" "$mirror"
fi
cp /etc/resolv.conf "$root/etc/resolv.conf"
cat > "$root/etc/apt/sources.list" <<EOF
deb $mirror bookworm main
deb $mirror bookworm-updates main
deb ${mirror%/debian}/debian-security bookworm-security main
EOF

mounted=()
bind() { mkdir -p "$root$2"; mount --bind "$1" "$root$2"; mounted=("$root$2" "${mounted[@]}"); }
cleanup() { for m in "${mounted[@]}"; do umount -l "$m" || true; done; }
trap cleanup EXIT
mount -t proc proc "$root/proc"; mounted=("$root/proc")
bind /dev /dev
bind /dev/pts /dev/pts
mkdir -p "$root/dev/shm"; mount -t tmpfs shm "$root/dev/shm"; mounted=("$root/dev/shm" "${mounted[@]}")
# The repository read-only at the same path, so a worktree's .git file still resolves inside.
git_common=$(cd "$repo" && cd "$(git rev-parse --git-common-dir)" && pwd)
bind "$repo" "$repo"
bind "$git_common" "$git_common"
[ -n "${SORTIE_SHARED_DIR:-}" ] && bind "$SORTIE_SHARED_DIR" /ci/shared

chroot "$root" /usr/bin/env -i HOME=/root PATH=/usr/sbin:/usr/bin:/sbin:/bin LANG=C.UTF-8 \
  CI=true SORTIE_FUZZ_BUDGET="${SORTIE_FUZZ_BUDGET:-240}" bash -euo pipefail -c "
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -qq
    apt-get install -y -qq --no-install-recommends git ca-certificates >/dev/null
    git config --global --add safe.directory '*'
    rm -rf /ci/sortie
    git clone --quiet --no-local --branch '$branch' '$repo' /ci/sortie
    cd /ci/sortie
    echo \"ci-fresh-debian: \$(git log --oneline -1) on \$(. /etc/os-release; echo \$PRETTY_NAME)\"
    start=\$(date +%s)
    CI=true bash .ci/run && rc=0 || rc=\$?
    echo \"ci-fresh-debian: .ci/run exited \$rc after \$(( \$(date +%s) - start ))s\"
    exit \$rc"
