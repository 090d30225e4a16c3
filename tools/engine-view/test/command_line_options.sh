#!/usr/bin/env bash
# The options engine-view shares with engine-render: --light-set / --light give the frame
# engine-render gives with the same options (and S saves them, in any folder, as .gltf or
# .glb, rendering the same); --key-light and --ground light a scene that has no light the
# same way (placement printed, same image); a scene without lights is warned about; a
# --save-settings path that cannot be written is one error at start, before any window
# (these runs have no X server at all).
source "$(dirname "$0")/common.sh"

# A bad --save-settings: exit 1, one line naming the path and the reason, no window.
expect_start_error() {  # PATH EXPECTED_PART
  set +e
  env -u DISPLAY "$view" --config "$config" --scene showcase.gltf --save-settings "$1" > out.txt 2> err.txt
  local status=$?
  set -e
  if [[ $status -ne 1 ]] || [[ $(wc -l < err.txt) -ne 1 ]] || ! grep -qF -- "$2" err.txt; then
    echo "FAIL: --save-settings $1 gave exit $status and stderr <<$(cat err.txt)>>, expected exit 1 and" \
         "one line with \"$2\"" >&2
    exit 1
  fi
  echo "ok: $(cat err.txt)"
}
expect_start_error missing/saved.gltf "missing/saved.gltf: its folder $work/missing does not exist"
mkdir -p adir.gltf
expect_start_error adir.gltf "adir.gltf: is a folder, not a file to write"
# Saved elsewhere, showcase.bin goes along; a different file already there is not replaced.
mkdir -p other
echo "not the scene's" > other/showcase.bin
expect_start_error other/saved.gltf \
  "other/showcase.bin: buffers[0] (uri 'showcase.bin'): a different file is already there: not replaced"

# --light-set and --light: the same frame as engine-render's, and saved by S.
cat > save.txt <<'SCRIPT'
overlay off
frames 2
screenshot viewer_set.png
save
quit
SCRIPT
# With --key-light too: the added light is the viewer's and is not saved into the file.
run_view save.txt --light sun=woo --light-set point_light.resolution=512 --save-settings saved.gltf \
  --key-light spot > /dev/null
"$render" --config "$config" --scene showcase.gltf --width 160 --height 120 --light sun=woo \
  --light-set point_light.resolution=512 --key-light spot --out render_set.png > /dev/null
same viewer_set.png render_set.png
run_view save.txt --light sun=woo --light-set point_light.resolution=512 --save-settings saved.gltf > /dev/null
"$render" --config "$config" --scene showcase.gltf --width 160 --height 120 --light sun=woo \
  --light-set point_light.resolution=512 --out render_set.png > /dev/null
same viewer_set.png render_set.png
python3 - saved.gltf <<'PY'
import json, sys
lights = {l["name"]: l["extras"]["shadow"] for l in json.load(open(sys.argv[1]))["extensions"]["KHR_lights_punctual"]["lights"]}
if lights["sun"]["variant"] != "woo" or lights["point_light"]["resolution"] != 512:
    sys.exit(f"FAIL: --light/--light-set not saved: {lights}")
PY
echo "ok: --light and --light-set give engine-render's frame and are saved"

# Saved in another folder, as .gltf (showcase.bin copied beside it) and as .glb (buffers
# embedded): engine-render of each gives the frame of the save beside the scene.
mkdir -p elsewhere
"$render" --config "$config" --scene saved.gltf --width 160 --height 120 --out render_saved.png > /dev/null
for saved in elsewhere/saved.gltf elsewhere/saved.glb; do
  run_view save.txt --light sun=woo --light-set point_light.resolution=512 --save-settings "$saved" > /dev/null
  "$render" --config "$config" --scene "$saved" --width 160 --height 120 --out render_elsewhere.png > /dev/null
  same render_saved.png render_elsewhere.png
done
cmp elsewhere/showcase.bin showcase.bin
echo "ok: saved elsewhere as .gltf and as .glb, both render as the save beside the scene"

# A bad --light-set: the plugin's refusal, naming the option, before the first frame (the
# script's save has its target: a save with none is refused before the window opens too).
set +e
run_view save.txt --light-set sun.resolution=0 --save-settings saved.gltf > out.txt 2> err.txt
status=$?
set -e
if [[ $status -ne 1 ]] || ! grep -qF -- "--light-set sun.resolution=0: " err.txt; then
  echo "FAIL: a bad --light-set gave exit $status and <<$(cat err.txt)>>" >&2
  exit 1
fi
echo "ok: $(tail -1 err.txt)"

# A scene without lights: warned about; --key-light and --ground: engine-render's light and
# ground (the same printed placement, the same frame).
python3 "$(dirname "$0")/../../scripts/remove_lights.py" showcase.gltf dark.gltf
cat > shot.txt <<'SCRIPT'
overlay off
frames 2
screenshot viewer_key.png
quit
SCRIPT
xvfb "$view" --config "$config" --scene dark.gltf --width 160 --height 120 --script shot.txt > out.txt 2> err.txt
grep -qF "dark.gltf: the scene has no lights" err.txt || { echo "FAIL: no warning: <<$(cat err.txt)>>" >&2; exit 1; }
xvfb "$view" --config "$config" --scene dark.gltf --width 160 --height 120 --script shot.txt \
  --key-light point --ground > view_out.txt 2> err.txt
"$render" --config "$config" --scene dark.gltf --width 160 --height 120 --key-light point --ground \
  --out render_key.png > render_out.txt
same viewer_key.png render_key.png
view_line=$(grep -o 'key light: .*' view_out.txt) render_line=$(grep -o 'key light: .*' render_out.txt)
if [[ -z $view_line ]] || [[ $view_line != "$render_line" ]] || grep -qF "no lights" err.txt; then
  echo "FAIL: key light <<$view_line>> vs engine-render's <<$render_line>>, stderr <<$(cat err.txt)>>" >&2
  exit 1
fi
echo "ok: $view_line, the same frame as engine-render's"
