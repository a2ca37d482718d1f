#!/usr/bin/env bash
# Vertical-alignment sweep of the bursting-bubble baseline (PC1, superbee,
# bvk, fwhm 6): for each base grid, n_y is changed by the given offsets so
# that the bed surface (y* = 28) moves through one cell, and
# `gridfree-worker align` reports dp* of every variant and the spread
# (max − min)/mean (docs/TRANSFER.md).
#
#   bench/alignment_sweep.sh BIN_DIR [--deposition JSON] [--grids "NX,NY,NZ ..."]
#                            [--offsets 0,1,...] [--threads N] [--out DIR]
#
# --deposition  the numerics.deposition object (default: the default transfer,
#               {"kind": "diffusion", "fwhm_dp": 6}); e.g. '{"preset": "fm18", "fwhm_dp": 6}'
# --grids       base grids (default Δ* ≈ 3.3, 2, 1.25, 1: "9,60,3 15,100,5 24,160,8 30,200,10")
# --offsets     n_y offsets (default 0..7: the surface moves 28·7/200 ≈ 1 cell)
# --out         keep the align JSON of each grid here (default: a temporary folder)
set -euo pipefail
if [[ $# -lt 1 ]]; then
  echo "usage: $0 BIN_DIR [--deposition JSON] [--grids LIST] [--offsets LIST] [--threads N] [--out DIR]" >&2
  exit 2
fi
bin="$1"; shift
deposition='{"kind": "diffusion", "fwhm_dp": 6}'
grids="9,60,3 15,100,5 24,160,8 30,200,10"
offsets="0,1,2,3,4,5,6,7"
threads=1
out=""
while [[ $# -gt 0 ]]; do
  case "$1" in
    --deposition) deposition="$2"; shift ;;
    --grids) grids="$2"; shift ;;
    --offsets) offsets="$2"; shift ;;
    --threads) threads="$2"; shift ;;
    --out) out="$2"; shift ;;
    *) echo "unknown option $1" >&2; exit 2 ;;
  esac
  shift
done
worker="$bin/gridfree-worker"
[[ -x "$worker" ]] || { echo "no gridfree-worker in $bin" >&2; exit 2; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
[[ -n "$out" ]] && mkdir -p "$out" || out="$work"

echo "machine: $(nproc) cores, $(uname -m), $(date -u +%Y-%m-%dT%H:%MZ), load $(cut -d' ' -f1-3 /proc/loadavg)"
echo "deposition: $deposition   n_y offsets: $offsets"
printf '%-12s %8s %s\n' base delta_star "spread  dp* per variant"
for g in $grids; do
  IFS=, read -r nx ny nz <<<"$g"
  job="$work/job_${nx}_${ny}_${nz}.json"
  cat >"$job" <<JSON
{
  "schema": "gridfree/job/1",
  "case": {
    "name": "PC1", "domain_dp": [30, 200, 10], "particle_diameter_cm": 0.01,
    "gas": {"density_g_cm3": 1e-3, "viscosity_g_cm_s": 2e-4},
    "gravity_cm_s2": [0, 0, 0],
    "boundaries": {"x": "periodic", "z": "periodic",
      "y_low": {"type": "mass_inflow", "superficial_velocity_cm_s": 20.0},
      "y_high": {"type": "pressure_outflow", "pressure_dyn_cm2": 0.0}},
    "particles": {"generator": {"kind": "bursting_bubble", "seed": 1}},
    "probes": {"pressure_drop": {"y1_dp": 4, "y2_dp": 104}}
  },
  "numerics": {
    "grid": {"cells": [$nx, $ny, $nz]}, "convection": "superbee", "drag": "bvk",
    "deposition": $deposition,
    "tolerances": {"linear": 1e-8, "filter": 1e-10, "steady": 1e-5},
    "max_iterations": 20000
  }
}
JSON
  result="$out/align_${nx}_${ny}_${nz}.json"
  set +e
  "$worker" align "$job" --cells-y-offsets "$offsets" --threads "$threads" -q -o "$result"
  set -e
  python3 - "$result" "$g" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
v = r["variants"]
dps = " ".join(f'{x["cells"][1]}:{x["dp_star"]:.6g}' if x["dp_star"] is not None else f'{x["cells"][1]}:{x["status"]}' for x in v)
spread = f'{100 * r["spread"]:.3f}%' if r["spread"] is not None else "n/a (" + r["reason"] + ")"
print(f'{sys.argv[2]:<12} {v[0]["delta_star"]:8.3f} {spread}  {dps}')
PY
done
