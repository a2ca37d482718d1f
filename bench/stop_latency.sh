#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# How promptly `gridfree run` stops, at random moments of a large study, and
# what a stop costs: SIGINT at a random time after each (re)start, the time
# from the signal to the process's exit, the exit code, temporary files left
# in the report and run folders; then a last run to the end, and how often
# each job was solved (the instant worker logs every solve).
#
#   bench/stop_latency.sh BIN_DIR [K] [STOPS] [MAX_DELAY_S]
#
# K: the study of bench/scale_study.py (108·K jobs, 6·K series; default 20).
# STOPS: how many SIGINTs (default 12), each after a uniform random delay in
# [0.2, MAX_DELAY_S] s (default 6) from the start of that run, so stops land
# in claims, result transactions, series extrapolations and report writes
# (chart export included, unless BENCH_EXPORT=0). BENCH_J: jobs at once
# (default 2). BENCH_SEED: the delays' seed (default 1).
#
# Prints one line per stop (delay, seconds to exit, exit code, jobs done so
# far) and a summary: median and largest stop time, temporary files left,
# solves per job (a stop may cost the jobs in flight, at most BENCH_J each).
set -euo pipefail
if [[ $# -lt 1 ]]; then
  echo "usage: $0 BIN_DIR [K] [STOPS] [MAX_DELAY_S]" >&2
  exit 2
fi
bin=$(cd "$1" && pwd)
k=${2:-20}
stops=${3:-12}
max_delay=${4:-6}
here=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
jobs_at_once=${BENCH_J:-2}
path_for_run=$PATH
if [[ ${BENCH_EXPORT:-1} == 0 ]]; then mkdir -p "$work/no_converter"; path_for_run="$work/no_converter"; fi
worker="$work/instant_worker"
cc -O2 -o "$worker" "$here/bench/instant_worker.c" -lm
python3 "$here/bench/scale_study.py" "$here/studies/quickstart.json" "$k" > "$work/study.json"
jobs=$((108 * k))
export INSTANT_WORKER_LOG="$work/solves.log"
RANDOM=${BENCH_SEED:-1}

run_study() {  # starts `gridfree run` in the background; its pid in $run_pid
  (cd "$work" && PATH="$path_for_run" GRIDFREE_WORKER="$worker" \
     exec "$bin/gridfree" run study.json --db "$work/db.sqlite" -j "$jobs_at_once" >> "$work/run.log" 2>&1) &
  run_pid=$!
}

done_jobs() {
  sqlite3 "$work/db.sqlite" "SELECT count(*) FROM jobs WHERE status = 'done'" 2>/dev/null || echo 0
}

temporary_files() {  # files a writer left half-done: report temporaries and *.tmp
  find "$work" \( -name '.*.tmp-*' -o -name '*.tmp' \) -type f | wc -l
}

printf '%6s %9s %9s %5s %10s %6s\n' stop delay_s exit_s rc jobs_done tmp
times=()
for ((i = 1; i <= stops; ++i)); do
  run_study
  delay=$(awk -v r="$RANDOM" -v m="$max_delay" 'BEGIN { printf("%.2f", 0.2 + (m - 0.2) * r / 32767) }')
  sleep "$delay"
  signalled=$(date +%s.%N)
  kill -INT "$run_pid" 2>/dev/null || true
  rc=0
  wait "$run_pid" || rc=$?
  exited=$(date +%s.%N)
  took=$(awk -v a="$signalled" -v b="$exited" 'BEGIN { printf("%.3f", b - a) }')
  times+=("$took")
  printf '%6d %9s %9s %5d %10s %6s\n' "$i" "$delay" "$took" "$rc" "$(done_jobs)" "$(temporary_files)"
  if [[ $rc -ne 130 && $rc -ne 0 ]]; then
    echo "run exited $rc: see below" >&2
    tail -5 "$work/run.log" >&2
    exit 1
  fi
done

run_study
wait "$run_pid" || { echo "the last run failed: see below" >&2; tail -5 "$work/run.log" >&2; exit 1; }
solves=$(wc -l < "$work/solves.log")
distinct=$(sort -u "$work/solves.log" | wc -l)
printf '%s\n' "${times[@]}" | sort -n | awk -v n="${#times[@]}" -v jobs="$jobs" -v done="$(done_jobs)" \
    -v solves="$solves" -v distinct="$distinct" -v tmp="$(temporary_files)" '
  { t[NR] = $1 }
  END {
    median = (n % 2) ? t[(n + 1) / 2] : (t[n / 2] + t[n / 2 + 1]) / 2
    printf("stops %d: median %.3f s, largest %.3f s to exit\n", n, median, t[n])
    printf("jobs %d, done %d, solves %d (distinct jobs solved %d, solved again %d), temporary files left %d\n",
           jobs, done, solves, distinct, solves - distinct, tmp)
  }'
