#!/usr/bin/env bash
# Bursting-bubble baseline (PC1, superbee, bvk, fwhm 6) on Δ* = 1 and 0.5,
# and optionally 0.25: wall time, iterations, peak RSS, cells·iterations/s.
#
#   bench/run.sh BIN_DIR [--fine] [--threads N]
#
# BIN_DIR holds gridfree-worker (e.g. build/bin). --fine adds Δ* = 0.25
# (3.84 M cells: minutes to hours). Results go to a temporary folder.
set -euo pipefail
if [[ $# -lt 1 ]]; then
  echo "usage: $0 BIN_DIR [--fine] [--threads N]" >&2
  exit 2
fi
bin="$1"; shift
fine=0
threads=""
while [[ $# -gt 0 ]]; do
  case "$1" in
    --fine) fine=1 ;;
    --threads) threads="--threads $2"; shift ;;
    *) echo "unknown option $1" >&2; exit 2 ;;
  esac
  shift
done
worker="$bin/gridfree-worker"
[[ -x "$worker" ]] || { echo "no gridfree-worker in $bin" >&2; exit 2; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

grids=("30 200 10" "60 400 20")
[[ $fine -eq 1 ]] && grids+=("120 800 40")

echo "machine: $(nproc) cores, $(uname -m), $(date -u +%Y-%m-%d)"
printf '%-14s %10s %8s %10s %10s %12s %14s\n' cells delta_star status iterations wall_s peak_rss_mb cell_it_per_s
for g in "${grids[@]}"; do
  read -r nx ny nz <<<"$g"
  job="$work/job_${nx}.json"
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
    "deposition": {"kind": "diffusion", "fwhm_dp": 6},
    "tolerances": {"linear": 1e-8, "filter": 1e-10, "steady": 1e-5},
    "max_iterations": 20000
  }
}
JSON
  set +e
  # shellcheck disable=SC2086
  "$worker" solve "$job" -o "$work/result_${nx}.json" -q $threads
  set -e
  python3 - "$work/result_${nx}.json" "$nx" "$ny" "$nz" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
cells = int(sys.argv[2]) * int(sys.argv[3]) * int(sys.argv[4])
wall = r["timing"]["wall_s"]
rate = cells * r["iterations"] / wall if wall > 0 else 0
print(f'{"x".join(sys.argv[2:5]):<14} {r["grid"]["delta_star"]:10.3g} {r["status"]:>8} {r["iterations"]:10d} '
      f'{wall:10.1f} {r["memory"]["peak_rss_mb"]:12.1f} {rate:14.3g}   dp_star {r["srq"].get("dp_star")}')
PY
done
