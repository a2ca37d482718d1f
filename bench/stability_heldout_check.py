#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Checks every converged value of the held-out stability scenes against
independent estimates (docs/SOLVER.md "Held-out scenes").

    bench/stability_heldout_check.py DB [STUDY]

DB holds a run of studies/stability_heldout.json (STUDY defaults to
"stability_heldout"). For every grid of the view v_stability it prints the
outcome and, for a converged grid, dp* against
  - van Leer's dp* on the same case, transfer and grid (a bounded
    second-order scheme, converged on every grid of the study), with the
    tolerance max(2 |dp*_vL / dp*_upwind - 1|, 2 %): the first- against
    second-order gap on that grid measures the convection error there, and
    two second-order schemes differ by less than it;
  - for the uniform bed (case names starting "uniform"), the pressure drop
    of a continuum bed of the same solids fraction under the same drag law
    (BVK; PHYSICS.md §6: dp/dy = beta U0 / eps_g^2, Re_s = Re_p), within
    the tolerance UNIFORM_TOL (below; a random bed is not a continuum).
Every outcome other than converged must carry a reason. Exits 1 when any
check fails, and prints the failures last.
"""
import math
import subprocess
import sys

UNIFORM_TOL = 0.10  # justified above and in docs/SOLVER.md "Held-out scenes"
SCHEME_TOL = 0.08
RHO, MU, D = 1e-3, 2e-4, 0.01


def bvk_dp_star(phi, u0, y1, y2):
    eps = 1.0 - phi
    re = RHO * u0 * D / MU
    f = 10 * phi / eps ** 2 + eps ** 2 * (1 + 1.5 * math.sqrt(phi))
    x = re ** ((1 + 4 * phi) / 2)
    f += 0.413 / (24 * eps ** 2) * (re * (1 / eps + 3 * eps * phi) + 8.4 * re ** 0.657) * x / (x + 10 ** (3 * phi))
    beta = phi * 18 * MU * eps * f / D ** 2
    return beta * u0 / eps ** 2 * (y2 - y1) * D / (RHO * u0 ** 2)


def rows(db, study):
    sql = (
        "SELECT v.case_name, v.convection, v.fwhm_dp, v.deposition, v.delta_star_nominal, v.outcome, "
        "COALESCE(v.iterations, ''), COALESCE(v.dp_star, ''), COALESCE(v.reason, ''), "
        "json_extract(j.spec_json, '$.case.boundaries.y_low.superficial_velocity_cm_s'), "
        "COALESCE(json_extract(r.result_json, '$.bed.solids_fraction'), "
        "json_extract(j.spec_json, '$.case.particles.generator.solids_fraction')), "
        "json_extract(j.spec_json, '$.case.probes.pressure_drop.y1_dp'), "
        "json_extract(j.spec_json, '$.case.probes.pressure_drop.y2_dp') "
        "FROM v_stability v JOIN jobs j ON j.id = v.job_id LEFT JOIN results r ON r.job_id = v.job_id WHERE v.study = '%s' "
        "ORDER BY v.case_name, v.deposition, v.fwhm_dp DESC, v.convection, v.delta_star_nominal DESC;" % study
    )
    out = subprocess.run(["sqlite3", "-separator", "|", db, sql], check=True, capture_output=True, text=True).stdout
    for line in out.splitlines():
        f = line.split("|")
        yield {"case": f[0], "scheme": f[1], "fwhm": float(f[2]), "dep": f[3], "h": float(f[4]), "outcome": f[5],
               "it": f[6], "dp": float(f[7]) if f[7] else None, "reason": f[8], "u0": float(f[9]),
               "phi": float(f[10]), "y1": float(f[11]), "y2": float(f[12])}


def main(argv):
    if len(argv) < 2:
        sys.exit("usage: stability_heldout_check.py DB [STUDY]")
    all_rows = list(rows(argv[1], argv[2] if len(argv) > 2 else "stability_heldout"))
    if not all_rows:
        sys.exit("no rows in v_stability for the study")

    def key(r, scheme):
        # centroid has no filter: its cells are the same jobs at every FWHM level
        return (r["case"], r["fwhm"] if r["dep"] != "centroid" else 0, r["dep"], r["h"], scheme)

    by = {key(r, r["scheme"]): r for r in all_rows}
    failures, checked, worst = [], 0, {}
    print("case | scheme | transfer | Δ* | outcome | it. | dp* | vs van Leer (tol) | vs continuum | reason")
    all_rows = [r for r in all_rows if r["dep"] != "centroid" or r["fwhm"] == max(x["fwhm"] for x in all_rows)]
    for r in all_rows:
        transfer = "centroid" if r["dep"] == "centroid" else f"fwhm{r['fwhm']:g}"
        cols = [r["case"], r["scheme"], transfer, f"{r['h']:g}", r["outcome"], r["it"]]
        if r["outcome"] != "converged":
            if not r["reason"]:
                failures.append(f"{cols}: no reason")
            print(" | ".join(cols + ["", "", "", r["reason"][:90]]))
            continue
        vl, fou = by.get(key(r, "van_leer")), by.get(key(r, "fou"))
        vs_vl = ""
        if vl and fou and vl["outcome"] in ("converged", "stalled") and vl["dp"] and fou["outcome"] == "converged":
            tol = max(2 * abs(vl["dp"] / fou["dp"] - 1), SCHEME_TOL)
            dev = r["dp"] / vl["dp"] - 1
            vs_vl = f"{dev:+.2%} ({tol:.1%}{', vL stalled' if vl['outcome'] == 'stalled' else ''})"
            checked += 1
            if abs(dev) > tol:
                failures.append(f"{cols}: dp* {r['dp']:.6g} is {dev:+.2%} from van Leer's {vl['dp']:.6g}, tol {tol:.1%}")
            w = worst.setdefault(r["scheme"], [0.0, 0.0])
            w[0] = max(w[0], abs(dev))
        elif r["scheme"] not in ("van_leer", "fou"):
            failures.append(f"{cols}: no converged van Leer and upwind on the same grid to check against")
        vs_c = ""
        if r["case"].startswith("uniform") and r["dep"] != "centroid" and r["fwhm"] == 6:
            ref = bvk_dp_star(r["phi"], r["u0"], r["y1"], r["y2"])
            dev = r["dp"] / ref - 1
            vs_c = f"{dev:+.2%}"
            w = worst.setdefault(r["scheme"], [0.0, 0.0])
            w[1] = max(w[1], abs(dev))
            if abs(dev) > UNIFORM_TOL:
                failures.append(f"{cols}: dp* {r['dp']:.6g} is {dev:+.2%} from the continuum bed's {ref:.6g}")
        print(" | ".join(cols + [f"{r['dp']:.6g}", vs_vl, vs_c, ""]))
    counts = {}
    for r in all_rows:
        counts[r["outcome"]] = counts.get(r["outcome"], 0) + 1
    print("\noutcomes:", ", ".join(f"{n} {o}" for o, n in sorted(counts.items())))
    print(f"{checked} converged values checked against van Leer's;",
          "largest deviation per scheme (vs van Leer, vs continuum):",
          ", ".join(f"{s} {a:.2%}/{b:.2%}" for s, (a, b) in sorted(worst.items())))
    if failures:
        print("\nFAILED:")
        for f in failures:
            print(" ", f)
        sys.exit(1)
    print("all checks passed")


if __name__ == "__main__":
    main(sys.argv)
