#!/usr/bin/env bash
# Bursting-bubble baseline (PC1, superbee, bvk, fwhm 6) on Δ* = 1, 0.5 and
# 0.25: wall time, iterations, peak RSS, cells·iterations/s and where the
# time went (drag + filter, momentum, pressure).
#
#   bench/run.sh BIN_DIR [--quick] [--threads N] [--csv FILE]
#
# BIN_DIR holds gridfree-worker (e.g. build/bin). --quick skips Δ* = 0.25
# (3.84 M cells, about half an hour on 2 cores). --csv also writes the rows
# to FILE. Jobs and results go to a temporary folder.
set -euo pipefail
if [[ $# -lt 1 ]]; then
  echo "usage: $0 BIN_DIR [--quick] [--threads N] [--csv FILE]" >&2
  exit 2
fi
bin="$1"; shift
quick=0
threads=""
csv=""
while [[ $# -gt 0 ]]; do
  case "$1" in
    --quick) quick=1 ;;
    --fine) ;;  # the default; kept for older command lines
    --threads) threads="--threads $2"; shift ;;
    --csv) csv="$2"; shift ;;
    *) echo "unknown option $1" >&2; exit 2 ;;
  esac
  shift
done
worker="$bin/gridfree-worker"
[[ -x "$worker" ]] || { echo "no gridfree-worker in $bin" >&2; exit 2; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

grids=("30 200 10" "60 400 20")
[[ $quick -eq 0 ]] && grids+=("120 800 40")
[[ -n "$csv" ]] && echo "cells,delta_star,status,iterations,wall_s,cpu_s,peak_rss_mb,cell_iterations_per_s,drag_s,momentum_s,pressure_s,dp_star" >"$csv"

echo "machine: $(nproc) cores, $(uname -m), $(date -u +%Y-%m-%d)"
printf '%-14s %10s %10s %10s %8s %8s %11s %13s %7s %9s %9s %12s\n' cells delta_star status iterations wall_s cpu_s peak_rss_mb cell_it_per_s drag_s momentum_s pressure_s dp_star
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
  python3 - "$work/result_${nx}.json" "$nx" "$ny" "$nz" "$csv" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
n = [int(v) for v in sys.argv[2:5]]
cells = n[0] * n[1] * n[2]
wall = r["timing"]["wall_s"]
rate = cells * r["iterations"] / wall if wall > 0 else 0
t = r.get("extra", {}).get("timing", {})
dp = r["srq"].get("dp_star")
row = ["x".join(sys.argv[2:5]), f'{r["grid"]["delta_star"]:.3g}', r["status"], str(r["iterations"]),
       f"{wall:.1f}", f'{r["timing"]["cpu_s"]:.1f}', f'{r["memory"]["peak_rss_mb"]:.1f}', f"{rate:.3e}",
       f'{t.get("drag_s", 0):.1f}', f'{t.get("momentum_s", 0):.1f}', f'{t.get("pressure_s", 0):.1f}',
       f"{dp:.8g}" if dp is not None else ""]
print("{:<14} {:>10} {:>10} {:>10} {:>8} {:>8} {:>11} {:>13} {:>7} {:>9} {:>9} {:>12}".format(*row))
if sys.argv[5]:
    with open(sys.argv[5], "a") as f:
        f.write(",".join(row) + "\n")
PY
done
