#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""The solver's robustness envelope as a chart: outer iterations and outcome
over Δ*, one panel per bed, one line per Re_p.

    bench/stability_envelope_chart.py DB OUT.svg [STUDY]

DB is the database of a run of studies/stability_envelope.json (STUDY
defaults to "stability_envelope"); its cases are named BED-ReX (e.g.
"uniform0.2-Re10"). Each grid is a marker at (Δ* requested, outer iterations
the job ran): a filled circle when it converged, an open square when it
stalled, a cross when it diverged, a triangle for any other outcome (drawn
at the bottom when the job ran no iteration). Log scales in Δ* (fine to the
right) and in iterations. Reads the view v_stability and results.cpu_s with
the sqlite3 command-line tool; prints nothing.
"""
import math
import subprocess
import sys

COLOURS = {"Re0.1": "#2471a3", "Re1": "#1e8449", "Re10": "#b9770e", "Re100": "#7d3c98", "Re300": "#c0392b"}
PW, PH, ML, MT, GAP = 250, 190, 60, 40, 30  # panel width/height, margins


def query(db, study):
    sql = (
        "SELECT v.case_name, v.delta_star_nominal, v.outcome, COALESCE(v.iterations, 0) "
        "FROM v_stability v WHERE v.study = '%s' ORDER BY v.case_name, v.delta_star_nominal DESC;" % study
    )
    out = subprocess.run(["sqlite3", "-separator", "|", db, sql], check=True, capture_output=True, text=True).stdout
    rows = []
    for line in out.splitlines():
        case, h, outcome, it = line.split("|")
        bed, re = case.rsplit("-", 1)
        rows.append((bed, re, float(h), outcome, int(it)))
    return rows


def main(argv):
    if len(argv) < 3:
        sys.exit("usage: stability_envelope_chart.py DB OUT.svg [STUDY]")
    rows = query(argv[1], argv[3] if len(argv) > 3 else "stability_envelope")
    if not rows:
        sys.exit("no rows in v_stability for the study")
    beds = []
    for r in rows:
        if r[0] not in beds:
            beds.append(r[0])
    beds.sort(key=lambda b: ("uniform" not in b, "bubbling" in b, b))  # uniform beds by ε_s, then dense
    hs = sorted({r[2] for r in rows}, reverse=True)
    hmax, hmin = math.log(max(hs) * 1.15), math.log(min(hs) / 1.15)
    itmax = max(10, max(r[4] for r in rows))
    lmin, lmax = math.log(10), math.log(10 ** math.ceil(math.log10(itmax)))
    cols = min(3, len(beds))
    nrow = (len(beds) + cols - 1) // cols
    W = ML + cols * (PW + GAP) + 120
    H = MT + nrow * (PH + GAP + 30) + 20
    s = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" font-family="sans-serif" font-size="11">',
         f'<rect width="{W}" height="{H}" fill="white"/>',
         f'<text x="{ML}" y="18" font-size="13">Outer iterations and outcome over Δ* (default numerics, stall_window 200)</text>']
    for b, bed in enumerate(beds):
        ox = ML + (b % cols) * (PW + GAP)
        oy = MT + (b // cols) * (PH + GAP + 30)

        def X(h):
            return ox + PW * (hmax - math.log(h)) / (hmax - hmin)

        def Y(it):
            v = math.log(max(it, 10))
            return oy + PH - PH * (v - lmin) / (lmax - lmin)

        s.append(f'<rect x="{ox}" y="{oy}" width="{PW}" height="{PH}" fill="none" stroke="#888"/>')
        s.append(f'<text x="{ox + 4}" y="{oy - 5}" font-weight="bold">{bed}</text>')
        for h in hs:
            s.append(f'<line x1="{X(h):.1f}" y1="{oy + PH}" x2="{X(h):.1f}" y2="{oy + PH + 4}" stroke="#888"/>')
            s.append(f'<text x="{X(h):.1f}" y="{oy + PH + 15}" text-anchor="middle" font-size="9">{h:g}</text>')
        s.append(f'<text x="{ox + PW / 2}" y="{oy + PH + 27}" text-anchor="middle">Δ*</text>')
        e = int(round(lmin / math.log(10)))
        while 10 ** e <= math.exp(lmax) * 1.001:
            y = Y(10 ** e)
            s.append(f'<line x1="{ox}" y1="{y:.1f}" x2="{ox + PW}" y2="{y:.1f}" stroke="#eee"/>')
            if b % cols == 0:
                s.append(f'<text x="{ox - 4}" y="{y + 4:.1f}" text-anchor="end" font-size="9">{10 ** e}</text>')
            e += 1
        if b % cols == 0:
            s.append(f'<text x="{ox - 40}" y="{oy + PH / 2}" transform="rotate(-90 {ox - 40} {oy + PH / 2})" '
                     f'text-anchor="middle">outer iterations</text>')
        for re, colour in COLOURS.items():
            pts = [(r[2], r[3], r[4]) for r in rows if r[0] == bed and r[1] == re]
            if not pts:
                continue
            path = " ".join(f"{X(h):.1f},{Y(it):.1f}" for h, o, it in pts if it > 0)
            s.append(f'<polyline points="{path}" fill="none" stroke="{colour}" stroke-width="1" opacity="0.6"/>')
            for h, o, it in pts:
                x, y = X(h), Y(it)
                title = f"<title>{bed} {re} Δ* {h:g}: {o}, {it} it.</title>"
                if o == "converged":
                    s.append(f'<circle cx="{x:.1f}" cy="{y:.1f}" r="3" fill="{colour}">{title}</circle>')
                elif o == "stalled":
                    s.append(f'<rect x="{x - 4:.1f}" y="{y - 4:.1f}" width="8" height="8" fill="white" '
                             f'stroke="{colour}" stroke-width="1.5">{title}</rect>')
                elif o == "diverged":
                    s.append(f'<path d="M{x - 4:.1f},{y - 4:.1f}L{x + 4:.1f},{y + 4:.1f}M{x - 4:.1f},{y + 4:.1f}'
                             f'L{x + 4:.1f},{y - 4:.1f}" stroke="{colour}" stroke-width="2">{title}</path>')
                else:
                    s.append(f'<path d="M{x:.1f},{y - 5:.1f}L{x + 5:.1f},{y + 4:.1f}L{x - 5:.1f},{y + 4:.1f}Z" '
                             f'fill="white" stroke="{colour}" stroke-width="1.5">{title}</path>')
    lx, ly = ML + cols * (PW + GAP), MT + 10
    for i, (re, colour) in enumerate(COLOURS.items()):
        s.append(f'<line x1="{lx}" y1="{ly + 16 * i}" x2="{lx + 18}" y2="{ly + 16 * i}" stroke="{colour}" stroke-width="2"/>')
        s.append(f'<text x="{lx + 24}" y="{ly + 16 * i + 4}">Re_p {re[2:]}</text>')
    ly += 16 * len(COLOURS) + 10
    s.append(f'<circle cx="{lx + 9}" cy="{ly}" r="3" fill="#444"/><text x="{lx + 24}" y="{ly + 4}">converged</text>')
    s.append(f'<rect x="{lx + 5}" y="{ly + 12}" width="8" height="8" fill="white" stroke="#444" stroke-width="1.5"/>'
             f'<text x="{lx + 24}" y="{ly + 20}">stalled</text>')
    s.append(f'<path d="M{lx + 5},{ly + 28}L{lx + 13},{ly + 36}M{lx + 5},{ly + 36}L{lx + 13},{ly + 28}" stroke="#444" '
             f'stroke-width="2"/><text x="{lx + 24}" y="{ly + 36}">diverged</text>')
    s.append(f'<path d="M{lx + 9},{ly + 43}L{lx + 14},{ly + 52}L{lx + 4},{ly + 52}Z" fill="white" stroke="#444" '
             f'stroke-width="1.5"/><text x="{lx + 24}" y="{ly + 52}">other</text>')
    s.append("</svg>")
    with open(argv[2], "w") as f:
        f.write("\n".join(s) + "\n")


if __name__ == "__main__":
    main(sys.argv)
