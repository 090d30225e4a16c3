#!/usr/bin/env bash
# Load -> change settings (script `set` and key presses) -> save -> engine-render of the
# saved file equals the viewer's frame; the saved file differs from the loaded one only in
# the lights' extras.shadow; and the changed frame does differ from the unchanged scene.
source "$(dirname "$0")/common.sh"

cat > script.txt <<'SCRIPT'
overlay off
set sun variant woo
set spot_light resolution 1024
set spot_light polygon_offset [1.5, 6]
select point_light
# point_light: standard -> woo, 1024 -> 2048, pcf -> vsm (the filter key's next; pcss needs a
# size), offset units +1, dimming +0.05
key V
key R
key P
key ]
key .
frames 2
screenshot viewer.png
save
quit
SCRIPT
run_view script.txt --save-settings saved.gltf
"$render" --config "$config" --scene saved.gltf --width 160 --height 120 --out saved.png > /dev/null
same viewer.png saved.png

# Control: the unchanged scene renders differently (the comparison above can fail).
"$render" --config "$config" --scene showcase.gltf --width 160 --height 120 --out original.png > /dev/null
if "$compare" viewer.png original.png "$TOLERANCE" "$FRACTION"; then
  echo "FAIL: the changed settings made no visible difference: the round trip proves nothing" >&2
  exit 1
fi

# Every byte outside the lights' "shadow" objects is as loaded; the saved settings are the
# ones chosen.
python3 - showcase.gltf saved.gltf <<'PY'
import json, re, sys
original, saved = (open(p, encoding="utf-8").read() for p in sys.argv[1:3])
strip = lambda text: re.sub(r'"shadow":\s*\{[^{}]*\}', '"shadow":{}', text)
if strip(original) != strip(saved):
    sys.exit("FAIL: the saved file differs outside the lights' extras.shadow")
lights = {l["name"]: l["extras"]["shadow"] for l in json.loads(saved)["extensions"]["KHR_lights_punctual"]["lights"]}
# The file's own keys stay; of the rest only what differs from the defaults is written
# (depth_format and an unchanged dimming are left to the config).
expected = {
    "spot_light": {"variant": "standard", "resolution": 1024, "filter": "pcf", "polygon_offset": [1.5, 6]},
    "sun": {"variant": "woo", "resolution": 2048, "filter": "pcf"},
    "point_light": {"variant": "woo", "resolution": 2048, "filter": "vsm", "dimming": 0.45,
                    "polygon_offset": [0.0, 1.0]},
}
if lights != expected:
    sys.exit(f"FAIL: saved settings {lights} != {expected}")
PY
echo "ok: engine-render of the saved scene equals the viewer's frame; only extras.shadow changed"
