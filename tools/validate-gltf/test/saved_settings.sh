#!/usr/bin/env bash
# saved_settings.sh VIEW RENDER COMPARE CONTENT NODE VALIDATOR_DIR: engine-view's
# --save-settings output after settings changes on every light has 0 glTF-Validator errors:
# saved as .gltf beside the scene, as .glb in another folder (buffers embedded), and that
# .glb saved again as .gltf (its binary chunk written beside it as a .bin).
here=$(cd "$(dirname "$0")" && pwd)
node=$5 validator=$6
# engine-view's test harness: Xvfb, a scratch copy of the showcase, run_view.
source "$here/../../engine-view/test/common.sh"

cat > script.txt <<'SCRIPT'
overlay off
set sun variant woo
set spot_light resolution 1024
set spot_light polygon_offset [1.5, 6]
set point_light dimming 0.45
save
quit
SCRIPT
run_view script.txt --save-settings saved.gltf > /dev/null
mkdir -p glb back
run_view script.txt --save-settings glb/saved.glb > /dev/null
xvfb "$view" --config "$config" --scene glb/saved.glb --width 160 --height 120 --script script.txt \
  --save-settings back/saved.gltf > /dev/null
"$node" "$here/../validate.mjs" --validator "$validator" saved.gltf glb/saved.glb back/saved.gltf
