#!/usr/bin/env bash
# vsm and evsm in the tuner's search: on closed.gltf's spot (a finite, fitted far plane) they
# are candidates, measured like the other filters; on refusing.gltf, whose spot has an
# infinite far plane and whose sun is warped by lispsm, the plugin refuses them, so the tuner
# never measures them there nor writes them, and the tuned file renders.
source "$(dirname "$0")/common.sh" "$@"
render=$3

fast=(--variants standard --resolutions 512 --depth-formats d24 --filters pcf,vsm,evsm --budget-ms 100000)
tune "${fast[@]}" --scene "$work/closed.gltf" --out "$work/closed_tuned.gltf" --report "$work/closed.json" > /dev/null
python3 - "$work/closed.json" <<'PY' || fail "vsm and evsm were not measured as candidates of closed.gltf's spot"
import json, sys
light = json.load(open(sys.argv[1]))["lights"][0]
filters = {m["setting"].get("filter") for m in light["measured"]}
assert {"vsm", "evsm"} <= filters, filters
print("ok: closed.gltf's spot measured with %s" % ", ".join(sorted(f for f in filters if f)))
PY

tune "${fast[@]}" --scene "$work/refusing.gltf" --out "$work/refusing_tuned.gltf" --report "$work/refusing.json" > /dev/null
python3 - "$work/refusing.json" <<'PY' || fail "a light that refuses vsm and evsm was given them"
import json, sys
lights = json.load(open(sys.argv[1]))["lights"]
assert len(lights) == 2, [l.get("light") for l in lights]
for light in lights:
    filters = {m["setting"].get("filter") for m in light["measured"]}
    assert not {"vsm", "evsm"} & filters, (light.get("light"), filters)
    assert light["after"]["setting"].get("filter") not in ("vsm", "evsm"), light["after"]
print("ok: neither refusing light measured or chose vsm or evsm")
PY
# The tuned file is one the plugin accepts: it renders.
"$render" --config "$content/engine.json" --scene "$work/refusing_tuned.gltf" --width 64 --height 48 \
  --out "$work/refusing.png" > /dev/null || fail "the tuned refusing.gltf does not render"
echo "ok: the tuned file renders"
