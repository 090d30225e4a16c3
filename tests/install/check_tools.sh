#!/usr/bin/env bash
# Installs the build into a staged prefix and runs every installed tool from a folder that is
# neither the source nor the build tree, with ENGINE_PLUGIN_PATH unset: each answers --help,
# and each does one small real run with no --config, so the config, the scenes and the shadow
# plugin can only come from the install.
#   check_tools.sh BUILD_DIR WORK_DIR
set -euo pipefail
build=$1 work=$2
prefix=$work/staged-install
fail() { echo "FAIL: $*"; exit 1; }

rm -rf "$work"
mkdir -p "$work"
cmake --install "$build" --prefix "$prefix" > "$work/install.log" || { cat "$work/install.log"; fail "cmake --install"; }
bin=$prefix/bin data=$prefix/share/shadow-engine
run=$(mktemp -d)
trap 'rm -rf "$run"' EXIT
cd "$run"
unset ENGINE_PLUGIN_PATH LD_LIBRARY_PATH

# Every tool a user is told about (docs/) is installed, and whatever else is in bin/ is a
# program that answers --help too.
for tool in engine-render engine-view shadowmap-bench shadowmap-stress shadowmap-tune soak; do
  [[ -x $bin/$tool ]] || fail "$tool is not installed in $bin"
done
for tool in "$bin"/*; do
  "$tool" --help > help.txt 2>&1 || { cat help.txt; fail "$(basename "$tool") --help exited $?"; }
  grep -q "usage: $(basename "$tool")" help.txt || { cat help.txt; fail "$(basename "$tool") --help printed no usage"; }
done

# A copy of the showcase in this folder: shadowmap-tune writes its result beside the scene.
cp "$data/scenes/showcase.gltf" "$data/scenes/showcase.bin" .
[[ ! -e content ]] || fail "the run folder has a content/ of its own: the default config could come from it"

"$bin/engine-render" --scene showcase.gltf --width 64 --height 48 --out render.png > render.txt 2>&1 \
  || { cat render.txt; fail "engine-render with the installed config exited $?"; }
[[ -s render.png ]] || fail "engine-render wrote no image"

# engine-view needs a window: a virtual X server, as its own tests run it.
command -v xvfb-run > /dev/null || fail "xvfb-run not found (Debian xvfb and xauth; tools/install-deps.sh installs them)"
xvfb-run -a -s "-screen 0 640x480x24 -noreset" "$bin/engine-view" --scene showcase.gltf --width 64 --height 48 \
  --screenshot view.png > view.txt 2>&1 || { cat view.txt; fail "engine-view with the installed config exited $?"; }
[[ -s view.png ]] || fail "engine-view wrote no screenshot"

"$bin/shadowmap-tune" --scene showcase.gltf --budget-ms 100000 --out tuned.gltf --width 32 --height 24 \
  --frames 1 --views orbit:1 --variants standard --resolutions 512 --depth-formats d24 --filters pcf \
  > tune.txt 2>&1 || { cat tune.txt; fail "shadowmap-tune with the installed config exited $?"; }
[[ -s tuned.gltf ]] || fail "shadowmap-tune wrote no tuned scene"

# The bench's default scenes come from the install too: name only one to keep it small.
"$bin/shadowmap-bench" --scene "$data/scenes/showcase.gltf" --variants standard --resolutions 256 \
  --depth-formats d24 --filters pcf --width 32 --height 24 --frames 1 --out bench > bench.txt 2>&1 \
  || { cat bench.txt; fail "shadowmap-bench with the installed config exited $?"; }
[[ $(wc -l < bench/results.csv) -eq 4 ]] || fail "shadowmap-bench wrote no row per light: $(cat bench/results.csv)"

"$bin/shadowmap-stress" --quick --sweep special --variants standard --formats d24 --no-plots --out stress \
  > stress.txt 2>&1 || { cat stress.txt; fail "shadowmap-stress with the installed plugin exited $?"; }
[[ -s stress/stress.csv ]] || fail "shadowmap-stress wrote no stress.csv"

"$bin/soak" --config "$data/engine.json" --scene showcase.gltf --out soak.csv --frames 4 --width 32 --height 24 \
  --change-every 2 --sample-every 1 --warmup 2 > soak.txt 2>&1 || { cat soak.txt; fail "soak exited $?"; }
[[ -s soak.csv ]] || fail "soak wrote no samples"
echo "every installed tool ran from $run"
