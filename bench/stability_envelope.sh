#!/usr/bin/env bash
# The solver's robustness envelope (docs/SOLVER.md "Robustness envelope"):
# runs studies/stability.json (120 series, 540 distinct jobs on six grids
# Δ* 3.3 → 0.7; about 100 s of CPU, 9–16 min of wall time on 2 shared
# cores) into OUT_DIR/stability.sqlite and prints the outcome of every grid
# per series from the view v_stability ("3.3:45" = converged in 45 outer
# iterations; else the outcome word), then the count of each outcome. The
# chart is the report's stability map, OUT_DIR/reports/stability/
# stability_map.svg (docs/figures/stability_map.svg is a copy).
#
#   bench/stability_envelope.sh BIN_DIR OUT_DIR [-j N]
set -euo pipefail
if [[ $# -lt 2 ]]; then
  echo "usage: $0 BIN_DIR OUT_DIR [-j N]" >&2
  exit 2
fi
bin="$(cd "$1" && pwd)"; out="$2"; shift 2
jobs=2
while [[ $# -gt 0 ]]; do
  case "$1" in
    -j) jobs="$2"; shift ;;
    *) echo "unknown option $1" >&2; exit 2 ;;
  esac
  shift
done
[[ -x "$bin/gridfree" ]] || { echo "no gridfree in $bin" >&2; exit 2; }
study="$(cd "$(dirname "$0")/.." && pwd)/studies/stability.json"
mkdir -p "$out"
cd "$out"
# Exit 3 is expected: the study is made of grids that fail.
"$bin/gridfree" run "$study" -j "$jobs" --db stability.sqlite >run.log 2>&1 || [[ $? -eq 3 ]]
sqlite3 stability.sqlite "
  SELECT case_name, convection, 'fwhm' || fwhm_dp, deposition,
         group_concat(printf('%.2g:%s', delta_star_nominal,
                             CASE outcome WHEN 'converged' THEN iterations ELSE outcome END), ' ')
  FROM (SELECT * FROM v_stability WHERE study = 'stability' ORDER BY series_id, delta_star DESC)
  GROUP BY series_id ORDER BY series_id;"
echo
sqlite3 stability.sqlite "SELECT outcome, COUNT(*) FROM v_stability WHERE study = 'stability' GROUP BY outcome;"
echo "chart: $out/reports/stability/stability_map.svg"
