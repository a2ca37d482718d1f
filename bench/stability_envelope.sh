#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The solver's robustness envelope (docs/SOLVER.md "Robustness envelope"):
# runs studies/stability.json (120 series, 540 distinct jobs on six grids
# Δ* 3.3 → 0.7; about 100 s of CPU, 9–16 min of wall time on 2 shared
# cores) into OUT_DIR/stability.sqlite and prints the outcome of every grid
# per series from the view v_stability ("3.3:45" = converged in 45 outer
# iterations; else the outcome word), then the count of each outcome. The
# chart is the report's stability map, OUT_DIR/reports/stability/
# stability_map.svg (docs/figures/stability_map.svg is a copy).
#
# --study NAME runs studies/NAME.json instead, into OUT_DIR/NAME.sqlite:
#   stability_envelope  the envelope under the default settings (docs/SOLVER.md
#                       "The envelope under the default settings"); also
#                       writes OUT_DIR/stability_envelope.svg, the chart of
#                       outer iterations and outcome over Δ* per bed and Re_p
#                       (docs/figures/stability_envelope.svg is a copy)
#   stability_heldout   the held-out scenes (docs/SOLVER.md "Held-out scenes");
#                       bench/stability_heldout_check.py then checks every
#                       converged value against independent estimates
#   stability_remedy    the limit-cycle cells with stall_remedy relax_correction
# Each prints the table, the count of each outcome and the jobs' CPU seconds.
#
#   bench/stability_envelope.sh BIN_DIR OUT_DIR [-j N] [--study NAME]
set -euo pipefail
if [[ $# -lt 2 ]]; then
  echo "usage: $0 BIN_DIR OUT_DIR [-j N] [--study NAME]" >&2
  exit 2
fi
bin="$(cd "$1" && pwd)"; out="$2"; shift 2
jobs=2
name=stability
while [[ $# -gt 0 ]]; do
  case "$1" in
    -j) jobs="$2"; shift ;;
    --study) name="$2"; shift ;;
    *) echo "unknown option $1" >&2; exit 2 ;;
  esac
  shift
done
[[ -x "$bin/gridfree" ]] || { echo "no gridfree in $bin" >&2; exit 2; }
here="$(cd "$(dirname "$0")" && pwd)"
study="$here/../studies/$name.json"
[[ -f "$study" ]] || { echo "no study $study" >&2; exit 2; }
db="$name.sqlite"
[[ "$name" == stability ]] && db=stability.sqlite
mkdir -p "$out"
cd "$out"
# Exit 3 is expected: the study is made of grids that fail.
"$bin/gridfree" run "$study" -j "$jobs" --db "$db" >"$name.log" 2>&1 || [[ $? -eq 3 ]]
sqlite3 "$db" "
  SELECT case_name, convection, 'fwhm' || fwhm_dp, deposition,
         group_concat(printf('%.2g:%s', delta_star_nominal,
                             CASE outcome WHEN 'converged' THEN iterations ELSE outcome END), ' ')
  FROM (SELECT * FROM v_stability WHERE study = '$name' ORDER BY series_id, delta_star DESC)
  GROUP BY series_id ORDER BY series_id;"
echo
sqlite3 "$db" "SELECT outcome, COUNT(*) FROM v_stability WHERE study = '$name' GROUP BY outcome;"
sqlite3 "$db" "SELECT printf('%d distinct jobs, %.1f s of CPU', COUNT(*), SUM(r.cpu_s))
  FROM results r WHERE r.job_id IN (SELECT DISTINCT job_id FROM v_stability WHERE study = '$name');"
if [[ "$name" == stability_envelope ]]; then
  python3 "$here/stability_envelope_chart.py" "$db" stability_envelope.svg "$name"
  echo "chart: $out/stability_envelope.svg"
fi
echo "map: $out/reports/$name/stability_map.svg"
