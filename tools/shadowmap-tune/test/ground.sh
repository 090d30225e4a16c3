#!/usr/bin/env bash
# --ground: a model without a floor is measured with the ground engine-render --ground adds
# under it, so the key light's shadow on the ground counts (more evaluated pixels than without)
# and the written file holds the key light but no ground.
source "$(dirname "$0")/common.sh" "$@"

# The boxes without their floor: what a sample model file looks like.
python3 - "$work/dark.gltf" "$work/floating.gltf" <<'PY'
import json, sys
scene = json.load(open(sys.argv[1]))
floor = next(i for i, node in enumerate(scene["nodes"]) if node.get("name") == "floor")
for s in scene["scenes"]:
    s["nodes"] = [n for n in s["nodes"] if n != floor]
json.dump(scene, open(sys.argv[2], "w"))
PY
uri=$(json "$work/floating.gltf" "r['buffers'][0]['uri']")
[[ -f $work/$uri ]] || fail "the scene's buffer $uri is missing"

one_setting=(--variants standard --resolutions 512 --depth-formats d24 --filters pcf --views cameras)
tune "${one_setting[@]}" --scene "$work/floating.gltf" --budget-ms 100000 --key-light directional \
  --out "$work/bare.gltf" --report "$work/bare.json" 2> /dev/null
tune "${one_setting[@]}" --scene "$work/floating.gltf" --budget-ms 100000 --key-light directional --ground \
  --out "$work/grounded.gltf" --report "$work/grounded.json" 2> "$work/grounded.log"
grep -q 'shadowmap-tune: ground: ' "$work/grounded.log" || fail "no ground note: $(cat "$work/grounded.log")"
bare=$(json "$work/bare.json" "r['lights'][0]['before']['evaluated_pixels']")
grounded=$(json "$work/grounded.json" "r['lights'][0]['before']['evaluated_pixels']")
(( grounded > bare )) || fail "the ground added no evaluated pixels ($bare without, $grounded with)"
# The file gains the key light's node only.
[[ $(json "$work/grounded.gltf" "len(r['nodes']) - len(json.load(open('$work/floating.gltf'))['nodes'])") == 1 ]] \
  || fail "the tuned file holds more than the key light's node"
echo "ok: --ground measured $grounded pixels against $bare without, and wrote no ground"
