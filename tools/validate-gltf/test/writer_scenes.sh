#!/usr/bin/env bash
# writer_scenes.sh MAKE_SEEDS SCENES_DIR NODE VALIDATOR_DIR: the scenes the loader tests' glTF
# writer makes (as the fuzzer's seeds) have 0 glTF-Validator errors.
set -euo pipefail
make_seeds=$1 scenes=$2 node=$3 validator=$4
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$make_seeds" "$work" "$scenes"
# The copies of content/scenes need their .bin files beside them, and two seeds an image
# file 'tex.png' (the fuzzer writes one beside every input): here a 2x2 RGB PNG.
cp "$scenes"/*.bin "$work/"
python3 - "$work/tex.png" <<'PNG'
import struct, sys, zlib
def chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
rows = b"".join(b"\0" + bytes(row) for row in ([255, 0, 0, 0, 255, 0], [0, 0, 255, 255, 255, 255]))
png = (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", 2, 2, 8, 2, 0, 0, 0))
       + chunk(b"IDAT", zlib.compress(rows)) + chunk(b"IEND", b""))
open(sys.argv[1], "wb").write(png)
PNG
"$node" "$here/../validate.mjs" --validator "$validator" "$work"
