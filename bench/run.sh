#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Worker benchmark: the bursting-bubble baseline (PC1, superbee, bvk, fwhm 6)
# on Δ* = 1, 0.5 and 0.25, and the SSCP-like bed (walls in x and z,
# Re_p ≈ 500) on Δ* = 4.7 and 2.3: wall and CPU time, iterations, peak RSS,
# bytes per cell, cost per cell (µs of wall time per cell), cells·iterations
# per second and where the time went (drag + filter, momentum, pressure).
#
#   bench/run.sh BIN_DIR [--quick] [--finest] [--only bubble|sscp] [--threads N] [--seed S] [--csv FILE]
#
# BIN_DIR holds gridfree-worker (e.g. build/bin). --quick skips Δ* = 0.25
# (3.84 M cells); --finest adds Δ* = 0.16 (187 × 1250 × 62 = 14.5 M cells,
# several GB: only on an otherwise idle machine). --csv also writes the rows
# to FILE. --seed S (default 1) generates another particle configuration
# of both beds: the held-out check of figures measured on seed 1. Jobs and
# results go to a temporary folder. Print `uptime` with
# the figures: timings on a shared machine are noisy. `iter` and cell_it/s
# count the fine grid's outer iterations; `nested` is the wall time of the
# coarser grids of the nested start (docs/SOLVER.md), included in wall_s.
set -euo pipefail
if [[ $# -lt 1 ]]; then
  echo "usage: $0 BIN_DIR [--quick] [--finest] [--only bubble|sscp] [--threads N] [--seed S] [--csv FILE]" >&2
  exit 2
fi
bin="$1"; shift
quick=0
finest=0
only=""
threads=""
seed=1
csv=""
while [[ $# -gt 0 ]]; do
  case "$1" in
    --quick) quick=1 ;;
    --finest) finest=1 ;;
    --fine) ;;  # the default; kept for older command lines
    --only) only="$2"; shift ;;
    --threads) threads="--threads $2"; shift ;;
    --seed) seed="$2"; shift
            [[ "$seed" =~ ^[0-9]+$ ]] || { echo "--seed: expected a non-negative integer, got '$seed'" >&2; exit 2; } ;;
    --csv) csv="$2"; shift ;;
    *) echo "unknown option $1" >&2; exit 2 ;;
  esac
  shift
done
worker="$bin/gridfree-worker"
[[ -x "$worker" ]] || { echo "no gridfree-worker in $bin" >&2; exit 2; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

# case name, cells
runs=()
if [[ "$only" != sscp ]]; then
  runs+=("bubble 30 200 10" "bubble 60 400 20")
  [[ $quick -eq 0 ]] && runs+=("bubble 120 800 40")
  [[ $finest -eq 1 ]] && runs+=("bubble 187 1250 62")
fi
if [[ "$only" != bubble ]]; then
  runs+=("sscp 15 79 5" "sscp 30 161 10")
fi

bubble_case() {
  cat <<JSON
    "name": "PC1", "domain_dp": [30, 200, 10], "particle_diameter_cm": 0.01,
    "gas": {"density_g_cm3": 1e-3, "viscosity_g_cm_s": 2e-4},
    "gravity_cm_s2": [0, 0, 0],
    "boundaries": {"x": "periodic", "z": "periodic",
      "y_low": {"type": "mass_inflow", "superficial_velocity_cm_s": 20.0},
      "y_high": {"type": "pressure_outflow", "pressure_dyn_cm2": 0.0}},
    "particles": {"generator": {"kind": "bursting_bubble", "seed": $seed}},
    "probes": {"pressure_drop": {"y1_dp": 4, "y2_dp": 104}}
JSON
}
sscp_case() {
  cat <<JSON
    "name": "SSCP-like", "domain_dp": [70, 370, 23], "particle_diameter_cm": 0.3256,
    "gas": {"density_g_cm3": 1.2e-3, "viscosity_g_cm_s": 1.8e-4},
    "gravity_cm_s2": [0, -981, 0],
    "boundaries": {"x": "wall", "z": "wall",
      "y_low": {"type": "mass_inflow", "superficial_velocity_cm_s": 219.0},
      "y_high": {"type": "pressure_outflow", "pressure_dyn_cm2": 0.0}},
    "particles": {"generator": {"kind": "sscp_like", "seed": $seed, "bed_height_dp": 51,
      "solids_fraction": 0.58, "bubbles": 3, "bubble_radius_dp": 4}},
    "probes": {"pressure_drop": {"y1_dp": 4, "y2_dp": 44}}
JSON
}

header="case,cells,delta_star,status,iterations,wall_s,cpu_s,peak_rss_mb,bytes_per_cell,us_per_cell,cell_iterations_per_s,drag_s,momentum_s,pressure_s,nested_s,dp_star"
[[ -n "$csv" ]] && echo "$header" >"$csv"
echo "machine: $(nproc) cores, $(uname -m), $(date -u +%Y-%m-%dT%H:%MZ); load:$(uptime | sed 's/.*load average://'); particle seed $seed"
printf '%-9s %-13s %6s %10s %5s %8s %8s %8s %6s %8s %10s %6s %6s %6s %6s %13s\n' case cells dstar status iter wall_s cpu_s rss_mb B/cell us/cell cell_it/s drag mom pres nested dp_star
for r in "${runs[@]}"; do
  read -r name nx ny nz <<<"$r"
  job="$work/job_${name}_${nx}.json"
  {
    echo '{ "schema": "gridfree/job/1", "case": {'
    "${name}_case"
    cat <<JSON
  },
  "numerics": {
    "grid": {"cells": [$nx, $ny, $nz]}, "convection": "superbee", "drag": "bvk",
    "deposition": {"kind": "diffusion", "fwhm_dp": 6},
    "tolerances": {"linear": 1e-8, "filter": 1e-10, "steady": 1e-5},
    "max_iterations": 20000
  }
}
JSON
  } >"$job"
  set +e
  # shellcheck disable=SC2086
  "$worker" solve "$job" -o "$work/result.json" -q $threads
  set -e
  python3 - "$work/result.json" "$name" "$nx" "$ny" "$nz" "$csv" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
n = [int(v) for v in sys.argv[3:6]]
cells = n[0] * n[1] * n[2]
wall = r["timing"]["wall_s"]
rss = r["memory"]["peak_rss_mb"]
rate = cells * r["iterations"] / wall if wall > 0 else 0
t = r.get("extra", {}).get("timing", {})
nested = sum(level.get("wall_s", 0) for level in r.get("extra", {}).get("nested_start", [])[-1:])
dp = r["srq"].get("dp_star")
row = [sys.argv[2], "x".join(sys.argv[3:6]), f'{r["grid"]["delta_star"]:.3g}', r["status"], str(r["iterations"]),
       f"{wall:.1f}", f'{r["timing"]["cpu_s"]:.1f}', f"{rss:.1f}", f"{rss * 2**20 / cells:.0f}",
       f"{1e6 * wall / cells:.1f}", f"{rate:.3e}",
       f'{t.get("drag_s", 0):.1f}', f'{t.get("momentum_s", 0):.1f}', f'{t.get("pressure_s", 0):.1f}',
       f"{nested:.1f}", f"{dp:.10g}" if dp is not None else ""]
print("{:<9} {:<13} {:>6} {:>10} {:>5} {:>8} {:>8} {:>8} {:>6} {:>8} {:>10} {:>6} {:>6} {:>6} {:>6} {:>13}".format(*row))
if sys.argv[6]:
    with open(sys.argv[6], "a") as f:
        f.write(",".join(row) + "\n")
PY
done
