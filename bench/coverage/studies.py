#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
# The studies behind docs/EXTRAPOLATION.md "Coverage", written from the
# shipped bursting-bubble paper study into OUT_DIR:
#   in_sample.json       its 12 series on the 11 coarsest grids (Δ* 3.3 → 0.556)
#   in_sample_fm18.json  the baseline with the paper's transfer, same grids
#   held_out.json        bubble seeds 4, 5 (20 cm/s) and 6 (30 cm/s), BVK and
#                        Gidaspow blend, 14 grids (Δ* 3.3 → 0.39)
#   held_out_fm18.json   seed 4, BVK, fm18, 12 grids
#   baseline_fm18_13.json  the baseline with fm18 on its 13 coarsest grids
#                        (Δ* 3.3 → 0.388), for bubble_series.py
# Run them into one database each (gridfree run F --db D -j 2), then
# windows.py on the database.
#
#   bench/coverage/studies.py REPO_ROOT OUT_DIR
import copy
import os
import json
import sys

root, out = sys.argv[1], sys.argv[2]
os.makedirs(out, exist_ok=True)
paper = json.load(open(f"{root}/studies/bursting_bubble_paper.json"))
grids = paper["grids"]["delta_star"]


def write(name, study):
    json.dump(study, open(f"{out}/{name}.json", "w"), indent=1)


s = copy.deepcopy(paper)
s["name"], s["grids"] = "coverage-in-sample", {"delta_star": grids[:11]}
write("in_sample", s)
f = json.load(open(f"{root}/studies/bursting_bubble_baseline_fm18.json"))
f["name"], f["grids"] = "coverage-in-sample-fm18", {"delta_star": f["grids"]["delta_star"][:11]}
write("in_sample_fm18", f)
b = json.load(open(f"{root}/studies/bursting_bubble_baseline_fm18.json"))
b["name"], b["grids"] = "coverage-bubble-fm18-13", {"delta_star": b["grids"]["delta_star"][:13]}
write("baseline_fm18_13", b)

cases = {}
for name, seed, u in [("PC4", 4, 20.0), ("PC5", 5, 20.0), ("PC6u30", 6, 30.0)]:
    c = copy.deepcopy(paper["cases"]["PC1"])
    c["particles"]["generator"]["seed"] = seed
    c["boundaries"]["y_low"]["superficial_velocity_cm_s"] = u
    cases[name] = c
held = {"schema": paper["schema"], "name": "coverage-held-out", "description": "held-out coverage series",
        "cases": cases, "factors": {"convection": ["superbee"], "fwhm_dp": [6], "drag": ["bvk", "gidaspow_blend"]},
        "grids": {"delta_star": grids[:14]}, "numerics": paper["numerics"], "extrapolation": paper["extrapolation"]}
write("held_out", held)
h = copy.deepcopy(held)
h["name"], h["cases"] = "coverage-held-out-fm18", {"PC4": cases["PC4"]}
h["factors"] = {"convection": ["superbee"], "fwhm_dp": [6], "drag": ["bvk"], "deposition": ["fm18"]}
h["grids"] = {"delta_star": grids[:12]}
write("held_out_fm18", h)
