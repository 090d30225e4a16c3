#!/usr/bin/env bash
# egl_device_choice.sh ENGINE_RENDER CONFIG SCENE: ENGINE_EGL_DEVICE (GlContext.h) through a
# tool. `list` names every device and still renders on the default; an index of a listed
# device renders on it; an index past the list, or not a number, is one line naming the
# variable, the value and the devices there are, with exit status 1.
# (On a machine without a GPU driver, Mesa lists only its software device: what CI checks.
# A driver that lists none gets its own branch below.)
set -euo pipefail
render=$1 config=$2 scene=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
run() {  # run DEVICE: engine-render at 32x24, stderr to $work/err
  ENGINE_EGL_DEVICE=$1 "$render" --config "$config" --scene "$scene" --width 32 --height 24 \
    --out "$work/out.png" > /dev/null 2> "$work/err"
}
fail() { echo "FAIL: $*" >&2; cat "$work/err" >&2; exit 1; }

refused() {  # refused VALUE PATTERN: the choice fails with one line naming variable and value
  if run "$1"; then fail "ENGINE_EGL_DEVICE=$1 rendered instead of failing"; fi
  [ "$(wc -l < "$work/err")" -eq 1 ] || fail "ENGINE_EGL_DEVICE=$1: not one line"
  grep -Eq "^engine-render: EGL: ENGINE_EGL_DEVICE=$1: $2" "$work/err" ||
    fail "ENGINE_EGL_DEVICE=$1: the error does not name the variable, the value and the reason"
}

run list || fail "ENGINE_EGL_DEVICE=list did not render"
if grep -qx 'EGL devices: none listed' "$work/err"; then
  # A driver that enumerates no device (NVIDIA's in a VM without DRM nodes, seen by
  # tools/gpu-check.sh) renders on the default display, and every index is refused, saying why.
  [ -s "$work/out.png" ] || fail "ENGINE_EGL_DEVICE=list wrote no image"
  for bad in 0 gpu; do refused "$bad" "(EGL lists no device|this EGL cannot enumerate devices)"; done
  echo "ok: no device listed; list renders on the default display and indices give one clear line"
  exit 0
fi
grep -Eq '^EGL device 0: .+ \(.*\)$' "$work/err" || fail "list: no line 'EGL device 0: NAME (EXTENSIONS)'"
count=$(grep -c '^EGL device [0-9]*: ' "$work/err")
# The software device where Mesa lists one, else the first.
chosen=$(grep -m1 '^EGL device [0-9]*: .*\[software\]' "$work/err" | sed -E 's/^EGL device ([0-9]+):.*/\1/' || true)
echo "listed $count device(s); software device: ${chosen:-none}"
chosen=${chosen:-0}

run "$chosen" || fail "ENGINE_EGL_DEVICE=$chosen did not render"
[ -s "$work/out.png" ] || fail "ENGINE_EGL_DEVICE=$chosen wrote no image"

for bad in "$count" 99 gpu -1; do refused "$bad" "no such device \(the devices: 0 = "; done
echo "ok: list, a listed device, and bad indices each give one clear line"
