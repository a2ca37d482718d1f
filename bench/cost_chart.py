#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""CPU time per cell against cells, one line per benchmark table.

    bench/cost_chart.py OUT.svg "LABEL=FILE.csv" ...

Each FILE.csv has at least the columns case, cells ("NXxNYxNZ") and cpu_s,
as `bench/run.sh --csv` writes them; only the bursting-bubble rows are
drawn (the cost per cell of one case as its grid is refined). Log scale in
cells, linear in µs of CPU per cell.
"""
import csv
import math
import sys

COLOURS = ["#c0392b", "#2471a3", "#1e8449", "#7d3c98", "#b9770e"]
W, H, LEFT, RIGHT, TOP, BOTTOM = 560, 320, 70, 540, 30, 270


def read_points(path):
    points = []
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            if row["case"] != "bubble":
                continue
            n = 1
            for v in row["cells"].split("x"):
                n *= int(v)
            points.append((n, 1e6 * float(row["cpu_s"]) / n))
    return sorted(points)


def main(argv):
    if len(argv) < 3 or any("=" not in a for a in argv[2:]):
        sys.exit("usage: cost_chart.py OUT.svg LABEL=FILE.csv [LABEL=FILE.csv ...]")
    series = []
    for arg in argv[2:]:
        label, path = arg.split("=", 1)
        pts = read_points(path)
        if not pts:
            sys.exit(f"{path}: no bubble rows")
        series.append((label, pts))
    cells = sorted({n for _, pts in series for n, _ in pts})
    ymax = max(us for _, pts in series for _, us in pts)
    step = 10 ** math.floor(math.log10(ymax))
    top = step * math.ceil(1.35 * ymax / step)  # headroom for the legend
    lo, hi = math.log10(cells[0]) - 0.3, math.log10(cells[-1]) + 0.3
    x = lambda n: LEFT + (RIGHT - LEFT) * (math.log10(n) - lo) / (hi - lo)
    y = lambda us: BOTTOM - (BOTTOM - TOP) * us / top
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" font-family="sans-serif" font-size="12">',
           '<rect width="100%" height="100%" fill="white"/>',
           f'<text x="{W / 2}" y="18" text-anchor="middle">CPU time per cell of a whole solve (µs), bursting bubble (BENCHMARKS.md)</text>',
           f'<line x1="{LEFT}" y1="{BOTTOM}" x2="{RIGHT}" y2="{BOTTOM}" stroke="black"/>',
           f'<line x1="{LEFT}" y1="{TOP}" x2="{LEFT}" y2="{BOTTOM}" stroke="black"/>']
    for k in range(int(round(top / step)) + 1):
        v = k * step
        out.append(f'<line x1="{LEFT - 4}" y1="{y(v):.1f}" x2="{LEFT}" y2="{y(v):.1f}" stroke="black"/>'
                   f'<text x="{LEFT - 8}" y="{y(v) + 4:.1f}" text-anchor="end">{v:g}</text>')
    for n in cells:
        label = f"{n / 1e6:.3g} M" if n >= 1e6 else f"{n / 1e3:.3g} k"
        out.append(f'<line x1="{x(n):.1f}" y1="{BOTTOM}" x2="{x(n):.1f}" y2="{BOTTOM + 4}" stroke="black"/>'
                   f'<text x="{x(n):.1f}" y="{BOTTOM + 18}" text-anchor="middle">{label}</text>')
    out.append(f'<text x="{(LEFT + RIGHT) / 2}" y="{H - 6}" text-anchor="middle">cells</text>')
    for i, (label, pts) in enumerate(series):
        c = COLOURS[i % len(COLOURS)]
        poly = " ".join(f"{x(n):.1f},{y(us):.1f}" for n, us in pts)
        out.append(f'<polyline fill="none" stroke="{c}" stroke-width="2" points="{poly}"/>')
        dy = 16 if i == len(series) - 1 and i > 0 else -6  # the last series labelled below its points
        for n, us in pts:
            out.append(f'<circle cx="{x(n):.1f}" cy="{y(us):.1f}" r="4" fill="{c}"/>'
                       f'<text x="{x(n) + 6:.1f}" y="{y(us) + dy:.1f}" fill="{c}">{us:.3g}</text>')
        out.append(f'<text x="{LEFT + 10}" y="{TOP + 14 + 16 * i}" fill="{c}">{label}</text>')
    out.append("</svg>")
    with open(argv[1], "w") as f:
        f.write("\n".join(out) + "\n")


if __name__ == "__main__":
    main(sys.argv)
