#!/usr/bin/env python3
"""Joins PNG pictures of the same height left to right into one RGB PNG, for the docs'
comparisons (tools/beam_frames). Only the standard library: 8-bit RGB or RGBA, not interlaced,
which is what beamzone writes.

    tools/side_by_side.py OUT.png A.png B.png [...] [--half]

--half shrinks every picture to half its size first (2x2 box filter)."""
import os
import struct
import sys
import zlib


def read_png(path):
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        sys.exit(f"{path}: not a PNG")
    pos, idat, header = 8, b"", None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        pos += 12 + length
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
    width, height, depth, colour, _, _, interlace = header
    channels = {2: 3, 6: 4}.get(colour)
    if depth != 8 or channels is None or interlace:
        sys.exit(f"{path}: only 8-bit RGB or RGBA, not interlaced")
    raw = zlib.decompress(idat)
    stride = width * channels
    rows, prev = [], bytearray(stride)
    for y in range(height):
        kind = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b = prev[i]
            c = prev[i - channels] if i >= channels else 0
            if kind == 1:
                line[i] = (line[i] + a) & 255
            elif kind == 2:
                line[i] = (line[i] + b) & 255
            elif kind == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        prev = line
    # Keep RGB only.
    rgb = [bytearray(b for x in range(width) for b in row[x * channels:x * channels + 3]) for row in rows]
    return width, height, rgb


def half(width, height, rows):
    w, h = width // 2, height // 2
    out = []
    for y in range(h):
        r0, r1 = rows[2 * y], rows[2 * y + 1]
        line = bytearray(w * 3)
        for x in range(w):
            for c in range(3):
                i = 6 * x + c
                line[3 * x + c] = (r0[i] + r0[i + 3] + r1[i] + r1[i + 3] + 2) // 4
        out.append(line)
    return w, h, out


def write_png(path, width, height, rows):
    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))
    raw = b"".join(b"\x00" + bytes(r) for r in rows)
    png = (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)) +
           chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))
    tmp = path + ".tmp"
    with open(tmp, "wb") as f:
        f.write(png)
    os.replace(tmp, path)


def main(argv):
    shrink = "--half" in argv
    args = [a for a in argv if a != "--half"]
    if len(args) < 3:
        sys.exit(__doc__)
    out, inputs = args[0], args[1:]
    pictures = [read_png(p) for p in inputs]
    if shrink:
        pictures = [half(*p) for p in pictures]
    height = pictures[0][1]
    if any(p[1] != height for p in pictures):
        sys.exit("the pictures differ in height")
    rows = [bytearray().join(p[2][y] for p in pictures) for y in range(height)]
    write_png(out, sum(p[0] for p in pictures), height, rows)


if __name__ == "__main__":
    main(sys.argv[1:])
