#!/usr/bin/env bash
# A bad script fails with exit 1 and one line naming the file and the line: an unknown
# command (found before the window opens), and a light or setting that does not exist
# (found when the command runs).
source "$(dirname "$0")/common.sh"

expect_error() {  # SCRIPT_TEXT EXPECTED_MESSAGE_PART...
  local text=$1
  shift
  printf '%s\n' "$text" > bad.txt
  set +e
  run_view bad.txt > out.txt 2> err.txt
  local status=$?
  set -e
  for part in "$@"; do
    if [[ $status -ne 1 ]] || [[ $(wc -l < err.txt) -ne 1 ]] || ! grep -qF -- "$part" err.txt; then
      echo "FAIL: script <<$text>> gave exit $status and stderr <<$(cat err.txt)>>," \
           "expected exit 1 and one line with \"$part\"" >&2
      exit 1
    fi
  done
  echo "ok: $(cat err.txt)"
}

expect_error $'frames 1\n# a comment\njump 3' 'bad.txt:3: unknown command "jump"'
expect_error $'frames 2 3' 'bad.txt:1: frames: expected 1 argument(s), got 2'
expect_error $'view sideways' 'bad.txt:1: view: unknown view "sideways"'
expect_error $'frames 1\nselect moon' 'bad.txt:2: select: no light "moon" in the scene'
expect_error $'time soon' 'bad.txt:1: time: T must be a number of seconds in [0, 1e6]'
# The plugin refuses these when they are applied (the next frame): still the `set` line.
expect_error $'set sun variant foo\nframes 1' 'engine-view: bad.txt:1: ' 'sun' '"foo"'
expect_error $'set sun colour 3' 'engine-view: bad.txt:1: ' 'sun' 'colour'
# A light is sized by its type's key: the sun by angular_diameter, never light_radius.
expect_error $'set sun light_radius 0.1' 'engine-view: bad.txt:1: ' 'sun' 'angular_diameter'

# Outputs are checked before the window opens: a save into a missing folder (or with
# nowhere to save) fails naming its line, and the screenshot before it is never taken.
expect_error $'screenshot early.png\nframes 1\nsave missing/saved.gltf' 'bad.txt:3: save: ' 'missing/saved.gltf: its folder' 'does not exist'
[[ ! -e early.png ]] || { echo "FAIL: the script ran before its save was found impossible" >&2; exit 1; }
expect_error $'save' 'bad.txt:1: save: nowhere to save'
expect_error $'screenshot missing/shot.png' 'bad.txt:1: screenshot: ' 'missing/shot.png: its folder'

# A script without `quit` ends the viewer once its last command has run (exit 0, its
# screenshot taken): headless under Xvfb nobody could close it. Before, it waited forever:
# the timeout turns a hang into a failure.
printf 'frames 2\nscreenshot last.png\n' > noquit.txt
set +e
timeout 120 xvfb-run -a -s "-screen 0 640x480x24 -noreset" "$view" --config "$config" --scene showcase.gltf \
  --width 160 --height 120 --script noquit.txt > out.txt 2> err.txt
status=$?
set -e
if [[ $status -ne 0 ]] || [[ ! -s last.png ]]; then
  echo "FAIL: a script without quit gave exit $status (124: still running after 120 s), screenshot: $(ls -l last.png 2>&1)" >&2
  exit 1
fi
echo "ok: a script without quit exits 0 after its last command"
