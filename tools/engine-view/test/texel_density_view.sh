#!/usr/bin/env bash
# The texel-density view (key M): on the showcase's sun it differs from the shaded view, every
# pixel is the no-value grey or a colour of the documented scale, with grey (the sky) and
# green (about a texel per pixel) both there (engine-view-check-texel-density), and it is
# engine-render --texel-density's heat map of the same camera, size and light; M again goes
# back to the view it left. Everything is rendered in this run.
source "$(dirname "$0")/common.sh"
check_density=$6

cat > density.txt <<'SCRIPT'
overlay off
select sun
view shaded
screenshot shaded.png
key M
screenshot density.png
key M
screenshot back.png
quit
SCRIPT
run_view density.txt > out.txt 2> err.txt || { echo "FAIL: the density script failed: $(cat err.txt)" >&2; exit 1; }
"$render" --config "$config" --scene showcase.gltf --width 160 --height 120 --out render.png \
  --texel-density sun=density_ref.png > /dev/null

if "$compare" shaded.png density.png "$TOLERANCE" "$FRACTION" > /dev/null; then
  echo "FAIL: the texel-density view of the sun is the shaded picture" >&2
  exit 1
fi
if ! "$check_density" density.png > check.txt; then
  echo "FAIL: the texel-density view is not the documented scale: $(cat check.txt)" >&2
  exit 1
fi
same density.png density_ref.png
same back.png shaded.png
echo "ok: M shows the sun's texel density ($(cat check.txt)), engine-render's heat map, and M goes back"
