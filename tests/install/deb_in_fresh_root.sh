#!/usr/bin/env bash
# Installs the .deb that `cpack -G DEB` made into a brand-new Debian 12 root and renders the
# installed showcase there with the installed config, headless: proof that the package's
# dependencies are complete and that the installed engine needs no build tree.
#   deb_in_fresh_root.sh BASE_TARBALL ROOT_DIR PACKAGE.deb
# BASE_TARBALL: a debootstrap --variant=minbase bookworm tree as a tar (without ./dev).
# Needs root (chroot, mounts) and the network (apt fetches the dependencies).
#
# Safety: the chroot gets its OWN /dev (a tmpfs with a handful of device nodes and a new
# devpts instance), never a bind of the host's /dev, and the old root is removed only after
# every mount under it is gone (rm --one-file-system as a second guard).
set -euo pipefail
base=$1 root=$2 deb=$3
[ "$(id -u)" -eq 0 ] || { echo "deb_in_fresh_root: needs root" >&2; exit 2; }

unmount_all() {  # every mount at or under $root, deepest first
  local m
  for m in $(awk -v r="$root" '$2 == r || index($2, r "/") == 1 {print $2}' /proc/mounts | sort -r); do
    umount "$m" 2>/dev/null || umount -l "$m" 2>/dev/null || true
  done
  if awk -v r="$root" '$2 == r || index($2, r "/") == 1 {found=1} END {exit !found}' /proc/mounts; then
    echo "deb_in_fresh_root: mounts remain under $root; refusing to delete it" >&2; return 1
  fi
}

unmount_all
rm -rf --one-file-system "$root"; mkdir -p "$root"; tar -C "$root" -xf "$base"
cp "$deb" "$root/root/"
cp /etc/resolv.conf "$root/etc/resolv.conf" 2>/dev/null || true
trap 'unmount_all || true' EXIT INT TERM
mkdir -p "$root/proc" "$root/dev" "$root/tmp"
mount -t proc proc "$root/proc"
mount -t tmpfs -o mode=755 devfs "$root/dev"
while read -r name major minor; do mknod -m 666 "$root/dev/$name" c "$major" "$minor"; done <<'NODES'
null 1 3
zero 1 5
full 1 7
random 1 8
urandom 1 9
tty 5 0
NODES
mkdir -p "$root/dev/pts" "$root/dev/shm"
mount -t devpts -o newinstance,ptmxmode=0666 devpts "$root/dev/pts" && ln -s pts/ptmx "$root/dev/ptmx"
ln -s /proc/self/fd "$root/dev/fd"
ln -s /proc/self/fd/0 "$root/dev/stdin"; ln -s /proc/self/fd/1 "$root/dev/stdout"; ln -s /proc/self/fd/2 "$root/dev/stderr"
mount -t tmpfs tmpfs "$root/tmp"; mount -t tmpfs tmpfs "$root/dev/shm"

# Inside: apt resolves the package's Depends, then the installed tools run from /tmp (no
# content/ there), with the installed config and scene, on llvmpipe through EGL.
chroot "$root" /usr/bin/env -i HOME=/root PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
  DEBIAN_FRONTEND=noninteractive MESA_SHADER_CACHE_DISABLE=true bash -euxc "
    apt-get update -qq
    apt-get install -y -qq --no-install-recommends /root/$(basename "$deb") > /tmp/apt.log 2>&1 || { tail -30 /tmp/apt.log; exit 1; }
    tail -3 /tmp/apt.log
    dpkg -s shadow-engine | grep -E '^(Version|Depends):'
    cd /tmp
    data=/usr/share/shadow-engine
    engine-render --config \$data/engine.json --scene \$data/scenes/showcase.gltf --out x.png --width 320 --height 240
    engine-render --scene \$data/scenes/showcase.gltf --out default-config.png --width 320 --height 240
    engine-render --config \$data/engine.json --scene \$data/scenes/showcase.gltf --out t.png --width 320 --height 240 --truth
    ls -l x.png default-config.png t.png
    shadowmap-bench --scene \$data/scenes/showcase.gltf --variants standard --resolutions 512 --depth-formats d24 --filters pcf --frames 1 --width 160 --height 120 --out bench
    head -3 bench/results.csv
    cp \$data/scenes/showcase.gltf \$data/scenes/showcase.bin .
    shadowmap-tune --scene showcase.gltf --budget-ms 100000 --out tuned.gltf --width 160 --height 120 --frames 1 --views orbit:1 --variants standard --resolutions 512 --depth-formats d24 --filters pcf
    test -s tuned.gltf
    echo '{\"plugins\": [{\"library\": \"no_such_plugin\"}]}' > missing.json
    if ENGINE_PLUGIN_PATH=/opt/a:/opt/b engine-render --config missing.json --scene \$data/scenes/showcase.gltf --out y.png; then exit 1; fi
  "
