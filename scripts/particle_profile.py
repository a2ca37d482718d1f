#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Statistics and a picture of particle configurations (CSV x,y,z,d in cm).

    scripts/particle_profile.py --domain LX LY LZ --out FIG.svg A.csv [B.csv ...]

Prints, per file, the particle count and the solids fraction profile
eps_s(y) in bins of one mean diameter (the exact volume of each sphere
between the bin's planes, over the bin's volume), and writes an SVG with
(left) the particles of the first file whose centres lie within one
diameter of the mid-plane z = LZ/2, drawn as their circles of section, and
(right) eps_s(y) of every file. Standard library only.
"""
import argparse
import csv
import math


def read(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return [(float(r["x"]), float(r["y"]), float(r["z"]), float(r["d"])) for r in rows]


def cap(r, t):
    """Volume of a sphere of radius r below the plane at height t from its centre."""
    t = max(-r, min(r, t))
    return math.pi * (r * r * (t + r) - (t ** 3 + r ** 3) / 3.0)


def profile(parts, lx, ly, lz, dy):
    n = int(math.ceil(ly / dy))
    vol = [0.0] * n
    for x, y, z, d in parts:
        r = d / 2
        for b in range(max(0, int((y - r) / dy)), min(n, int((y + r) / dy) + 1)):
            vol[b] += cap(r, (b + 1) * dy - y) - cap(r, b * dy - y)
    return [v / (lx * lz * dy) for v in vol]


def svg(parts, profiles, names, lx, ly, lz, y_top, out):
    scale = 560.0 / y_top  # px per cm, bed region only
    w_left = lx * scale
    x0, y0 = 40, 20
    px = x0 + w_left + 60
    pw = 260
    h = y_top * scale
    s = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{px + pw + 120:.0f}" height="{h + 70:.0f}" '
         'font-family="sans-serif" font-size="12">']
    s.append(f'<rect x="{x0}" y="{y0}" width="{w_left:.1f}" height="{h:.1f}" fill="none" stroke="black"/>')
    zc = lz / 2
    for x, y, z, d in parts:
        if y > y_top or abs(z - zc) > d:
            continue
        r = math.sqrt(max(0.0, (d / 2) ** 2 - (z - zc) ** 2))
        s.append(f'<circle cx="{x0 + x * scale:.1f}" cy="{y0 + h - y * scale:.1f}" r="{r * scale:.2f}" fill="#555"/>')
    s.append(f'<text x="{x0}" y="{y0 + h + 30:.0f}">section z = {zc:.2f} cm (first file), y up to {y_top:.0f} cm</text>')
    s.append(f'<rect x="{px}" y="{y0}" width="{pw}" height="{h:.1f}" fill="none" stroke="black"/>')
    colours = ["#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b"]
    for k, prof in enumerate(profiles):
        dy = y_top / len(prof)
        pts = " ".join(f"{px + min(e, 0.7) / 0.7 * pw:.1f},{y0 + h - (i + 0.5) * dy * scale:.1f}"
                       for i, e in enumerate(prof))
        c = colours[k % len(colours)]
        s.append(f'<polyline points="{pts}" fill="none" stroke="{c}" stroke-width="1.2"/>')
        s.append(f'<text x="{px + pw + 8}" y="{y0 + 14 + 16 * k}" fill="{c}">{names[k]}</text>')
    for e in (0, 0.2, 0.4, 0.6):
        xe = px + e / 0.7 * pw
        s.append(f'<text x="{xe:.1f}" y="{y0 + h + 16:.0f}" text-anchor="middle">{e:.1f}</text>')
    s.append(f'<text x="{px + pw / 2:.0f}" y="{y0 + h + 32:.0f}" text-anchor="middle">solids fraction (1 d bins)</text>')
    s.append("</svg>")
    with open(out, "w") as f:
        f.write("\n".join(s) + "\n")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--domain", nargs=3, type=float, required=True, metavar=("LX", "LY", "LZ"), help="cm")
    ap.add_argument("--top", type=float, default=None, help="highest y (cm) drawn; default: 1.3 x the bed top")
    ap.add_argument("--out", required=True)
    ap.add_argument("files", nargs="+")
    a = ap.parse_args()
    lx, ly, lz = a.domain
    sets = [read(f) for f in a.files]
    d = sum(p[3] for p in sets[0]) / len(sets[0])
    top = a.top or 1.3 * max(max(p[1] for p in s) for s in sets)
    profiles, names = [], []
    for f, parts in zip(a.files, sets):
        prof = profile(parts, lx, ly, lz, d)
        bed = [e for e in prof if e > 0.3]
        height = max(i for i, e in enumerate(prof) if e > 0.05) + 1
        print(f"{f}: {len(parts)} particles, bed top ~{height * d:.2f} cm ({height} d), "
              f"mean solids fraction in bins above 0.3: {sum(bed) / max(1, len(bed)):.3f}, "
              f"min in the bed: {min(prof[1:height - 1]):.3f}")
        profiles.append(prof[: int(top / d)])
        names.append(f.rsplit("/", 1)[-1])
    svg(sets[0], profiles, names, lx, ly, lz, top, a.out)


if __name__ == "__main__":
    main()
