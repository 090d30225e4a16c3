#!/usr/bin/env bash
# --key-light on a scene without lights: the key light engine-render would place is tuned
# and written into the tuned file with its chosen setting (a light, a node placing it, the
# node in the scene's roots, KHR_lights_punctual listed as used). The written light is the
# measured one: tuning the tuned file (no --key-light needed now) measures the first run's
# "after" error exactly (errors are deterministic; another position, cone or setting would
# shade other pixels) and changes no byte.
source "$(dirname "$0")/common.sh" "$@"

tune --scene "$work/dark.gltf" --budget-ms 100000 --key-light spot --out "$work/keyed.gltf" \
  --report "$work/first.json" 2> "$work/stderr"
grep -q 'shadowmap-tune: key light: spot "key_light" at (' "$work/stderr" || fail "no placement printed: $(cat "$work/stderr")"
grep -q 'the key light added with its setting' "$work/stderr" || fail "no addition reported: $(cat "$work/stderr")"
python3 - "$work/dark.gltf" "$work/keyed.gltf" "$work/first.json" <<'PY' || fail "the key light is not in the file as chosen"
import json, sys
dark, keyed, report = (json.load(open(path)) for path in sys.argv[1:])
lights = keyed["extensions"]["KHR_lights_punctual"]["lights"]
assert len(lights) == 1 and lights[0]["name"] == "key_light" and lights[0]["type"] == "spot", lights
chosen = report["lights"][0]["after"]["setting"]
shadow = lights[0]["extras"]["shadow"]
# The saved keys are the chosen ones that differ from the defaults (the config's d24, pcf,
# 2048; the built-in normal offset 0.25, README's table); a chosen key without a default to
# fall back on (a fitted polygon_offset) must be saved.
config_defaults = {"depth_format": "d24", "filter": "pcf", "resolution": 2048, "variant": "standard",
                   "normal_offset": 0.25}
for key, value in chosen.items():
    saved = shadow[key] if key in shadow else config_defaults.get(key)
    assert saved == value, (key, shadow, chosen)
node = len(dark["nodes"])
assert keyed["nodes"][node]["extensions"]["KHR_lights_punctual"]["light"] == 0
assert keyed["scenes"][keyed.get("scene", 0)]["nodes"] == dark["scenes"][dark.get("scene", 0)]["nodes"] + [node]
assert "KHR_lights_punctual" in keyed["extensionsUsed"]
# Everything else as it was, but for the size the choice was measured at (asset.extras).
assert keyed["asset"]["extras"]["shadowmap_tune"] == {"width": report["width"], "height": report["height"]}
del keyed["asset"]["extras"]
for key in dark:
    if key not in ("nodes", "scenes", "extensions", "extensionsUsed"):
        assert keyed[key] == dark[key], key
assert keyed["nodes"][:node] == dark["nodes"]
PY

# Valid glTF by the Khronos validator the repository vendors (0 errors, 0 warnings).
validator=$content/../tools/validate-gltf
node "$validator/validate.mjs" --validator "$validator/vendor/node_modules/gltf-validator" --max-warnings 0 \
  "$work/keyed.gltf" > "$work/validation" 2>&1 || fail "the tuned file is not valid glTF: $(cat "$work/validation")"

tune --scene "$work/keyed.gltf" --budget-ms 100000 --out "$work/again.gltf" --report "$work/second.json"
cmp "$work/keyed.gltf" "$work/again.gltf" || fail "tuning the tuned file changed it: $(diff "$work/keyed.gltf" "$work/again.gltf" | head)"
first=$(json "$work/first.json" "r['lights'][0]['after']['error']")
second=$(json "$work/second.json" "r['lights'][0]['before']['error']")
[[ $first == "$second" ]] || fail "the written light measures $second % where the tuned one measured $first %"

# A scene that has lights keeps them and says the flag did nothing.
tune --scene "$work/closed.gltf" --budget-ms 100000 --key-light spot --out "$work/closed_out.gltf" 2> "$work/stderr"
grep -q 'closed.gltf has lights: --key-light ignored' "$work/stderr" || fail "no note: $(cat "$work/stderr")"
echo "ok: the key light is tuned and written as measured ($first %)"
