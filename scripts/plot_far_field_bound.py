#!/usr/bin/env python3
"""docs/far_field_bound.png: the near-field distance d_far / D the error bound chose per
direction (C across, gamma down) for two emitters, on a log colour scale from 2 D to 60 D (white:
near field at every distance); right: the colour bar, 2 D at the bottom, 60 D at the top.
Data: LUXGRID_FIGURE_DIR=DIR build/tests/nearfield_tests --gtest_filter=FarFieldBound.FigureData.
Needs only Python: the PNG is written by hand, the axes' labels and ticks with a 5 x 7 pixel
font defined below.
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

# A 5 x 7 pixel font for the axes (one string of 7 rows per glyph, '#' = ink).
FONT = {
    "0": ".###.#...##..###.#.###..##...#.###.", "1": "..#...##....#....#....#....#...###.",
    "2": ".###.#...#....#...#...#...#...#####", "3": "#####...#...#.....#.....##...#.###.",
    "4": "...#...##..#.#.#..#.#####...#....#.", "5": "######....####.....#....##...#.###.",
    "6": "..##..#...#....####.#...##...#.###.", "7": "#####....#...#...#...#....#....#...",
    "8": ".###.#...##...#.###.#...##...#.###.", "9": ".###.#...##...#.####....#...#..##..",
    "C": ".###.#...##....#....#....#...#.###.", "D": "####.#...##...##...##...##...#####.",
    "L": "#....#....#....#....#....#....#####", "a": "...........###.....#.#####...#.####",
    "b": "#....#....#.##.##..##...##...#####.", "d": "....#....#.##.##..###...##...#.####",
    "e": "...........###.#...#######.....###.", "f": "..##..#..#.#...###...#....#....#...",
    "g": "...........#####...#.####....#.###.", "h": "#....#....#.##.##..##...##...##...#",
    "i": "..#........##....#....#....#...###.", "l": ".##....#....#....#....#....#...###.",
    "m": "..........##.#.#.#.##.#.##...##...#", "n": "..........#.##.##..##...##...##...#",
    "o": "...........###.#...##...##...#.###.", "p": "..........####.#...#####.#....#....",
    "q": "...........####...##.####....#....#", "r": "..........#.##.##...#....#....#....",
    "s": "...........#####.....###.....#####.", "t": ".#....#...###..#....#....#..#...##.",
    "u": "..........#...##...##...##..##.##.#", "v": "..........#...##...##...#.#.#...#..",
    "w": "..........#...##...##.#.##.#.#.#.#.", "y": "..........#...##...#.####....#.###.",
    "x": "..........#...#.#.#...#...#.#.#...#", "(": "...#...#...#....#....#.....#.....#.",
    ")": ".#.....#.....#....#....#...#...#...", "/": "....#...#...#...#...#...#....#.....",
    "_": "..............................#####", ".": "..........................##...##..",
    ",": ".....................##...##..#....", ":": "......##...##........##...##.......",
    "c": "...........###.#....#....#...#.###.", "=": "..........#####.....#####..........", " ": "." * 35,
}

def text(pix, x, y, s, ink=(0, 0, 0), scale=2):
    """Draws `s` with its top-left corner at (x, y), 6 x scale pixels per character."""
    for k, ch in enumerate(s):
        rows = FONT[ch].ljust(35, ".")[:35]
        for r in range(7):
            for c in range(5):
                if rows[r * 5 + c] == "#":
                    for dy in range(scale):
                        for dx in range(scale):
                            px, py = x + (6 * k + c) * scale + dx, y + r * scale + dy
                            if 0 <= py < len(pix) and 0 <= px < len(pix[0]): pix[py][px] = ink

def width(s, scale=2): return 6 * len(s) * scale

def read(path):
    rows, title = [], ""
    for line in open(path):
        if line.startswith("#"): title = line[1:].strip(); continue
        rows.append([float(x) for x in line.split(",")])
    return title, rows

def main(folder, out):
    panels = [("Ledvance flood, 8 C planes", read(f"{folder}/ledvance_flmax_asym_isym0.csv")),
              ("Lambertian 0.6 m square", read(f"{folder}/lambertian_square_0.6m.csv"))]
    h, w = len(panels[0][1][1]), len(panels[0][1][1][0])  # gamma 0..180 step 1, C 0..358 step 2
    left, top, bottom, gap, bar, right = 70, 56, 56, 40, 30, 180
    W = left + 2 * w * SCALE + gap + 30 + bar + right
    H = top + h * SCALE + bottom
    pix = [[(255, 255, 255)] * W for _ in range(H)]
    black = (0, 0, 0)
    for k, (title, (_, rows)) in enumerate(panels):
        x0 = left + k * (w * SCALE + gap)
        for gi, row in enumerate(rows):
            for ci, v in enumerate(row):
                c = colour(v)
                for dy in range(SCALE):
                    for dx in range(SCALE): pix[top + gi * SCALE + dy][x0 + ci * SCALE + dx] = c
        # Frame, ticks every 90 degrees of C and 45 of gamma, labels.
        for x in range(x0 - 1, x0 + w * SCALE + 1): pix[top - 1][x] = pix[top + h * SCALE][x] = black
        for y in range(top - 1, top + h * SCALE + 1): pix[y][x0 - 1] = pix[y][x0 + w * SCALE] = black
        for c_deg in range(0, 361, 90):
            x = min(x0 + c_deg * SCALE // 2, x0 + w * SCALE)
            for y in range(top + h * SCALE, top + h * SCALE + 6): pix[y][x] = black
            text(pix, x - width(str(c_deg)) // 2, top + h * SCALE + 9, str(c_deg))
        for g_deg in range(0, 181, 45):
            y = min(top + g_deg * SCALE, top + h * SCALE)
            for x in range(x0 - 7, x0 - 1): pix[y][x] = black
            if k == 0: text(pix, x0 - 10 - width(str(g_deg)), y - 7, str(g_deg))
        text(pix, x0 + (w * SCALE - width("C (deg)")) // 2, top + h * SCALE + 30, "C (deg)")
        text(pix, x0 + (w * SCALE - width(title)) // 2, 8, title)
    text(pix, 4, 30, "gamma (deg)")
    xb = left + 2 * (w * SCALE + gap) - gap + 30
    for y in range(h * SCALE):
        v = math.exp(math.log(HI) - (math.log(HI) - math.log(LO)) * y / (h * SCALE - 1))
        for x in range(bar): pix[top + y][xb + x] = colour(v * 0.999)
    for v in (2, 5, 10, 20, 40, 60):
        y = top + round((math.log(HI) - math.log(v)) / (math.log(HI) - math.log(LO)) * (h * SCALE - 1))
        for x in range(xb + bar, xb + bar + 6): pix[y][x] = black
        text(pix, xb + bar + 9, y - 7, str(v))
    text(pix, xb - 10, 30, "d_far / D")
    text(pix, xb + bar + 50, top + 40, "white:", scale=2)
    text(pix, xb + bar + 50, top + 60, "near", scale=2)
    text(pix, xb + bar + 50, top + 80, "field", scale=2)
    text(pix, xb + bar + 50, top + 100, "at every", scale=2)
    text(pix, xb + bar + 50, top + 120, "distance", scale=2)
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
