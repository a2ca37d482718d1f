#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
# Exact-answer OpenFOAM series for the coverage corpus: steady 1-D
# advection–diffusion with scalarTransportFoam,
#   u dT/dx = D d²T/dx² on 0 < x < 1, T(0) = 0, T(1) = 1, u = 1, D = 1/Pe,
# Pe = 10. Exact answer
#   T(x) = (exp(Pe x) − 1) / (exp(Pe) − 1),
#   mean over x: ((exp(Pe) − 1)/Pe − 1) / (exp(Pe) − 1),
#   T(1/2) = 1 / (exp(Pe/2) + 1),
# the mean as the sum of OpenFOAM's cell values times h (midpoint rule,
# second order), T(1/2) read from the two cell centres around x = 1/2
# (linear, second order: with an even N they lie h/2 either side).
# Convection `Gauss upwind` (formal order 1), `Gauss linear` (formal
# order 2) and `Gauss vanLeer` (a TVD limiter: no formal order declared);
# Laplacian `Gauss linear corrected` throughout. steadyState in time,
# iterated until T's initial residual is below 1e-12 (SIMPLE
# residualControl): upwind and linear are linear in T, one step with the
# linear solver converged to 1e-14 is the answer; vanLeer's limiter lags its
# weights one step. Grids N = 10 … 160 cells (ratio √2, rounded to even
# N); cell Péclet number u h/D = 1 on the coarsest grid. Each run takes
# well under a second.
#
#   WM_PROJECT_DIR=/usr/share/openfoam bench/coverage/openfoam_advection_diffusion.py \
#       > bench/coverage/corpus/openfoam_advection_diffusion.json
import math
import os
import re
import subprocess
import sys

from corpus_file import corpus_text
import tempfile

GRIDS = [10, 14, 20, 28, 40, 56, 80, 114, 160]
PECLET = 10.0
SCHEMES = (("upwind", 1), ("linear", 2), ("vanLeer", None))
HEADER = "FoamFile\n{\n    version 2.0;\n    format ascii;\n    class %s;\n    object %s;\n}\n"


def files(n, scheme):
    return {
        "system/blockMeshDict": HEADER % ("dictionary", "blockMeshDict") + (
            "convertToMeters 1;\nvertices ((0 0 0) (1 0 0) (1 0.1 0) (0 0.1 0) (0 0 0.1) (1 0 0.1) (1 0.1 0.1) "
            "(0 0.1 0.1));\nblocks (hex (0 1 2 3 4 5 6 7) (%d 1 1) simpleGrading (1 1 1));\nedges ();\n"
            "boundary (\n inlet { type patch; faces ((0 4 7 3)); }\n outlet { type patch; faces ((1 2 6 5)); }\n"
            " sides { type empty; faces ((0 1 5 4) (3 7 6 2) (0 3 2 1) (4 5 6 7)); }\n);\n") % n,
        "system/controlDict": HEADER % ("dictionary", "controlDict") + (
            "application scalarTransportFoam;\nstartFrom startTime;\nstartTime 0;\nstopAt endTime;\nendTime 5000;\n"
            "deltaT 1;\nwriteControl timeStep;\nwriteInterval 5000;\nwriteFormat ascii;\nwritePrecision 17;\n"
            "timeFormat general;\ntimePrecision 6;\nrunTimeModifiable false;\n"),
        "system/fvSchemes": HEADER % ("dictionary", "fvSchemes") + (
            "ddtSchemes { default steadyState; }\ngradSchemes { default Gauss linear; }\n"
            "divSchemes { default none; div(phi,T) bounded Gauss %s; }\n"
            "laplacianSchemes { default Gauss linear corrected; }\ninterpolationSchemes { default linear; }\n"
            "snGradSchemes { default corrected; }\n") % scheme,
        "system/fvSolution": HEADER % ("dictionary", "fvSolution") + (
            "solvers { T { solver PBiCGStab; preconditioner DILU; tolerance 1e-14; relTol 0; maxIter 10000; } }\n"
            "SIMPLE { nNonOrthogonalCorrectors 0; residualControl { T 1e-12; } }\n"),
        "constant/transportProperties": HEADER % ("dictionary", "transportProperties") + (
            "DT DT [0 2 -1 0 0 0 0] %.17g;\n") % (1.0 / PECLET),
        "0/T": HEADER % ("volScalarField", "T") + (
            "dimensions [0 0 0 0 0 0 0];\ninternalField uniform 0;\nboundaryField {\n"
            " inlet { type fixedValue; value uniform 0; }\n outlet { type fixedValue; value uniform 1; }\n"
            " sides { type empty; }\n}\n"),
        "0/U": HEADER % ("volVectorField", "U") + (
            "dimensions [0 1 -1 0 0 0 0];\ninternalField uniform (1 0 0);\nboundaryField {\n"
            " inlet { type fixedValue; value uniform (1 0 0); }\n outlet { type zeroGradient; }\n"
            " sides { type empty; }\n}\n"),
    }


