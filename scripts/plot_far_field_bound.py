#!/usr/bin/env python3
"""docs/far_field_bound.png: the near-field distance d_far / D the error bound chose per
direction (C across, gamma down) for two emitters, on a log colour scale from 2 D to 60 D (white:
near field at every distance); right: the colour bar, 2 D at the bottom, 60 D at the top.
Data: LUXGRID_FIGURE_DIR=DIR build/tests/nearfield_tests --gtest_filter=FarFieldBound.FigureData.
Needs only Python (the PNG is written by hand; the labels are in docs/nearfield.md's caption).
Usage: scripts/plot_far_field_bound.py DIR docs/far_field_bound.png"""
import math, struct, sys, zlib

LO, HI = 2.0, 60.0  # x D, the colour scale's ends
SCALE = 2           # pixels per data cell (2 deg C x 1 deg gamma)

def colour(v):
    """Viridis-like ramp by its five anchors, log in d_far; beyond HI white."""
    if v > HI: return (255, 255, 255)
    t = (math.log(max(v, LO)) - math.log(LO)) / (math.log(HI) - math.log(LO))
    anchors = [(68, 1, 84), (59, 82, 139), (33, 145, 140), (94, 201, 98), (253, 231, 37)]
    x = t * (len(anchors) - 1); i = min(int(x), len(anchors) - 2); f = x - i
    return tuple(round(a + f * (b - a)) for a, b in zip(anchors[i], anchors[i + 1]))

def read(path):
    rows, title = [], ""
    for line in open(path):
        if line.startswith("#"): title = line[1:].strip(); continue
        rows.append([float(x) for x in line.split(",")])
    return title, rows

def main(folder, out):
    panels = [read(f"{folder}/ledvance_flmax_asym_isym0.csv"), read(f"{folder}/lambertian_square_0.6m.csv")]
    h, w = len(panels[0][1]), len(panels[0][1][0])
    gap, bar = 20, 30
    W = 2 * w * SCALE + 2 * gap + bar
    H = h * SCALE
    pix = [[(255, 255, 255)] * W for _ in range(H)]
    for k, (_, rows) in enumerate(panels):
        x0 = k * (w * SCALE + gap)
        for gi, row in enumerate(rows):
            for ci, v in enumerate(row):
                c = colour(v)
                for dy in range(SCALE):
                    for dx in range(SCALE): pix[gi * SCALE + dy][x0 + ci * SCALE + dx] = c
    xb = 2 * (w * SCALE + gap)
    for y in range(H):
        v = math.exp(math.log(HI) - (math.log(HI) - math.log(LO)) * y / (H - 1))
        for x in range(bar): pix[y][xb + x] = colour(v * 0.999)
    write_png(out, pix)

def write_png(path, pix):
    """RGB, 8 bit, no filter (PNG spec, ISO/IEC 15948 sec. 11)."""
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)
    H, W = len(pix), len(pix[0])
    raw = b"".join(b"\0" + bytes(v for p in row for v in p) for row in pix)
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", W, H, 8, 2, 0, 0, 0)) +
                chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))

if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
