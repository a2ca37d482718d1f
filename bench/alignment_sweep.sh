#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
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
source "$(dirname "$0")/bubble_job.sh"
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

machine_line
echo "deposition: $deposition   n_y offsets: $offsets"
printf '%-12s %8s %s\n' base delta_star "spread  dp* per variant"
for g in $grids; do
  IFS=, read -r nx ny nz <<<"$g"
  job="$work/job_${nx}_${ny}_${nz}.json"
  write_bubble_job "$job" "$nx" "$ny" "$nz" "$deposition"
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
