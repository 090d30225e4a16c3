#!/usr/bin/env bash
# Renders one matrix of images, shadow masks, map images and stats with two builds of the engine
# and plugin, and counts the files that differ: the proof that a refactor changed no output.
# Both runs happen on this machine in one call, so llvmpipe's CPU-dependent rounding is the
# same on both sides: any differing byte is a change of output.
#
#   tools/compare-builds.sh BEFORE_BUILD_DIR AFTER_BUILD_DIR [OUT_DIR]
#
# A build dir is what tools/build.sh makes (bin/, lib/, plugins/); copy one aside
# (cp -a build /tmp/before) before changing the code. The matrix: the showcase and the
# masked scenes under every variant, filter, depth format (reversed Z included) and cascade
# setting, each axis swept from the defaults, plus the stress tool's quick set (its CSV,
# with the timing columns dropped).
set -euo pipefail

if [ $# -lt 2 ]; then
    echo "usage: $0 BEFORE_BUILD_DIR AFTER_BUILD_DIR [OUT_DIR]" >&2
    exit 1
fi
before=$(realpath "$1")
after=$(realpath "$2")
out=$(realpath -m "${3:-/tmp/compare-builds}")
repo=$(cd "$(dirname "$0")/.." && pwd)
scenes="$repo/content/scenes"
width=320
height=180

# One render of SCENE with ARGS by BUILD into DIR/NAME*: the image, every light's mask and
# map, and the stats without their timings (what was drawn, culled, cached and reused).
render() {
    local build=$1 dir=$2 name=$3 scene=$4
    shift 4
    local lights=()
    mapfile -t lights < <("$build/bin/engine-render" --scene "$scene" --list |
        awk '/^  lights/{on=1; next} on && NF>=3 {print $2}')
    local outputs=()
    for light in "${lights[@]}"; do
        outputs+=(--shadow-mask "$light=$dir/${name}_mask_$light.png" --shadow-map "$light=$dir/${name}_map_$light.png")
    done
    # The build's own plugin: its plugins/ folder first on the search path.
    ENGINE_PLUGIN_PATH="$build/plugins" LD_LIBRARY_PATH="$build/lib" \
        "$build/bin/engine-render" --config "$repo/content/engine.json" --scene "$scene" \
        --width $width --height $height --out "$dir/$name.png" --stats "$dir/$name.stats" "${outputs[@]}" "$@" \
        >/dev/null 2>&1 || echo "render failed: $name" >"$dir/$name.failed"
    if [ -f "$dir/$name.stats" ]; then
        python3 - "$dir/$name.stats" >"$dir/${name}_stats.json" <<'PY'
import json, sys
def untimed(value):
    if isinstance(value, dict):
        return {k: untimed(v) for k, v in value.items() if "ms" not in k.split("_") and "seconds" not in k}
    if isinstance(value, list):
        return [untimed(v) for v in value]
    return value
print(json.dumps(untimed(json.load(open(sys.argv[1]))), indent=1, sort_keys=True))
PY
        rm "$dir/$name.stats"
    fi
}

matrix() {
    local build=$1 dir=$2
    mkdir -p "$dir"
    for scene in showcase masked_canopy masked_fence; do
        local file="$scenes/$scene.gltf"
        render "$build" "$dir" "${scene}_defaults" "$file"
        for variant in standard woo backface; do
            for filter in nearest pcf; do
                render "$build" "$dir" "${scene}_${variant}_${filter}" "$file" \
                    --set "shadowmap_plugin.variant=\"$variant\"" --set "shadowmap_plugin.filter=\"$filter\""
            done
            for format in d16 d24 d32f; do
                render "$build" "$dir" "${scene}_${variant}_${format}" "$file" \
                    --set "shadowmap_plugin.variant=\"$variant\"" --set "shadowmap_plugin.depth_format=\"$format\""
            done
            render "$build" "$dir" "${scene}_${variant}_d32f_rz" "$file" \
                --set "shadowmap_plugin.variant=\"$variant\"" --set 'shadowmap_plugin.depth_format="d32f"' \
                --set 'shadowmap_plugin.reversed_z=true'
        done
        for cascades in 1 2 4 '"auto"'; do
            render "$build" "$dir" "${scene}_cascades_${cascades//\"/}" "$file" \
                --set "shadowmap_plugin.cascades=$cascades" --frames 2
        done
        render "$build" "$dir" "${scene}_woo_cascades_3" "$file" --set 'shadowmap_plugin.variant="woo"' \
            --set 'shadowmap_plugin.cascades=3'
        render "$build" "$dir" "${scene}_uncached" "$file" --set 'shadowmap_plugin.cache_maps=false' --frames 2
    done
    render "$build" "$dir" "lamps_defaults" "$scenes/lamps.gltf"
    # The stress quick set: every column but the timings.
    ENGINE_PLUGIN_PATH="$build/plugins" LD_LIBRARY_PATH="$build/lib" \
        "$build/bin/shadowmap-stress" --quick --no-plots --out "$dir/stress" >/dev/null 2>&1 || true
    if [ -f "$dir/stress/stress.csv" ]; then
        python3 - "$dir/stress/stress.csv" "$dir/stress_no_time.csv" <<'PY'
import csv, sys
rows = list(csv.reader(open(sys.argv[1])))
keep = [i for i, name in enumerate(rows[0]) if name not in ("seconds",) and "ms" not in name and "time" not in name]
with open(sys.argv[2], "w", newline="") as f:
    csv.writer(f).writerows([[row[i] for i in keep] for row in rows])
PY
    fi
}

rm -rf "$out"
matrix "$before" "$out/before"
matrix "$after" "$out/after"

differ=0 total=0
for file in "$out"/before/*; do
    [ -f "$file" ] || continue
    total=$((total + 1))
    name=$(basename "$file")
    if ! cmp -s "$file" "$out/after/$name"; then
        echo "differs: $name"
        differ=$((differ + 1))
    fi
done
for file in "$out"/after/*; do
    [ -f "$file" ] && [ ! -e "$out/before/$(basename "$file")" ] && { echo "only after: $(basename "$file")"; differ=$((differ + 1)); }
done
failed=$(find "$out" -name '*.failed' | wc -l)
echo "$total files compared, $differ differ, $failed renders failed (outputs in $out)"
[ "$differ" -eq 0 ] && [ "$failed" -eq 0 ]
