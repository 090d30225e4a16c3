#!/usr/bin/env bash
# tools/gpu-check.sh on this machine. Where EGL lists only Mesa's software device (CI), the
# check refuses to run, naming it; on the software device chosen by ENGINE_EGL_DEVICE it
# makes the whole table (4 scenes x 8 rows, tiny frames) and each scene's errors against
# truth, and writes the report.
# Usage: gpu_check.sh SOURCE_DIR BUILD_DIR
set -euo pipefail
source_dir=$1 build=$2
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
check=("$source_dir/tools/gpu-check.sh" --table-only --build "$build")
fail() {
  echo "FAIL: $*" >&2
  # What the engine-render runs of the table printed on stderr, where a row says "failed".
  if [ -s "$out/report/table-errors.txt" ]; then echo "their errors:" >&2; tail -n 40 "$out/report/table-errors.txt" >&2; fi
  exit 1
}
# A command that stops the script under set -e says which, instead of exiting silently.
trap 'echo "FAIL: line $LINENO: \"$BASH_COMMAND\" exited with status $?" >&2' ERR

listing=$(ENGINE_EGL_DEVICE=list "$build/bin/engine-render" --config "$source_dir/content/engine.json" \
            --scene "$source_dir/content/scenes/showcase.gltf" --out "$out/list.png" --width 8 --height 8 2>&1 >/dev/null) ||
  fail "engine-render with ENGINE_EGL_DEVICE=list: $listing"
if ! echo "$listing" | grep '^EGL device' | grep -vq '\[software\]'; then
  if (unset ENGINE_EGL_DEVICE; "${check[@]}" "$out/refused") 2> "$out/refused.err"; then
    fail "gpu-check ran with only a software device"
  fi
  grep -q "^gpu-check: no GPU: .* renders on llvmpipe" "$out/refused.err" ||
    fail "the refusal does not say why: $(cat "$out/refused.err")"
fi

device=$(echo "$listing" | sed -n 's/^EGL device \([0-9]*\): .*\[software\].*/\1/p' | head -1)
[ -n "$device" ] || { echo "no software EGL device listed: the table part needs one"; exit 0; }
ENGINE_EGL_DEVICE=$device "${check[@]}" --frames 2 --size 48x32 "$out/report" > "$out/log" 2>&1 ||
  fail "gpu-check on device $device: $(cat "$out/log")"
report=$out/report/report.md
[ -f "$report" ] || fail "no report.md"
grep -q '^- renderer: llvmpipe' "$report" || fail "the report names no renderer"
engine_glb=/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb
scenes=3
[ -f "$engine_glb" ] && scenes=4
# Per scene: still and camera with three configs each (unshadowed, on, off), light with two.
rows=$(grep -c '^| [A-Za-z0-9]* | \(still\|light\|camera\) | \(unshadowed\|on\|off\) | [0-9.]* | [0-9.]* | [0-9.]* |$' "$report" || true)
[ "$rows" -eq $((scenes * 8)) ] || fail "expected $((scenes * 8)) table rows with three times each, got $rows: $(cat "$report")"
# Against truth: every scene's lights, each with its error figures and the texel's size on
# screen (mean/p95, or - where no pixel has one).
for light in spot_light lamp_0 sun; do
  grep -Eq "^  $light +standard .* [0-9]+\.[0-9]{3} +[0-9]+\.[0-9]{3} +([0-9]+\.[0-9]+/[0-9]+\.[0-9]+|-)$" "$report" ||
    fail "no truth row for $light"
done
echo "ok: refused without a GPU; on device $device: $rows table rows, truth for every scene"
