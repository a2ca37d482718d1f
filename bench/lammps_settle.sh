#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# A bed settled under gravity by LAMMPS, the held-out comparison for
# gridfree's random emulsion (docs/PARTICLES.md "Held-out check: a
# DEM-settled bed"). Needs LAMMPS with the GRANULAR package (Debian:
# `apt-get install lammps`, binary lmp); nothing in gridfree's build, tests
# or demo needs it.
#
#   bench/lammps_settle.sh OUT_DIR [--n N] [--seed S] [--mu MU] [--steps K]
#
# Defaults: the issue's bed, 30 x 200 x 10 d of d = 0.3256 cm, walls in x
# and z and a floor, 9 011 spheres (eps_s 0.589 in a bed of 26.7 d), seed 1,
# friction 0.5, 28 000 steps (about 0.5 s: the top layer lands after about
# 0.25 s). Writes
# OUT_DIR/settled.dump (the final snapshot, cgs) and OUT_DIR/settled.json,
# a `gridfree-worker particles` spec that reads it ("format": "lammps"), and
# OUT_DIR/log.lammps. Prints the CPU time.
set -euo pipefail
if [[ $# -lt 1 ]]; then
  echo "usage: $0 OUT_DIR [--n N] [--seed S] [--mu MU] [--steps K]" >&2
  exit 2
fi
out="$1"; shift
n=9011; seed=1; mu=0.5; steps=28000
while [[ $# -gt 0 ]]; do
  case "$1" in
    --n) n="$2"; shift 2 ;;
    --seed) seed="$2"; shift 2 ;;
    --mu) mu="$2"; shift 2 ;;
    --steps) steps="$2"; shift 2 ;;
    *) echo "$0: unknown option $1" >&2; exit 2 ;;
  esac
done
command -v lmp > /dev/null || { echo "$0: lmp (LAMMPS) not found" >&2; exit 2; }
here="$(cd "$(dirname "$0")" && pwd)"
mkdir -p "$out"
cd "$out"
d=0.3256
/usr/bin/time -f "LAMMPS CPU %U s user, %S s system, %e s wall" \
  lmp -in "$here/lammps_settle.in" -log log.lammps -screen none \
    -var d "$d" -var nx 30 -var ny 200 -var nz 10 -var n "$n" -var seed "$seed" \
    -var mu "$mu" -var steps "$steps" -var out settled.dump
cat > settled.json <<JSON
{"domain_dp": [30, 200, 10], "particle_diameter_cm": $d,
 "boundaries": {"x": "wall", "z": "wall",
                "y_low": {"type": "mass_inflow", "superficial_velocity_cm_s": 219.0},
                "y_high": {"type": "pressure_outflow", "pressure_dyn_cm2": 0.0}},
 "file": "settled.dump", "format": "lammps", "units": "cgs"}
JSON
grep -E "^ +[0-9]+ +[0-9]+ " log.lammps | tail -3
echo "wrote $out/settled.dump and $out/settled.json"
