#!/usr/bin/env bash
# Runs the examples as a user would: render_one_frame with the shadow plugin and the example
# plugin from one config, then with a setting the example plugin must refuse.
#   test_examples.sh RENDER_ONE_FRAME PLUGIN_DIR SCENE WORK_DIR
set -euo pipefail
program=$1 plugin_dir=$2 scene=$3 work=$4
mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }

cat > "$work/config.json" <<JSON
{"plugin_dirs": ["$plugin_dir"],
 "plugins": [{"library": "shadowmap_plugin"},
             {"library": "pass_counter_plugin", "settings": {"label": "example"}}]}
JSON
rm -f "$work/one_frame.png"
output=$("$program" "$work/config.json" "$scene" "$work/one_frame.png") || fail "render_one_frame exited $?"
echo "$output"
[[ -s $work/one_frame.png ]] || fail "no image written"
for expected in '^count_example +ran$' '^shadow_[0-9]+_spot_light +ran$' '^lit +ran$' \
                '^light spot_light +standard$' '^light sun +standard$' '^light point_light +standard$'; do
  grep -Eq "$expected" <<<"$output" || fail "missing a line matching: $expected"
done

cat > "$work/bad.json" <<JSON
{"plugin_dirs": ["$plugin_dir"], "plugins": [{"library": "pass_counter_plugin", "settings": {"colour": 1}}]}
JSON
if message=$("$program" "$work/bad.json" "$scene" "$work/bad.png" 2>&1); then fail "a bad setting was accepted"; fi
echo "$message"
grep -q 'pass_counter_plugin' <<<"$message" || fail "the error does not name the plugin"
grep -q '"colour"' <<<"$message" || fail "the error does not name the setting"
echo "examples OK"
