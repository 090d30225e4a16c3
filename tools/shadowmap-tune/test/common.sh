# Shared by shadowmap-tune's script tests: the scenes (make_tune_scenes.py) in a scratch
# folder removed on exit, and `tune` with the small, fast sizes every test uses: 160x120,
# one timed frame, resolutions 512 and 1024 (the scenes are small; errors still differ).
# Usage: source common.sh TUNE_BINARY CONTENT_DIR
set -euo pipefail
tune_binary=$1 content=$2
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
python3 "$here/make_tune_scenes.py" "$work"

tune() {
  "$tune_binary" --config "$content/engine.json" --width 160 --height 120 --frames 1 --resolutions 512,1024 "$@"
}

# json FILE PYTHON-EXPRESSION: the expression's value, with the report loaded as r.
json() {
  python3 -c "import json, sys; r = json.load(open(sys.argv[1])); print($2)" "$1"
}

fail() { echo "FAIL: $*"; exit 1; }
