#!/usr/bin/env bash
# The viewer starts (in a window 200x150, resized to 160x120 by the script), renders frames,
# and its screenshots of the shaded, comparison and shadow-term views equal engine-render's
# image, --shadow-compare and --shadow-mask of the same camera, size and settings.
source "$(dirname "$0")/common.sh"

cat > script.txt <<'SCRIPT'
# hide the text, then the window at the size engine-render renders
overlay off
resize 160 120
frames 3
screenshot shaded.png
select sun
view comparison
screenshot comparison.png
view shadow
screenshot shadow.png
# the other views run too (no reference image: they are the viewer's own)
view light
view depth
view projected
view truth
key Tab
view projected
view depth
key D
select spot_light
view projected
view light
frames 2
quit
SCRIPT
xvfb "$view" --config "$config" --scene showcase.gltf \
  --width 200 --height 150 --script script.txt
"$render" --config "$config" --scene showcase.gltf --width 160 --height 120 --out shaded_ref.png \
  --shadow-compare sun=comparison_ref.png --shadow-mask sun=shadow_ref.png > /dev/null
same shaded.png shaded_ref.png
same comparison.png comparison_ref.png
same shadow.png shadow_ref.png
echo "ok: the viewer's shaded, comparison and shadow-term views equal engine-render's"
