# Sourced by engine-view's CLI tests. Arguments: VIEW RENDER COMPARE CONTENT_DIR CHECK_PENUMBRA
# CHECK_TEXEL_DENSITY.
#
# Tolerance for "the viewer's screenshot equals engine-render's image": every pixel within
# 1/255 per channel (TOLERANCE, FRACTION below). Both images come from the same Mesa llvmpipe
# rasterizer with the same draw calls (the viewer uses engine-render's Renderer, only the
# context differs: GLX window vs EGL surfaceless), and the viewer presents the renderer's
# bytes 1:1 (a blit without scaling, filtering or sRGB conversion) and reads the window
# back: measured difference 0/255 on 100% of the pixels (shaded, comparison and shadow-term
# views, 160x120, showcase). One step is left for a rounding in a driver's pixel transfer,
# far below what a real difference makes: one dimming step (0.05) of one light moves
# pixels by up to 13/255 (settings_round_trip.sh checks that this control does differ).
set -euo pipefail
view=$1 render=$2 compare=$3 content=$4 check_penumbra=${5:-}
TOLERANCE=1
FRACTION=1.0

if ! command -v xvfb-run > /dev/null || ! command -v Xvfb > /dev/null; then
  echo "FAIL: xvfb-run/Xvfb not found: engine-view's tests need a virtual X server" \
       "(Debian packages xvfb and xauth; tools/install-deps.sh installs them)" >&2
  exit 1
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# The scene refers to showcase.bin: a copy next to it lets the viewer save beside it.
cp "$content/scenes/showcase.gltf" "$content/scenes/showcase.bin" "$work/"
config=$content/engine.json
cd "$work"

# xvfb COMMAND...: under a fresh Xvfb. -noreset: by default Xvfb resets when its last client
# disconnects and signals xvfb-run (SIGUSR1) again, which can interrupt xvfb-run's own
# clean-up (exit 5, "problem while cleaning up temporary directory", ~1 run in 10 measured).
xvfb() {
  xvfb-run -a -s "-screen 0 640x480x24 -noreset" "$@"
}

# run_view SCRIPT [extra options]: the viewer at 160x120 under a fresh Xvfb.
run_view() {
  local script=$1
  shift
  xvfb "$view" --config "$config" --scene showcase.gltf --width 160 --height 120 --script "$script" "$@"
}

# same A B: A and B within the tolerance (diff image kept in the log on failure).
same() {
  if ! "$compare" "$1" "$2" "$TOLERANCE" "$FRACTION" "diff_$(basename "$1")"; then
    echo "FAIL: $1 and $2 differ beyond $TOLERANCE/255" >&2
    exit 1
  fi
}
