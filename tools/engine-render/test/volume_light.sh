#!/usr/bin/env bash
# engine-render with a volume light (stenciled shadow volumes: no map, a visibility per
# camera pixel): its passes' time is reported as a map's, "cached" in the table and
# map_cached in --stats when a still frame kept it, a time when the orbiting camera made it
# again; its error against the truth is that of an exact shadow; --shadow-map says why it
# has no map to write.
# Usage: volume_light.sh ENGINE_RENDER CONTENT_DIR
set -euo pipefail
render=$1 content=$2
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

run() {  # run NAME ARGS...: renders the showcase with the spot light's variant volume
  local name=$1
  shift
  "$render" --config "$content/engine.json" --scene "$content/scenes/showcase.gltf" --out "$out/$name.png" \
    --width 160 --height 90 --frames 3 --light-set 'spot_light.variant="volume"' --truth \
    --stats "$out/$name.json" "$@" > "$out/$name.txt" 2>&1 || { cat "$out/$name.txt"; fail "$name: exit $?"; }
}
# spot_light's entry of --stats' lights (per light, with the truth) and shadow_maps.
entry() { python3 -c "import json, sys; d = json.load(open(sys.argv[1])); \
  print(json.dumps([e for e in d[sys.argv[2]] if e['light'] == 'spot_light'][0], sort_keys=True))" "$out/$1.json" "$2"; }
field() { python3 -c "import json, sys; print(json.dumps(json.loads(sys.argv[1])[sys.argv[2]]))" "$1" "$2"; }

run still
row=$(grep -E '^  spot_light ' "$out/still.txt") || fail "no spot_light row: $(cat "$out/still.txt")"
[[ $(awk '{print $2, $3, $4}' <<< "$row") == "volume volumes cached" ]] || fail "still: $row"
for list in lights shadow_maps; do
  e=$(entry still $list)
  [[ $(field "$e" map_cached) == true && $(field "$e" map_ms) == null ]] || fail "still $list: $e"
done
# Exact: the error (percent) of a hard shadow decided at each pixel centre, off edges none.
python3 -c "import json, sys; e = json.loads(sys.argv[1]); sys.exit(not (e['error'] < 0.1 and e['error_noedge'] == 0))" \
  "$(entry still lights)" || fail "volume error: $(entry still lights)"

run orbit --orbit-camera
row=$(grep -E '^  spot_light ' "$out/orbit.txt")
ms=$(awk '{print $4}' <<< "$row")
[[ $ms =~ ^[0-9]+\.[0-9]+$ ]] || fail "orbiting camera: no time in $row"
for list in lights shadow_maps; do
  e=$(entry orbit $list)
  [[ $(field "$e" map_cached) == false ]] || fail "orbit $list: $e"
  python3 -c "import json, sys; sys.exit(not json.loads(sys.argv[1])['map_ms'] > 0)" "$e" || fail "orbit $list: $e"
done

if "$render" --config "$content/engine.json" --scene "$content/scenes/showcase.gltf" --out "$out/map.png" \
  --width 160 --height 90 --light-set 'spot_light.variant="volume"' --shadow-map "spot_light=$out/map_spot.png" \
  2> "$out/map.log" > /dev/null; then fail "--shadow-map of a volume light accepted"; fi
grep -q 'spot_light: variant volume has no shadow map' "$out/map.log" || fail "--shadow-map: $(cat "$out/map.log")"
echo "ok: volume light $ms ms orbiting, cached when still"
