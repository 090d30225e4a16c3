#!/usr/bin/env bash
# The light-size keys (- =) through the plugin: each light is sized by its type's setting
# (the sun by angular_diameter, the spot light by light_radius), stepping down to 0 under
# pcss turns the filter to pcf instead of leaving a setting the plugin refuses (the script
# would exit 1 naming the line), and the saved scene renders in engine-render as the viewer
# showed it.
source "$(dirname "$0")/common.sh"

cat > keys.txt <<'SCRIPT'
overlay off
select sun
key =
key =
select spot_light
key =
set spot_light filter pcss
frames 2
key -
frames 2
key =
key =
key =
key -
frames 2
screenshot viewer.png
save
quit
SCRIPT
run_view keys.txt --save-settings saved.gltf > out.txt 2> err.txt ||
  { echo "FAIL: the size keys' script failed: $(cat err.txt)" >&2; exit 1; }
"$render" --config "$config" --scene saved.gltf --width 160 --height 120 --out saved.png > /dev/null
same viewer.png saved.png

# The steps as documented (docs/viewer.md): 0 -> 0.01 world units or 0.002 rad, then x1.5 a
# step, down to 0 again; the saved file holds them with four significant digits.
python3 - saved.gltf <<'PY'
import json, sys
lights = {l["name"]: l["extras"]["shadow"] for l in json.load(open(sys.argv[1]))["extensions"]["KHR_lights_punctual"]["lights"]}
sun, spot = lights["sun"], lights["spot_light"]
checks = [
    ("sun angular_diameter", sun.get("angular_diameter"), 0.003),  # 0 -> 0.002 -> 0.003
    ("sun has no light_radius", "light_radius" in sun, False),
    ("spot_light light_radius", spot.get("light_radius"), 0.015),  # 0 -> 0.01 -> 0 -> .01, .015, .0225 -> .015
    ("spot_light filter", spot.get("filter"), "pcf"),              # pcss left for pcf at size 0
    ("spot_light has no angular_diameter", "angular_diameter" in spot, False),
]
for what, got, expected in checks:
    if got != expected:
        sys.exit(f"FAIL: {what}: {got!r}, expected {expected!r} (saved {lights})")
PY
echo "ok: the size keys step each light by its type's setting, pcss falls back to pcf at 0, saved as shown"
