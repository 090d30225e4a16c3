#!/usr/bin/env bash
# The tuner measures at the size the user will look at: by default engine-render's default
# image size (a setting's error depends on the size it is seen at), else the size given; the
# report and the tuned file record it, and engine-render notes a picture far from it.
#   display_size.sh TUNE_BINARY CONTENT_DIR ENGINE_RENDER_BINARY
source "$(dirname "$0")/common.sh" "$@"
engine_render=$3

# engine-render's default size, read from the image it writes without --width/--height.
"$engine_render" --config "$content/engine.json" --scene "$work/closed.gltf" --out "$work/default.png" > /dev/null
read -r render_width render_height < <(python3 -c "
import struct, sys
data = open(sys.argv[1], 'rb').read(24)
print(*struct.unpack('>II', data[16:24]))" "$work/default.png")

# One woo setting (no offsets to fit) and one view keep the default size's renders few.
one_setting=(--variants woo --resolutions 512 --depth-formats d24 --filters pcf --views orbit:1 --frames 1)
"$tune_binary" --config "$content/engine.json" "${one_setting[@]}" --scene "$work/closed.gltf" --budget-ms 100000 \
  --out "$work/default_size.gltf" --report "$work/default_size.json" > "$work/default_size.txt"
[[ $(json "$work/default_size.json" "r['width'], r['height']") == "$render_width $render_height" ]] \
  || fail "measured at $(json "$work/default_size.json" "r['width'], r['height']"), engine-render renders" \
          "${render_width}x${render_height}"
grep -q "at ${render_width}x${render_height} for 1 light" "$work/default_size.txt" \
  || fail "the printed report does not name the size: $(cat "$work/default_size.txt")"
json "$work/default_size.gltf" "r['asset'].get('extras', {}).get('shadowmap_tune') == {'width': $render_width, 'height': $render_height}" \
  | grep -qx True \
  || fail "the tuned file does not record ${render_width}x${render_height}: $(json "$work/default_size.gltf" "r['asset']")"

# A size given is the size measured and recorded; tuning at another size replaces the record.
"$tune_binary" --config "$content/engine.json" "${one_setting[@]}" --width 200 --height 100 \
  --scene "$work/default_size.gltf" --budget-ms 100000 --out "$work/small.gltf" --report "$work/small.json" > /dev/null
[[ $(json "$work/small.json" "r['width'], r['height']") == "200 100" ]] || fail "--width 200 --height 100 not measured"
json "$work/small.gltf" "r['asset']['extras'].get('shadowmap_tune') == {'width': 200, 'height': 100}" | grep -qx True \
  || fail "the record is not replaced: $(json "$work/small.gltf" "r['asset']")"
# engine-render says when it renders a tuned file far from the size it was tuned at.
"$engine_render" --config "$content/engine.json" --scene "$work/small.gltf" --out "$work/large.png" \
  2> "$work/large.log" > /dev/null
grep -q "small.gltf's shadow settings were tuned at 200x100 (asset.extras.shadowmap_tune), this picture is \
${render_width}x${render_height}: shadowmap-tune --width $render_width --height $render_height chooses for it" \
  "$work/large.log" || fail "no note at ${render_width}x${render_height}: $(cat "$work/large.log")"
"$engine_render" --config "$content/engine.json" --scene "$work/small.gltf" --out "$work/small.png" --width 200 \
  --height 100 2> "$work/small.log" > /dev/null
grep -q "tuned at" "$work/small.log" && fail "a note at the tuned size: $(cat "$work/small.log")"
echo "ok: measured and recorded at ${render_width}x${render_height} by default, and at the size given"
