#!/usr/bin/env bash
# egl_device_choice.sh ENGINE_RENDER CONFIG SCENE: ENGINE_EGL_DEVICE (GlContext.h) through a
# tool. `list` names every device and still renders on the default; an index of a listed
# device renders on it; an index past the list, or not a number, is one line naming the
# variable, the value and the devices there are, with exit status 1.
# (On a machine without a GPU driver, Mesa lists only its software device: what CI checks.)
set -euo pipefail
render=$1 config=$2 scene=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
run() {  # run DEVICE: engine-render at 32x24, stderr to $work/err
  ENGINE_EGL_DEVICE=$1 "$render" --config "$config" --scene "$scene" --width 32 --height 24 \
    --out "$work/out.png" > /dev/null 2> "$work/err"
}
fail() { echo "FAIL: $*" >&2; cat "$work/err" >&2; exit 1; }

run list || fail "ENGINE_EGL_DEVICE=list did not render"
grep -Eq '^EGL device 0: .+ \(.*\)$' "$work/err" || fail "list: no line 'EGL device 0: NAME (EXTENSIONS)'"
count=$(grep -c '^EGL device [0-9]*: ' "$work/err")
software=$(grep -m1 '^EGL device [0-9]*: .*\[software\]' "$work/err" | sed -E 's/^EGL device ([0-9]+):.*/\1/') ||
  fail "list: no software device (Mesa's llvmpipe lists one)"
echo "listed $count device(s); software device: $software"

run "$software" || fail "ENGINE_EGL_DEVICE=$software (the software device) did not render"
[ -s "$work/out.png" ] || fail "ENGINE_EGL_DEVICE=$software wrote no image"

for bad in "$count" 99 gpu -1; do
  if run "$bad"; then fail "ENGINE_EGL_DEVICE=$bad rendered instead of failing"; fi
  [ "$(wc -l < "$work/err")" -eq 1 ] || fail "ENGINE_EGL_DEVICE=$bad: not one line"
  grep -Eq "^engine-render: EGL: ENGINE_EGL_DEVICE=$bad: no such device \(the devices: 0 = " "$work/err" ||
    fail "ENGINE_EGL_DEVICE=$bad: the error does not name the variable, the value and the devices"
done
echo "ok: list, the software device, and bad indices each give one clear line"
