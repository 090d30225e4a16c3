#!/usr/bin/env bash
# A volume light (stenciled shadow volumes: no map, exact per pixel), reached by the variant
# key V and set live: the depth view shows the stencil count at each pixel (the render tests
# check the counts against truth), the other views of a light's map (projected, cascades,
# density) the shaded picture (their note says why), the comparison view its shadow term
# (there is no map depth to compare), and none of them fails; its shadow term is the one
# engine-render writes for the same light.
source "$(dirname "$0")/common.sh"

# From standard, V steps through the plugin's variants to volume (woo, backface, none, volume).
cat > volume.txt <<'SCRIPT'
overlay off
select spot_light
key V
key V
key V
key V
view shaded
screenshot shaded.png
view depth
screenshot depth.png
view projected
screenshot projected.png
view cascades
screenshot cascades.png
view density
screenshot density.png
view comparison
screenshot comparison.png
view shadow
screenshot shadow.png
save volume_saved.gltf
quit
SCRIPT
run_view volume.txt > out.txt 2> err.txt || { echo "FAIL: the volume script failed: $(cat err.txt)" >&2; exit 1; }
grep -q '"variant":"volume"' volume_saved.gltf || grep -q '"variant": *"volume"' volume_saved.gltf \
  || { echo "FAIL: four presses of V did not reach volume: $(grep -o '"shadow":{[^}]*}' volume_saved.gltf)" >&2; exit 1; }
for shown in projected cascades density; do same shaded.png "$shown.png"; done
if "$compare" shaded.png depth.png "$TOLERANCE" "$FRACTION" diff_depth.png > /dev/null; then
  echo "FAIL: the depth view of a volume light shows the shaded picture, not its stencil counts" >&2
  exit 1
fi
same shadow.png comparison.png
# The shadow view is the light's shadow term, as engine-render --shadow-mask writes it.
"$render" --config "$config" --scene showcase.gltf --width 160 --height 120 --out render.png \
  --light-set 'spot_light.variant="volume"' --shadow-mask "spot_light=mask.png" > /dev/null
same shadow.png mask.png
echo "ok: V reaches volume; its depth view shows the counts, its other map views the shaded picture, its comparison its shadow term"
