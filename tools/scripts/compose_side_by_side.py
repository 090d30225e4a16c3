#!/usr/bin/env python3
"""Composes PNGs of one height side by side, left to right, into one grey PNG, with a
2-pixel white gutter between them (so a dark edge of one image does not run into the next).

Standard library only (zlib + struct), so docs pictures can be remade without installing
anything. Reads 8-bit non-interlaced grey, grey+alpha, RGB or RGBA PNGs (what engine-render
writes); colour is reduced to its first channel, which for engine-render's masks is the grey.
Usage: python3 tools/scripts/compose_side_by_side.py OUT.png IN.png [IN.png]...
"""
import struct
import sys
import zlib

GUTTER = 2
CHANNELS = {0: 1, 2: 3, 4: 2, 6: 4}  # PNG colour type -> samples per pixel


def paeth(a, b, c):
    p = a + b - c
    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
    return a if pa <= pb and pa <= pc else b if pb <= pc else c


def unfilter(raw, width, height, bpp):
    """The scanlines of a PNG's inflated IDAT data, each filter undone (PNG spec 9.2)."""
    stride, rows, previous, at = width * bpp, [], bytearray(width * bpp), 0
    for _ in range(height):
        kind, line = raw[at], bytearray(raw[at + 1:at + 1 + stride])
        at += 1 + stride
        for x in range(stride):
            a = line[x - bpp] if x >= bpp else 0
            b = previous[x]
            c = previous[x - bpp] if x >= bpp else 0
            line[x] = (line[x] + (0, a, b, (a + b) // 2, paeth(a, b, c))[kind]) & 255
        rows.append(line)
        previous = line
    return rows


def read_grey(path):
    """(width, height, rows of grey bytes) of an 8-bit PNG."""
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        sys.exit("%s: not a PNG" % path)
    at, idat = 8, b""
    while at < len(data):
        length, kind = struct.unpack(">I4s", data[at:at + 8])
        body = data[at + 8:at + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
            if depth != 8 or interlace or colour not in CHANNELS:
                sys.exit("%s: only 8-bit, non-interlaced grey or RGB(A) PNGs are read" % path)
        elif kind == b"IDAT":
            idat += body
        at += 12 + length
    bpp = CHANNELS[colour]
    rows = unfilter(zlib.decompress(idat), width, height, bpp)
    return width, height, [bytes(row[::bpp]) for row in rows]


def write_grey(path, width, rows):
    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))
    # Filter 2 (up) on every row: the masks are mostly flat, so it compresses far better than none.
    previous, raw = bytes(width), bytearray()
    for row in rows:
        raw += b"\x02" + bytes((v - p) & 255 for v, p in zip(row, previous))
        previous = row
    header = struct.pack(">IIBBBBB", width, len(rows), 8, 0, 0, 0, 0)
    with open(path, "wb") as out:
        out.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(bytes(raw), 9))
                  + chunk(b"IEND", b""))


def main():
    if len(sys.argv) < 3:
        sys.exit("usage: python3 tools/scripts/compose_side_by_side.py OUT.png IN.png [IN.png]...")
    images = [read_grey(path) for path in sys.argv[2:]]
    height = images[0][1]
    if any(h != height for _, h, _ in images):
        sys.exit("the images differ in height: " + ", ".join("%dx%d" % (w, h) for w, h, _ in images))
    gutter = b"\xff" * GUTTER
    rows = [gutter.join(rows[y] for _, _, rows in images) for y in range(height)]
    write_grey(sys.argv[1], len(rows[0]), rows)


if __name__ == "__main__":
    main()
