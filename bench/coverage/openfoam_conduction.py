#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
# Exact-answer OpenFOAM series for the coverage corpus: 1-D transient
# conduction with laplacianFoam, ∂T/∂t = D ∂²T/∂x² on 0 < x < 1, T = 0 at both
# ends, T(x, 0) = sin(πx), D = 1, to t = 0.1. Exact answer
#   T(x, t) = exp(−π² D t) sin(πx),  mean over x: (2/π) exp(−π² D t),
#   T(1/4, t) = exp(−π² D t) / √2,
# the latter read from OpenFOAM's own cell values, linearly interpolated
# between the two centres around x = 1/4.
# Grids N = 10 … 160 cells (ratio √2), Δt = h/10: with Euler (first order in
# time) the error is O(h) (formal order 1), with backward (second order) O(h²)
# (formal order 2). Each run takes well under a second.
#
#   WM_PROJECT_DIR=/usr/share/openfoam bench/coverage/openfoam_conduction.py > bench/coverage/corpus/openfoam_conduction.json
import math
import os
import re
import subprocess
import sys

from corpus_file import corpus_text
import tempfile

GRIDS = [10, 14, 20, 28, 40, 56, 80, 113, 160]
END_TIME = 0.1
HEADER = "FoamFile\n{\n    version 2.0;\n    format ascii;\n    class %s;\n    object %s;\n}\n"


def files(n, ddt):
    dt = 0.1 / n
    centres = [(i + 0.5) / n for i in range(n)]
    t0 = "\n".join("%.17g" % math.sin(math.pi * x) for x in centres)
    return {
        "system/blockMeshDict": HEADER % ("dictionary", "blockMeshDict") + (
            "convertToMeters 1;\nvertices ((0 0 0) (1 0 0) (1 0.1 0) (0 0.1 0) (0 0 0.1) (1 0 0.1) (1 0.1 0.1) "
            "(0 0.1 0.1));\nblocks (hex (0 1 2 3 4 5 6 7) (%d 1 1) simpleGrading (1 1 1));\nedges ();\n"
            "boundary (\n ends { type patch; faces ((0 4 7 3) (1 2 6 5)); }\n"
            " sides { type empty; faces ((0 1 5 4) (3 7 6 2) (0 3 2 1) (4 5 6 7)); }\n);\n") % n,
        "system/controlDict": HEADER % ("dictionary", "controlDict") + (
            "application laplacianFoam;\nstartFrom startTime;\nstartTime 0;\nstopAt endTime;\nendTime %.17g;\n"
            "deltaT %.17g;\nwriteControl runTime;\nwriteInterval %.17g;\nwriteFormat ascii;\nwritePrecision 17;\n"
            "timeFormat general;\ntimePrecision 17;\nrunTimeModifiable false;\n") % (END_TIME, dt, END_TIME),
        "system/fvSchemes": HEADER % ("dictionary", "fvSchemes") + (
            "ddtSchemes { default %s; }\ngradSchemes { default Gauss linear; }\ndivSchemes { default none; }\n"
            "laplacianSchemes { default Gauss linear corrected; }\ninterpolationSchemes { default linear; }\n"
            "snGradSchemes { default corrected; }\n") % ddt,
        "system/fvSolution": HEADER % ("dictionary", "fvSolution") + (
            "solvers { T { solver PCG; preconditioner DIC; tolerance 1e-14; relTol 0; } }\n"
            "SIMPLE { nNonOrthogonalCorrectors 0; }\n"),
        "constant/transportProperties": HEADER % ("dictionary", "transportProperties") + "DT DT [0 2 -1 0 0 0 0] 1;\n",
        "0/T": HEADER % ("volScalarField", "T") + (
            "dimensions [0 0 0 1 0 0 0];\ninternalField nonuniform List<scalar> %d\n(\n%s\n);\n"
            "boundaryField { ends { type fixedValue; value uniform 0; } sides { type empty; } }\n") % (n, t0),
    }


def run(n, ddt):
    with tempfile.TemporaryDirectory() as case:
        for name, text in files(n, ddt).items():
            os.makedirs(os.path.join(case, os.path.dirname(name)), exist_ok=True)
            open(os.path.join(case, name), "w").write(text)
        for app in ("blockMesh", "laplacianFoam"):
            subprocess.run([app, "-case", case], check=True, capture_output=True)
        times = [d for d in os.listdir(case) if re.fullmatch(r"[0-9.eE+-]+", d) and float(d) > 0]
        last = max(times, key=float)
        text = open(os.path.join(case, last, "T")).read()
        body = text[text.index("(", text.index("internalField")) + 1:]
        values = [float(v) for v in body[:body.index(")")].split()]
    assert len(values) == n
    h = 1.0 / n
    x = 0.25 / h - 0.5  # T(1/4) between the centres around it
    i = int(math.floor(x))
    quarter = values[i] + (x - i) * (values[i + 1] - values[i])
    return h, sum(values) / n, quarter


def main():
    decay = math.exp(-math.pi ** 2 * END_TIME)
    exact = {"mean T": 2 / math.pi * decay, "T(1/4)": decay / math.sqrt(2)}
    version = subprocess.run("laplacianFoam -help | grep '^Using:'", shell=True, capture_output=True,
                             text=True).stdout.strip()
    series = []
    for ddt, order in (("Euler", 1), ("backward", 2)):
        rows = [run(n, ddt) for n in GRIDS]
        for q, col in (("mean T", 1), ("T(1/4)", 2)):
            series.append({"name": "laplacianFoam/%s/%s" % (ddt, q), "code": "OpenFOAM laplacianFoam",
                           "scheme": "Gauss linear corrected, ddt %s, dt = h/10" % ddt, "quantity": q,
                           "formal_order": order, "N": GRIDS, "h": [r[0] for r in rows],
                           "f": [r[col] for r in rows], "reference": exact[q], "reference_halfwidth": 0,
                           "reference_source": "exact: T = exp(-pi^2 t) sin(pi x) at t = 0.1"})
    doc = {"source": "OpenFOAM laplacianFoam, 1-D transient conduction with an exact answer (run here)",
           "command": "WM_PROJECT_DIR=/usr/share/openfoam bench/coverage/openfoam_conduction.py",
           "openfoam": version, "h": "h = 1/N, N cells on 0 < x < 1",
           "notes": ["The initial field is sin(pi x) at cell centres; T(1/4) is interpolated linearly "
                     "between OpenFOAM's two cell values around x = 1/4."],
           "series": series}
    sys.stdout.write(corpus_text(doc))


if __name__ == "__main__":
    main()
