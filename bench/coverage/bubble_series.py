#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
# The bursting-bubble series of the coverage corpus, computed by this
# repository's worker and read from the database of the runs (full precision,
# not read back from figures):
#
#   gridfree run STUDIES/baseline_fm18_13.json --db bubble.sqlite -j 1   # baseline, fm18, Δ* 3.3 → 0.388
#   gridfree run STUDIES/in_sample.json     --db bubble.sqlite -j 1   # the paper study's 12 series, Δ* 3.3 → 0.556
#   gridfree run studies/bursting_bubble_baseline.json --db bubble.sqlite -j 1   # baseline, default, 18 grids
#   bench/coverage/bubble_series.py GRIDFREE bubble.sqlite held-out     > corpus/bubble_held_out.json
#   bench/coverage/bubble_series.py GRIDFREE bubble.sqlite in-sample    > corpus/bubble_in_sample.json
#
# (STUDIES/ is written by bench/coverage/studies.py REPO_ROOT STUDIES.)
# Measured 2026-12-07 on the 2-core Debian 12 machine, niced, beside other
# builds: 7 min 25 s, 9 min 25 s and 26 min 44 s wall; 159, 338 and 1 070 s
# CPU (docs/EXTRAPOLATION.md "Coverage on other codes' series").
#
# held-out: the baseline (PC1, superbee, FWHM 6 d, BVK) with the default
# transfer and with fm18. The windows use the 13 coarsest grids (Δ* 3.3 →
# 0.388); the reference is f0 of `gridfree extrapolate --method eh14` on the
# five finest (Δ* 0.325 → 0.159), which no window contains. Those five come
# from the database when it holds them, else from docs/REPRODUCTION.md's
# table of the 18-grid runs (2026-11-29 default, 2026-12-02 fm18; printed to
# 0.001; the fm18 five cost 8 278 s CPU, too much to repeat here): each
# series says which.
# in-sample: the paper study's other eleven series on its 11 coarsest grids;
# reference: their f0 on all 18 grids (bench/coverage/in_sample_refs.json,
# docs/REPRODUCTION.md), which includes the 11 grids of the windows.
import json
import os
import sqlite3
import subprocess
import sys

from corpus_file import corpus_text
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
BASELINE = ("PC1", "superbee", 6.0, "bvk")
NWINDOWED = 13
# docs/REPRODUCTION.md "The baseline on the paper's 18 grids": Δ*, default dp*, fm18 dp* of the five finest grids.
QUOTED_FINEST = {
    "diffusion": ([0.325, 0.272, 0.228, 0.191, 0.159], [1016.192, 1016.245, 1016.271, 1016.286, 1016.297]),
    "fm18": ([0.325, 0.272, 0.228, 0.191, 0.159], [1017.608, 1016.481, 1017.521, 1017.141, 1017.326]),
}
QUOTED_SOURCE = ("docs/REPRODUCTION.md, table of 'The baseline on the paper's 18 grids' (the 18-grid runs of "
                 "2026-11-29 (default) and 2026-12-02 (fm18), dp* printed to 0.001)")


def read_series(db):
    rows = sqlite3.connect(db).execute(
        "SELECT DISTINCT case_name, convection, fwhm_dp, drag, deposition, delta_star, dp_star FROM v_results "
        "WHERE result_status = 'converged' ORDER BY delta_star DESC").fetchall()
    series = {}
    for case, conv, fwhm, drag, dep, h, f in rows:
        pts = series.setdefault((case, conv, float(fwhm), drag, dep), {})
        pts[round(h, 9)] = f
    return {k: sorted(v.items(), reverse=True) for k, v in series.items()}  # coarsest first


def extrapolate(gridfree, h, f, method):
    with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as tmp:
        json.dump({"h": h, "f": f}, tmp)
    try:
        out = subprocess.run([gridfree, "extrapolate", tmp.name, "--method", method], capture_output=True,
                             text=True, check=True).stdout
    finally:
        os.unlink(tmp.name)
    return json.loads(out[out.index("{"):])


def held_out(gridfree, series):
    out = []
    for dep, label in (("diffusion", "default transfer"), ("fm18", "fm18")):
        pts = series.get(BASELINE + (dep,), [])
        if len(pts) < NWINDOWED:
            sys.exit("the database holds %d grids of the %s baseline; %d needed" % (len(pts), dep, NWINDOWED))
        windowed, finest = pts[:NWINDOWED], pts[NWINDOWED:]
        if len(finest) >= 5:
            fh, ff, fsource = [p[0] for p in finest], [p[1] for p in finest], "computed (the database)"
        else:
            (fh, ff), fsource = QUOTED_FINEST[dep], QUOTED_SOURCE
        ref = extrapolate(gridfree, fh, ff, "eh14")
        out.append({
            "name": "bubble/PC1 superbee fwhm6 bvk %s, 13 grids" % label, "code": "gridfree-worker",
            "quantity": "DP*", "formal_order": None, "deposition": dep,
            "h": [p[0] for p in windowed], "f": [p[1] for p in windowed],
            "reference": ref["f0"], "reference_halfwidth": ref.get("u0"),
            "reference_source": "held out: f0 of `gridfree extrapolate --method eh14` on the five finest grids "
                                "(reference_grids), which no window contains",
            "reference_grids": {"h": fh, "f": ff, "source": fsource},
        })
    return out


def in_sample(series):
    refs = json.load(open(os.path.join(HERE, "in_sample_refs.json")))
    out = []
    for key, pts in sorted(series.items()):
        case, conv, fwhm, drag, dep = key
        if key[:4] == BASELINE:
            continue  # the baseline is in the held-out file
        name = "/".join([case, conv, str(fwhm), drag, dep])
        if name not in refs:
            sys.exit("no reference for %s in in_sample_refs.json" % name)
        pts = pts[:11]
        out.append({
            "name": "bubble/%s %s fwhm%g %s, 11 grids" % (case, conv, fwhm, drag), "code": "gridfree-worker",
            "quantity": "DP*", "formal_order": None, "deposition": dep,
            "h": [p[0] for p in pts], "f": [p[1] for p in pts], "reference": refs[name], "reference_halfwidth": None,
            "reference_source": "in sample: f0 of the series on all 18 grids (bench/coverage/in_sample_refs.json, "
                                "docs/REPRODUCTION.md), which include the 11 of the windows",
        })
    return out


def main():
    gridfree, db, part = sys.argv[1:4]
    series = read_series(db)
    common = {"h": "h = Δ* (cell size / particle diameter), the grid's own (from its cell counts)",
              "notes": ["No formal order is declared: the worker's limited (TVD) schemes have none on these grids.",
                        "Run 2026-12-07 on the 2-core Debian 12 machine (-j 1, niced, beside two other "
                        "engineers' builds): docs/EXTRAPOLATION.md \"Coverage on other codes' series\"."]}
    if part == "held-out":
        doc = {"source": "bursting-bubble baseline of this repository's worker, default transfer and fm18, "
                         "reference held out (computed here)",
               "command": "bench/coverage/bubble_series.py GRIDFREE bubble.sqlite held-out (runs: the script's header)",
               **common, "series": held_out(gridfree, series)}
    elif part == "in-sample":
        doc = {"source": "bursting-bubble paper study of this repository's worker, eleven more series, "
                         "reference in sample (computed here)",
               "command": "bench/coverage/bubble_series.py GRIDFREE bubble.sqlite in-sample (runs: the script's header)",
               **common, "series": in_sample(series)}
    else:
        sys.exit("part must be held-out or in-sample, not %s" % part)
    sys.stdout.write(corpus_text(doc))


if __name__ == "__main__":
    main()
