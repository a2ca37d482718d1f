#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
# Coverage of f1 ± U1 and of f0 ± k|f0 − f1| + σ (k = 1, 1.25, Fs) per
# method and per each window's own verdict, as in docs/EXTRAPOLATION.md
# "Coverage": every run of 4..8 consecutive grids among a series' NCOARSE
# coarsest is extrapolated with `gridfree extrapolate --method M` and
# compared with the series' reference answer (REFS: {"case/convection/
# fwhm/drag/deposition": f0}; for the held-out studies, each series' eh14 f0
# on all its grids: --refs-from eh14 writes them).
#
#   bench/coverage/windows.py GRIDFREE DB REFS.json [NCOARSE]
#   bench/coverage/windows.py GRIDFREE DB --refs-from METHOD > REFS.json
import json
import sqlite3
import statistics
import subprocess
import sys
import tempfile

gridfree, db = sys.argv[1], sys.argv[2]
rows = sqlite3.connect(db).execute(
    "SELECT case_name, convection, fwhm_dp, drag, deposition, delta_star, dp_star FROM v_results "
    "WHERE result_status = 'converged' ORDER BY series_id, delta_star DESC").fetchall()
series = {}
for r in rows:
    series.setdefault("/".join(map(str, r[:5])), []).append((r[5], r[6]))


def extrapolate(points, method):
    with tempfile.NamedTemporaryFile("w", suffix=".json") as f:
        json.dump({"h": [h for h, _ in points], "f": [v for _, v in points]}, f)
        f.flush()
        out = subprocess.run([gridfree, "extrapolate", f.name, "--method", method],
                             capture_output=True, text=True, check=True).stdout
    return json.loads(out)


if sys.argv[3] == "--refs-from":
    json.dump({k: extrapolate(p, sys.argv[4])["f0"] for k, p in series.items()}, sys.stdout, indent=1)
    sys.exit(0)

refs = json.load(open(sys.argv[3]))
ncoarse = int(sys.argv[4]) if len(sys.argv) > 4 else 11
stats = {}
for key, points in series.items():
    if key not in refs:
        print("no reference for", key, file=sys.stderr)
        continue
    ref, points = refs[key], points[:ncoarse]  # coarsest first
    for method in ("capped", "fm", "eh14"):
        for k in range(4, 9):
            for s in range(0, len(points) - k + 1):
                r = extrapolate(points[s:s + k], method)
                if r.get("f0") is None:
                    continue
                g, f0, sigma = r["grids"][0], r["f0"], r["sigma_re"]
                d = abs(f0 - g["f"])
                c = stats.setdefault((method, r["verdict"]["value"]),
                                     {"n": 0, "u1": 0, "k1": 0, "k125": 0, "kfs": 0, "rde": [], "rde0": [], "worst": 0})
                c["n"] += 1
                c["u1"] += abs(ref - g["f"]) <= g["u"]
                c["k1"] += abs(ref - f0) <= d + sigma
                c["k125"] += abs(ref - f0) <= 1.25 * d + sigma
                c["kfs"] += abs(ref - f0) <= r["fs"] * d + sigma
                c["rde"].append(g["u"] / abs(f0))
                c["rde0"].append((d + sigma) / abs(f0))
                c["worst"] = max(c["worst"], abs(ref - g["f"]) / g["u"] if g["u"] else 0)

print("| method | verdict | windows | f₁ ± U₁ covers | f0 ± (d+σ) covers | f0 ± (1.25d+σ) | f0 ± (Fs d+σ) "
      "| median RDE₁ | median (d+σ)/|f0| | worst miss (U₁) |")
print("|---|---|---|---|---|---|---|---|---|---|")
for (method, verdict), c in sorted(stats.items()):
    pct = lambda k: "%d (%.0f %%)" % (k, 100 * k / c["n"])
    print("| %s | %s | %d | %s | %s | %s | %s | %.3f %% | %.3f %% | %.2f |" % (
        method, verdict, c["n"], pct(c["u1"]), pct(c["k1"]), pct(c["k125"]), pct(c["kfs"]),
        100 * statistics.median(c["rde"]), 100 * statistics.median(c["rde0"]), c["worst"]))
