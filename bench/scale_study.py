# SPDX-License-Identifier: GPL-3.0-or-later
"""The benchmark study of K cases x 6 drag laws x the paper's 18 grids
(108*K jobs) on stdout, from the quickstart study's case PC1:

    python3 bench/scale_study.py studies/quickstart.json K

Each case is named okN so that tests/fixtures/fake_worker.sh and
bench/instant_worker.c answer it as converged (dp* = 1159 + delta*).
Used by bench/orchestrator_scale.sh and bench/stop_latency.sh.
"""
import json
import sys

base = json.load(open(sys.argv[1]))
k = int(sys.argv[2])
case = base["cases"]["PC1"]
doc = {
    "schema": base["schema"],
    "name": f"scale{k}",
    "description": f"orchestrator scale benchmark: {k} cases x 6 drag laws x 18 grids",
    "cases": {f"ok{i}": dict(case, particles={"generator": {"kind": "bursting_bubble", "seed": i + 1}})
              for i in range(k)},
    "factors": {"convection": ["superbee"], "fwhm_dp": [6],
                "drag": ["bvk", "gidaspow", "gidaspow_blend", "wen_yu", "hkl", "syamlal_obrien"]},
    "design": "factorial",
    "grids": {"delta_star": [3.3, 2.762, 2.311, 1.934, 1.619, 1.355, 1.134, 0.949, 0.794, 0.665,
                             0.556, 0.466, 0.39, 0.326, 0.273, 0.228, 0.191, 0.16]},
}
print(json.dumps(doc, indent=1))
