#!/usr/bin/env bash
# The penumbra view: on the showcase, its picture is penumbra-coloured exactly where the
# shadow view of the same light and camera, rendered in the same run, is strictly between
# black and white (engine-view-check-penumbra); for the spot light sized and filtered with
# pcss, and for the same light without a size, whose only partly lit pixels are pcf's edge.
# The sized light's penumbra covers more pixels than that edge (the view shows the size).
source "$(dirname "$0")/common.sh"

cat > penumbra.txt <<'SCRIPT'
overlay off
select spot_light
view shadow
screenshot hard_shadow.png
view penumbra
screenshot hard_penumbra.png
set spot_light light_radius 0.15
set spot_light filter pcss
view shadow
screenshot soft_shadow.png
view penumbra
screenshot soft_penumbra.png
quit
SCRIPT
run_view penumbra.txt > out.txt 2> err.txt || { echo "FAIL: the penumbra script failed: $(cat err.txt)" >&2; exit 1; }

# penumbra_pixels NAME: checks NAME_penumbra.png against NAME_shadow.png, prints the count.
penumbra_pixels() {
  if ! "$check_penumbra" "$1_penumbra.png" "$1_shadow.png" 1 > "$1_check.txt"; then
    echo "FAIL: the $1 penumbra view is not coloured where its shadow term is partly lit: $(cat "$1_check.txt")" >&2
    exit 1
  fi
  sed -n 's/^penumbra \([0-9]*\) pixels.*/\1/p' "$1_check.txt"
}
hard=$(penumbra_pixels hard)
soft=$(penumbra_pixels soft)
if (( soft <= hard )); then
  echo "FAIL: the spot light with light_radius 0.15 and pcss has $soft partly lit pixels, no more than" \
       "its pcf edge without a size ($hard)" >&2
  exit 1
fi
echo "ok: the penumbra view colours exactly the partly lit pixels: $hard (pcf edge), $soft (pcss, radius 0.15)"
