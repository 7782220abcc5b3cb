#!/usr/bin/env python3
"""Counts the pixels where two PNGs differ (any of R, G, B by more than a tolerance).

    png_diff.py a.png b.png [--tolerance T] [--rect X0 Y0 X1 Y1]

Prints "<differing pixels> <pixels compared>". --rect limits the count to the pixels with
X0 <= x < X1 and Y0 <= y < Y1 (top row 0). Reads 8-bit RGB and RGBA, non-interlaced: what
Irrlicht's writeImageToFile and stb_image_write produce. Standard library only (no Pillow in
this project's dependencies).
"""
import argparse
import struct
import sys
import zlib


def read_png(path):
    with open(path, "rb") as f:
        data = f.read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        sys.exit(f"png_diff: {path}: not a PNG")
    pos, idat, header = 8, b"", None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    width, height, depth, colour, _, _, interlace = header
    if depth != 8 or colour not in (2, 6) or interlace:
        sys.exit(f"png_diff: {path}: only 8-bit RGB/RGBA, non-interlaced (depth {depth}, colour {colour})")
    bpp = 3 if colour == 2 else 4
    raw, stride = zlib.decompress(idat), width * bpp
    rows, prev = [], bytearray(stride)
    for y in range(height):
        start = y * (stride + 1)
        kind, row = raw[start], bytearray(raw[start + 1:start + 1 + stride])
        for i in range(stride):
            a = row[i - bpp] if i >= bpp else 0
            b = prev[i]
            c = prev[i - bpp] if i >= bpp else 0
            if kind == 1:
                row[i] = (row[i] + a) & 255
            elif kind == 2:
                row[i] = (row[i] + b) & 255
            elif kind == 3:
                row[i] = (row[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                row[i] = (row[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(row)
        prev = row
    return width, height, bpp, rows


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("a")
    parser.add_argument("b")
    parser.add_argument("--tolerance", type=int, default=0)
    parser.add_argument("--rect", type=int, nargs=4)
    args = parser.parse_args()
    wa, ha, bpa, ra = read_png(args.a)
    wb, hb, bpb, rb = read_png(args.b)
    if (wa, ha) != (wb, hb):
        sys.exit(f"png_diff: sizes differ: {wa}x{ha} and {wb}x{hb}")
    x0, y0, x1, y1 = args.rect if args.rect else (0, 0, wa, ha)
    x0, y0, x1, y1 = max(x0, 0), max(y0, 0), min(x1, wa), min(y1, ha)
    differing = 0
    for y in range(y0, y1):
        for x in range(x0, x1):
            pa, pb = ra[y][x * bpa:x * bpa + 3], rb[y][x * bpb:x * bpb + 3]
            if any(abs(pa[c] - pb[c]) > args.tolerance for c in range(3)):
                differing += 1
    print(differing, max(x1 - x0, 0) * max(y1 - y0, 0))


if __name__ == "__main__":
    main()
