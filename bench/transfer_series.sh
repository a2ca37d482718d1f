#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# A series of eight grids Δ* ≈ 3.3 → 0.5 of the bursting-bubble baseline
# (PC1, superbee, bvk, fwhm 6) whose n_y are NOT chosen to put the bed
# surface (y* = 28) on a cell face, for one transfer (docs/TRANSFER.md).
# Prints cells, Δ*, status, iterations and dp* per grid and writes
# OUT_DIR/series.csv (h = Δ*, f = dp*) for `gridfree extrapolate`.
#
#   bench/transfer_series.sh BIN_DIR OUT_DIR [--deposition JSON] [--threads N]
set -euo pipefail
source "$(dirname "$0")/bubble_job.sh"
if [[ $# -lt 2 ]]; then
  echo "usage: $0 BIN_DIR OUT_DIR [--deposition JSON] [--threads N]" >&2
  exit 2
fi
bin="$1"; out="$2"; shift 2
deposition='{"kind": "diffusion", "fwhm_dp": 6}'
threads=1
while [[ $# -gt 0 ]]; do
  case "$1" in
    --deposition) deposition="$2"; shift ;;
    --threads) threads="$2"; shift ;;
    *) echo "unknown option $1" >&2; exit 2 ;;
  esac
  shift
done
worker="$bin/gridfree-worker"
[[ -x "$worker" ]] || { echo "no gridfree-worker in $bin" >&2; exit 2; }
mkdir -p "$out"
# Surface position 28 n_y/200 in cells: 8.54 8.96 12.74 15.54 20.02 25.62 35.14 56.42 — no face.
grids="9,61,3 11,74,4 14,91,5 17,111,6 21,143,7 27,183,9 38,251,13 60,403,20"
machine_line
echo "deposition: $deposition"
echo "h,f" >"$out/series.csv"  # h = Δ*, f = dp*
for g in $grids; do
  IFS=, read -r nx ny nz <<<"$g"
  job="$out/job_${nx}_${ny}_${nz}.json"
  write_bubble_job "$job" "$nx" "$ny" "$nz" "$deposition"
  result="$out/result_${nx}_${ny}_${nz}.json"
  set +e
  "$worker" solve "$job" -q --threads "$threads" -o "$result"
  set -e
  python3 - "$result" "$g" "$out/series.csv" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
dp = r["srq"].get("dp_star")
print(f'{sys.argv[2]:<12} {r["grid"]["delta_star"]:7.4f} {r["status"]:<14} {r["iterations"]:6d} {dp if dp is not None else "":>14} '
      f'{r["timing"]["wall_s"]:8.1f}s imbalance {r["extra"].get("interphase_force_imbalance", 0):.2e}')
if dp is not None and r["status"] == "converged":
    with open(sys.argv[3], "a") as f:
        f.write(f'{r["grid"]["delta_star"]!r},{dp!r}\n')
PY
done
