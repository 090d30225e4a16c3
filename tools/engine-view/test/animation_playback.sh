#!/usr/bin/env bash
# Playback in the viewer, on Debian's simple_skin (a strip bent by a skin animation) with a
# key light and a ground: `time 1.5` shows another picture than `time 0`, and after playing
# for 10 frames and stepping with Right, `time 1.5` shows exactly the picture of 1.5 again
# (the pose is a function of the time alone). An unknown --animate name is refused.
source "$(dirname "$0")/common.sh"
skin=/usr/share/assimp/models/glTF2/simple_skin/simple_skin.gltf

cat > play.txt <<'SCRIPT'
overlay off
time 0
screenshot rest.png
time 1.5
screenshot bent.png
play
frames 10
pause
key Right
time 1.5
screenshot again.png
quit
SCRIPT
if ! xvfb "$view" --config "$config" --scene "$skin" --key-light spot --ground --width 160 --height 120 \
    --script play.txt > out.txt 2> err.txt; then
  echo "FAIL: the playback script failed: $(cat err.txt)" >&2
  exit 1
fi
same bent.png again.png
if "$compare" rest.png bent.png "$TOLERANCE" "$FRACTION" diff_pose.png > /dev/null; then
  echo "FAIL: the picture at 1.5 s is the picture at rest: the pose did not reach the viewer" >&2
  exit 1
fi

set +e
xvfb "$view" --config "$config" --scene "$skin" --animate Walk --script play.txt > out.txt 2> err.txt
status=$?
set -e
if [[ $status -eq 0 ]] || ! grep -qF "has no animation named 'Walk'" err.txt; then
  echo "FAIL: --animate Walk gave exit $status and <<$(cat err.txt)>>" >&2
  exit 1
fi
echo "ok: time 0 and 1.5 differ, 1.5 again after playing is the same picture; unknown --animate refused"
