#!/usr/bin/env bash
# generated_scenes.sh NODE VALIDATOR_DIR: every scene generator of tools/scripts writes into a
# scratch directory, and the glTF-Validator finds 0 errors in what they wrote. (content/ is
# validated as committed by its own test; this one catches a generator change before its
# output is committed.)
set -euo pipefail
node=$1 validator=$2
here=$(cd "$(dirname "$0")" && pwd)
scripts=$here/../../scripts
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for generator in make_showcase.py make_masked_scenes.py make_outdoor.py make_animated_bench.py make_lamps.py \
    make_stacked_occluders.py; do
  python3 "$scripts/$generator" "$work" > /dev/null
done
"$node" "$here/../validate.mjs" --validator "$validator" "$work"