def cell_values(case, time):
    text = open(os.path.join(case, time, "T")).read()
    body = text[text.index("(", text.index("internalField")) + 1:]
    return [float(v) for v in body[:body.index(")")].split()]


def run(n, scheme):
    with tempfile.TemporaryDirectory() as case:
        for name, text in files(n, scheme).items():
            os.makedirs(os.path.join(case, os.path.dirname(name)), exist_ok=True)
            open(os.path.join(case, name), "w").write(text)
        subprocess.run(["blockMesh", "-case", case], check=True, capture_output=True)
        log = subprocess.run(["scalarTransportFoam", "-case", case], check=True, capture_output=True,
                             text=True).stdout
        if "converged in" not in log:
            sys.exit("N = %d, %s: T's residual did not reach 1e-12 in 5000 steps" % (n, scheme))
        times = [d for d in os.listdir(case) if re.fullmatch(r"[0-9]+", d) and int(d) > 0]
        values = cell_values(case, max(times, key=int))
    assert len(values) == n and n % 2 == 0
    h = 1.0 / n
    return h, sum(values) * h, 0.5 * (values[n // 2 - 1] + values[n // 2])


def main():
    e = math.exp(PECLET)
    exact = {"mean T": ((e - 1) / PECLET - 1) / (e - 1), "T(1/2)": 1 / (math.exp(PECLET / 2) + 1)}
    version = subprocess.run("scalarTransportFoam -help | grep '^Using:'", shell=True, capture_output=True,
                             text=True).stdout.strip()
    series = []
    for scheme, order in SCHEMES:
        rows = [run(n, scheme) for n in GRIDS]
        for q, col in (("mean T", 1), ("T(1/2)", 2)):
            series.append({"name": "scalarTransportFoam/%s/%s" % (scheme, q), "code": "OpenFOAM scalarTransportFoam",
                           "scheme": "div(phi,T) bounded Gauss %s, laplacian Gauss linear corrected, steadyState"
                           % scheme, "quantity": q, "formal_order": order, "N": GRIDS,
                           "h": [r[0] for r in rows], "f": [r[col] for r in rows], "reference": exact[q],
                           "reference_halfwidth": 0,
                           "reference_source": "exact: T = (exp(Pe x) - 1)/(exp(Pe) - 1), Pe = 10"})
    doc = {"source": "OpenFOAM scalarTransportFoam, steady 1-D advection-diffusion with an exact answer (run here)",
           "command": "WM_PROJECT_DIR=/usr/share/openfoam bench/coverage/openfoam_advection_diffusion.py",
           "openfoam": version, "h": "h = 1/N, N cells on 0 < x < 1",
           "notes": ["u = 1, D = 0.1 (Pe = 10), T(0) = 0, T(1) = 1; mean T = h * sum of the cell values; "
                     "T(1/2) = mean of the two cell values either side of x = 1/2.",
                     "vanLeer is a TVD limiter: no formal order is declared for it (formal_order null)."],
           "series": series}
    sys.stdout.write(corpus_text(doc))


if __name__ == "__main__":
    main()
