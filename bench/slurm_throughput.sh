#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Throughput and added latency of the Slurm executor: the paper's 216-job
# study (studies/bursting_bubble_paper.json) solved by the fake worker
# (tests/fixtures/fake_worker.sh, every job converges at once, or after
# SLEEP seconds) through a throwaway one-node Slurm
# (tests/integration/slurm/slurm_cluster.sh), -j SLOTS tasks at a time.
#
#   bench/slurm_throughput.sh BIN_DIR [SLOTS] [SLEEP] [EXTRA RUN FLAGS...]   (root; Slurm installed)
#
# --mem/--time are fixed small: the cost model would ask for more memory for
# the finest grids than the test node has (sbatch refuses those jobs).
# Prints: wall time, jobs per minute, and the median "added latency" per job
# = the time from the worker's end (mtime of <run folder>/exit_code) to the
# result's row in the database (results.recorded_at).
set -euo pipefail
bin=$(cd "${1:?usage: $0 BIN_DIR [SLOTS] [SLEEP]}" && pwd)
slots=${2:-8}
sleep_s=${3:-}
shift $(($# < 3 ? $# : 3))
src=$(cd "$(dirname "$0")/.." && pwd)
scratch=$(mktemp -d)
cluster="$scratch/cluster"
trap '"$src/tests/integration/slurm/slurm_cluster.sh" stop "$cluster"; rm -rf "$scratch"' EXIT
eval "$("$src/tests/integration/slurm/slurm_cluster.sh" start "$cluster")"
cd "$scratch"
export GRIDFREE_WORKER="$src/tests/fixtures/fake_worker.sh" GRIDFREE_FAKE_MODE=ok
[ -z "$sleep_s" ] || export GRIDFREE_FAKE_SLEEP="$sleep_s"
start=$(date +%s.%N)
"$bin/gridfree" run "$src/studies/bursting_bubble_paper.json" --db b.sqlite --executor slurm -j "$slots" \
  --mem 64 --time 10 "$@" \
  --out report >/dev/null 2>run.log || { grep -v '^\[info\]' run.log | tail -5; exit 1; }
end=$(date +%s.%N)
[ -z "${GRIDFREE_BENCH_LOG:-}" ] || cp run.log "$GRIDFREE_BENCH_LOG"
jobs=$(sqlite3 b.sqlite "SELECT COUNT(*) FROM results WHERE status = 'converged'")
submissions=$(ls b.sqlite.runs/slurm/*.sbatch | wc -l)
# Added latency: recorded_at (UTC, ms) minus the exit_code file's mtime.
# The run folder is the result file's (sharded: <db>.runs/<hh>/<job_hash>/).
sqlite3 -separator ' ' b.sqlite "SELECT (julianday(r.recorded_at) - 2440587.5) * 86400.0, j.result_path
  FROM results r JOIN jobs j ON j.id = r.job_id" |
  while read -r recorded result; do
    echo "$recorded $(stat -c %.9Y "$(dirname "$result")/exit_code")"
  done | awk '{ print $1 - $2 }' | sort -g > latency.txt
median=$(awk '{ a[NR] = $1 } END { print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2 }' latency.txt)
p90=$(awk '{ a[NR] = $1 } END { print a[int(NR * 0.9)] }' latency.txt)
awk -v s="$start" -v e="$end" -v n="$jobs" -v j="$slots" -v nsub="$submissions" -v m="$median" -v p="$p90" 'BEGIN {
  w = e - s
  printf "%d jobs converged, -j %d, %d sbatch submission(s): wall %.1f s, %.0f jobs/min; added latency median %.3f s, p90 %.3f s\n",
         n, j, nsub, w, 60 * n / w, m, p }'
