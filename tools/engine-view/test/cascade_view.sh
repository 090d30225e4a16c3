#!/usr/bin/env bash
# The cascades view: on the outdoor scene (tools/scripts/make_outdoor.py) the sun's default
# (auto) cascades tint the picture, so it differs from the shaded view; set to one map
# (`set sun cascades 1`, live) the same view is the shaded picture again, and so it is for
# the showcase's sun, which keeps one map by default.
source "$(dirname "$0")/common.sh"
python3 "$content/../tools/scripts/make_outdoor.py" "$work" > /dev/null

cat > cascades.txt <<'SCRIPT'
overlay off
select sun
view shaded
screenshot shaded.png
view cascades
screenshot tinted.png
set sun cascades 1
view shaded
screenshot one_map_shaded.png
view cascades
screenshot one_map.png
quit
SCRIPT
outdoor() {
  xvfb "$view" --config "$config" --scene outdoor.gltf --width 160 --height 90 --script cascades.txt \
    > out.txt 2> err.txt || { echo "FAIL: the cascades script failed: $(cat err.txt)" >&2; exit 1; }
}
outdoor
if "$compare" shaded.png tinted.png "$TOLERANCE" "$FRACTION" diff_tint.png > /dev/null; then
  echo "FAIL: the cascades view of the outdoor sun is the shaded picture: no cascade tinted" >&2
  exit 1
fi
same one_map_shaded.png one_map.png

run_view cascades.txt > out.txt 2> err.txt || { echo "FAIL: on the showcase: $(cat err.txt)" >&2; exit 1; }
same shaded.png tinted.png
echo "ok: the outdoor sun's cascades are tinted; one map (set live, or the showcase's) is not"
