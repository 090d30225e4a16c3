#!/usr/bin/env bash
# engine-view's --light-set NAME.intensity / NAME.color and --exposure: the frame engine-render
# gives with the same options. --exposure auto meters the same first frame in both tools, so
# both print the same EV100 and show the same picture; on lights in physical units (the
# showcase's spot at Blender's 54,351 cd, the others scaled alike) that picture is not white.
source "$(dirname "$0")/common.sh"

cat > shot.txt <<'SCRIPT'
overlay off
frames 2
screenshot viewer.png
quit
SCRIPT

# A light's own intensity and colour: engine-render's frame, and not the file's.
options=(--light-set sun.intensity=0.8 --light-set "spot_light.color=[0.5,1,0.25]")
run_view shot.txt "${options[@]}" > /dev/null
"$render" --config "$config" --scene showcase.gltf --width 160 --height 120 "${options[@]}" --out render.png > /dev/null
same viewer.png render.png
"$render" --config "$config" --scene showcase.gltf --width 160 --height 120 --out file.png > /dev/null
if "$compare" viewer.png file.png 0 1.0 diff_file.png > /dev/null 2>&1; then
  echo "FAIL: --light-set sun.intensity/spot_light.color changed nothing" >&2
  exit 1
fi
echo "ok: --light-set NAME.intensity and NAME.color give engine-render's frame"

# A bad intensity: one line naming the option, the light, the key and the value; no window.
set +e
env -u DISPLAY "$view" --config "$config" --scene showcase.gltf --light-set sun.intensity=-1 > out.txt 2> err.txt
status=$?
set -e
if [[ $status -ne 1 ]] || ! grep -qF -- '--light-set sun.intensity=-1: light "sun".intensity must be a finite number >= 0' err.txt; then
  echo "FAIL: a negative intensity gave exit $status and <<$(cat err.txt)>>" >&2
  exit 1
fi
echo "ok: $(cat err.txt)"

# Physical units, --exposure auto: the same EV100 and frame as engine-render's.
python3 - showcase.gltf physical.gltf <<'PY'
import json, sys
scene = json.load(open(sys.argv[1]))
lights = scene["extensions"]["KHR_lights_punctual"]["lights"]
factor = 54351.0 / next(l["intensity"] for l in lights if l["name"] == "spot_light")
for light in lights:
    light["intensity"] *= factor
json.dump(scene, open(sys.argv[2], "w"))
PY
xvfb "$view" --config "$config" --scene physical.gltf --width 160 --height 120 --script shot.txt \
  --exposure auto > view_out.txt
"$render" --config "$config" --scene physical.gltf --width 160 --height 120 --exposure auto \
  --out render_auto.png > render_out.txt 2>&1
view_ev=$(grep -o 'auto exposure: EV100 [-0-9.]*' view_out.txt || true)
render_ev=$(grep -o 'auto exposure: EV100 [-0-9.]*' render_out.txt || true)
if [[ -z $view_ev ]] || [[ $view_ev != "$render_ev" ]]; then
  echo "FAIL: engine-view said <<$view_ev>>, engine-render <<$render_ev>>" >&2
  exit 1
fi
same viewer.png render_auto.png
if grep -qF "of the image is saturated" render_out.txt; then
  echo "FAIL: auto exposure left the image saturated: <<$(cat render_out.txt)>>" >&2
  exit 1
fi
echo "ok: --exposure auto: $view_ev in both tools, the same frame"

# --exposure EV100 too, as engine-render's.
xvfb "$view" --config "$config" --scene physical.gltf --width 160 --height 120 --script shot.txt \
  --exposure 9 > /dev/null
"$render" --config "$config" --scene physical.gltf --width 160 --height 120 --exposure 9 \
  --out render_ev.png > /dev/null 2>&1
same viewer.png render_ev.png
echo "ok: --exposure 9 gives engine-render's frame"
