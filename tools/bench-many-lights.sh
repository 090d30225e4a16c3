#!/usr/bin/env bash
# Many shadowed lights: a street at night of N lamps (tools/scripts/make_street.py), each a
# narrow ranged spot with its own 1024 standard map (pcf), walked down by its "walker"
# camera at 1280x720. Per lamp count, three cases, alternating run by run over two rounds so
# load on the machine falls on all of them:
#   still        every lamp still: each map drawn once and then served from the cache
#                (drawn again only when the walk brings a lamp into view or needs a caster
#                the map left out);
#   swinging     the same street with 4 lamps swinging on their hangers: their maps are
#                redrawn every frame;
#   unshadowed   the same street with every lamp's shadow {"variant": "none"} (in the scene:
#                the lamps' own extras win over any plugin-wide default).
# Per run: the median, p99 and max frame time, the ratio to the unshadowed run of the same
# round, the maps drawn per timed frame (the lights' frames_rendered; the plugin's
# cache_misses, which also count the warm-up frames, beside it), the lights with a shadow in
# the last frame, and the shadow atlas's occupancy where the plugin reports an "atlas".
# Then the error of the still street against ray-traced truth at 640x360, off truth's shadow
# edges (percent of the lamp's evaluated pixels): still frames of the walk, each 8 to 13 m
# before the lamps it scores (every lamp; every 4th beyond 64 lamps, both sides), each lamp
# scored in the frame that sees most of its pool; the mean and max over the lamps and the
# worst lamp.
# Usage: tools/bench-many-lights.sh [FRAMES] [LAMP COUNTS...]   (defaults 60; 64 128 256)
# (build first: tools/build.sh). CONFIG=ENGINE.json runs every render with that engine config
# (e.g. one with "renderer": {"clustered_lights": true} to time the clustered pass below 33 lamps).
set -euo pipefail
config=${CONFIG:+$(realpath "$CONFIG")}  # before the cd: a path relative to where it was typed
cd "$(dirname "$0")/.."
frames=${1:-60}
shift || true
counts=("$@")
[ ${#counts[@]} -gt 0 ] || counts=(64 128 256)
render=build/bin/engine-render
swinging=4
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
[ -x "$render" ] || { echo "bench-many-lights: $render not found (build first: tools/build.sh)" >&2; exit 1; }

# engine-render with its report kept in $out/last.log and its warnings gathered in
# $out/warnings (printed once per lamp count: with many lights each run repeats them); on
# failure the report is shown and the bench stops.
render() {
  if ! "$render" ${config:+--config "$config"} "$@" > "$out/last.log" 2> "$out/last.err"; then
    cat "$out/last.log" "$out/last.err" >&2
    echo "bench-many-lights: engine-render $* failed" >&2
    exit 1
  fi
  cat "$out/last.err" >> "$out/warnings"
}

# One run's figures from its --stats: frame median/p99/max, the maps drawn per timed frame,
# the plugin's cache misses per timed frame, the lights with a shadow (a map drawn or
# cached) in the last frame, and the atlas's occupancy ("-" where the plugin has no atlas).
figures() {  # STATS.json
  python3 -c 'import json, sys
s = json.load(open(sys.argv[1]))
frames = s["frames"]
plugin = s.get("plugins", {}).get("shadowmap_plugin", {})
drawn = sum(m.get("frames_rendered", 0) for m in s["shadow_maps"])
shadowed = sum(1 for m in s["shadow_maps"] if m["map_ms"] is not None or m["map_cached"])
atlas = plugin.get("atlas")
occupancy = atlas.get("occupancy") if isinstance(atlas, dict) else None
misses = plugin.get("cache_misses")
print("%.1f %.1f %.1f %.2f %s %d %s" % (s["frame_ms_median"], s["frame_ms_p99"], s["frame_ms_max"],
      drawn / frames, "%.2f" % (misses / frames) if misses is not None else "-", shadowed,
      "%.3g" % occupancy if isinstance(occupancy, (int, float)) else "-"))' "$1"
}

# The still frames for the error: per scored lamp (every STRIDE-th along the street), a time
# at which the walker stands 8 to 13 m before it, and the lamp's name: "TIME NAME" lines. Read
# from the scene: the walk's keys (in the .bin) and the lamps' positions.
truth_times() {  # SCENE.gltf STRIDE
  python3 -c 'import json, os, struct, sys
path, stride = sys.argv[1], int(sys.argv[2])
doc = json.load(open(path))
binary = open(os.path.join(os.path.dirname(path), doc["buffers"][0]["uri"]), "rb").read()
def floats(accessor):
    a = doc["accessors"][accessor]
    view = doc["bufferViews"][a["bufferView"]]
    width = {"SCALAR": 1, "VEC3": 3, "VEC4": 4}[a["type"]]
    start = view.get("byteOffset", 0) + a.get("byteOffset", 0)
    flat = struct.unpack_from("<%df" % (a["count"] * width), binary, start)
    return [flat[i:i + width] for i in range(0, len(flat), width)]
nodes = doc["nodes"]
parent = {c: i for i, n in enumerate(nodes) for c in n.get("children", [])}
def world_z(i):  # the street has no rotated parents above its lamps
    z = 0.0
    while i is not None:
        z += nodes[i].get("translation", [0, 0, 0])[2]
        i = parent.get(i)
    return z
walker = next(i for i, n in enumerate(nodes) if n.get("name") == "walker")
walk = next(a for a in doc["animations"] if a["name"] == "walk")
channel = next(c for c in walk["channels"] if c["target"] == {"node": walker, "path": "translation"})
sampler = walk["samplers"][channel["sampler"]]
keys = list(zip([t[0] for t in floats(sampler["input"])], [p[2] for p in floats(sampler["output"])]))
def time_at(z):  # the walk is linear between keys and goes toward -z
    if z >= keys[0][1]: return keys[0][0]
    for (t0, z0), (t1, z1) in zip(keys, keys[1:]):
        if z1 <= z <= z0: return t0 + (t1 - t0) * (z0 - z) / (z0 - z1)
    return keys[-1][0]
lamps = sorted((i for i, n in enumerate(nodes) if "KHR_lights_punctual" in n.get("extensions", {})),
               key=lambda i: -world_z(i))
# Every STRIDE-th lamp, shifted by one every other time: both sides of the street (lamps
# alternate sides) are scored whatever the stride.
scored = [lamps[min(i + (i // stride) % 2 * (stride > 1), len(lamps) - 1)] for i in range(0, len(lamps), stride)]
camera_z = None
for lamp in scored:
    # A lamp 8 to 13 m ahead fills a good part of the view: one frame serves the lamps in that band.
    if camera_z is None or camera_z - world_z(lamp) > 13.0:
        camera_z = world_z(lamp) + 8.0
    print("%.4f %s" % (time_at(camera_z), nodes[lamp]["name"]))' "$1" "$2"
}

# Per scored lamp (NAMES: one a line), the frame that evaluated most of its pixels; the mean
# and max error off edges over them, the worst lamp, and how many lamps no frame saw.
errors() {  # NAMES STATS.json...
  python3 -c 'import json, sys
names = open(sys.argv[1]).read().split()
best = {}
for path in sys.argv[2:]:
    for light in json.load(open(path)).get("lights", []):
        if light["light"] in names and light["evaluated_pixels"] > best.get(light["light"], {}).get("evaluated_pixels", 0):
            best[light["light"]] = light
scored = list(best.values())
unseen = len(names) - len(scored)
if not scored:
    print("no scored lamp was seen in any still frame"); sys.exit(0)
worst = max(scored, key=lambda l: l["error_noedge"])
print("%d lamps scored (%d to %d px each%s): off edges mean %.3f %%, max %.3f %% (%s, %d px); "
      "with edges mean %.3f %%" % (len(scored), min(l["evaluated_pixels"] for l in scored),
      max(l["evaluated_pixels"] for l in scored), ", %d not seen" % unseen if unseen else "",
      sum(l["error_noedge"] for l in scored) / len(scored), worst["error_noedge"], worst["light"],
      worst["evaluated_pixels"], sum(l["error"] for l in scored) / len(scored)))' "$@"
}

echo "street of N lamps walked, $frames frames at 1280x720 (--animate all, 30 fps); $swinging lamps swinging;" \
  "error at 640x360; $(nproc) cores"
for lamps in "${counts[@]}"; do
  : > "$out/warnings"
  still=$(python3 tools/scripts/make_street.py "$out" --lamps "$lamps")
  swing=$(python3 tools/scripts/make_street.py "$out" --lamps "$lamps" --swinging "$swinging")
  none=$(python3 tools/scripts/make_street.py "$out" --lamps "$lamps" --no-shadows)
  declare -A scene=([still]=$still [swinging]=$swing [unshadowed]=$none)
  for round in 1 2; do
    for case in still swinging unshadowed; do
      render --scene "${scene[$case]}" --out "$out/frame.png" --width 1280 --height 720 --frames "$frames" \
        --animate all --stats "$out/$lamps-$case-$round.json"
    done
  done
  device=$(sed -n 's/.* ms, max [0-9.]* ms (\(.*\))$/\1/p' "$out/last.log")
  echo
  echo "$lamps lamps ($device)"
  printf "  %-11s %4s %9s %9s %9s %8s %11s %11s %9s %7s\n" case run median-ms p99-ms max-ms /unshad \
    maps/frame misses/frame shadowed atlas
  for case in still swinging unshadowed; do
    for round in 1 2; do
      row=$(figures "$out/$lamps-$case-$round.json")
      read -r median p99 max drawn misses shadowed atlas <<< "$row"
      base=$(python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["frame_ms_median"])' \
        "$out/$lamps-unshadowed-$round.json")
      printf "  %-11s %4s %9s %9s %9s %8s %11s %11s %9s %7s\n" "$case" "run$round" "$median" "$p99" "$max" \
        "$(awk -v a="$median" -v b="$base" 'BEGIN { printf "%.2f", a / b }')" "$drawn" "$misses" \
        "$shadowed/$lamps" "$atlas"
    done
  done

  stride=1
  [ "$lamps" -le 64 ] || stride=4
  truth_times "$still" "$stride" > "$out/scored"
  cut -d' ' -f2 "$out/scored" > "$out/names"
  mapfile -t times < <(cut -d' ' -f1 "$out/scored" | sort -u -n)
  truth=()
  for time in "${times[@]}"; do
    truth+=("$out/$lamps-truth-${#truth[@]}.json")
    render --scene "$still" --out "$out/still.png" --width 640 --height 360 --time "$time" --frames 1 \
      --warmup 0 --truth --stats "${truth[-1]}"
  done
  echo "  error at 640x360, ${#truth[@]} still frames: $(errors "$out/names" "${truth[@]}")"
  # Warnings every run gave (e.g. lights beyond what the lit pass renders), once.
  sort -u "$out/warnings" | sed 's/^/  /'
  rm -f "$out"/*.json
done
