#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The orchestrator's own cost per job as studies grow: `gridfree run` of a
# study of K cases × 6 drag laws × the paper's 18 grids (108·K jobs) with a
# worker that answers at once (through GRIDFREE_WORKER), so what is
# measured is the orchestrator: claims, records, progress, series
# extrapolations and reports.
#
#   bench/orchestrator_scale.sh BIN_DIR [K ...]     (default K: 1 10)
#
# BENCH_WORKER=instant (default): bench/instant_worker.c, compiled here with
# cc, one small process per job; BENCH_WORKER=shell: tests/fixtures/
# fake_worker.sh (a few processes per job, about 0.2 s of a slot each, so
# near 10 jobs/s at -j 2 at most). BENCH_J: jobs at once (default 2).
# BENCH_EXPORT=0: gridfree runs with a PATH without rsvg-convert, so the
# reports are written without their PDF/PNG copies (at 600 series those take
# rsvg-convert minutes per report write, in child processes not counted).
# BENCH_EXECUTOR=slurm: through a throwaway one-node Slurm
# (tests/integration/slurm/slurm_cluster.sh; root, Slurm installed), `run
# --executor slurm --mem 64 --time 10` (fixed small: the cost model would ask
# the finest grids for more memory than the node has); BENCH_J then counts
# array tasks at once (default 8, the node's CPUs). BENCH_EXECUTOR=slurm-stub:
# the same flags, but sbatch/squeue/scancel/sacct are bench/slurm_stub.py,
# which runs each array's tasks on this machine at once (-j of them at a
# time, no controller): the executor's own cost, apart from Slurm's launch
# rate (about 8 tiny tasks a second on a one-node Slurm here).
#
# Prints per size: jobs, wall s, jobs/s, the orchestrator's own CPU (user +
# system of the `gridfree` process alone, read from /proc every 0.1 s, so
# the fake workers' CPU is not counted) and that CPU per job in ms.
# Run it beside nothing else (print `uptime` with the figures).
set -euo pipefail
if [[ $# -lt 1 ]]; then
  echo "usage: $0 BIN_DIR [K ...]" >&2
  exit 2
fi
bin=$(cd "$1" && pwd); shift
sizes=("$@")
[[ ${#sizes[@]} -gt 0 ]] || sizes=(1 10)
here=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
tick=$(getconf CLK_TCK)
executor_flags=()
case ${BENCH_EXECUTOR:-local} in
  local) jobs_at_once=${BENCH_J:-2} ;;
  slurm) jobs_at_once=${BENCH_J:-8}
         trap '"$here/tests/integration/slurm/slurm_cluster.sh" stop "$work/cluster"; rm -rf "$work"' EXIT
         eval "$("$here/tests/integration/slurm/slurm_cluster.sh" start "$work/cluster")"
         executor_flags=(--executor slurm --mem 64 --time 10) ;;
  slurm-stub) jobs_at_once=${BENCH_J:-8}
         mkdir -p "$work/stub_bin"
         for tool in sbatch squeue scancel sacct; do  # python3 by its path: BENCH_EXPORT=0 narrows PATH
           printf '#!/bin/sh\nexec %q %q --as %s "$@"\n' "$(python3 -c "import sys; print(sys.executable)")" "$here/bench/slurm_stub.py" "$tool" \
             > "$work/stub_bin/$tool"
           chmod +x "$work/stub_bin/$tool"
         done
         export SLURM_STUB_DIR="$work/stub_state" PATH="$work/stub_bin:$PATH"
         executor_flags=(--executor slurm --mem 64 --time 10) ;;
  *) echo "BENCH_EXECUTOR: local, slurm or slurm-stub, not '${BENCH_EXECUTOR}'" >&2; exit 2 ;;
esac
path_for_run=$PATH
if [[ ${BENCH_EXPORT:-1} == 0 ]]; then  # the PATH's tools gridfree uses, without rsvg-convert
  # (mv: the array script's, whose environment under Slurm is gridfree's)
  mkdir -p "$work/no_converter"
  for tool in sbatch squeue scancel sacct scontrol sinfo mv; do
    ! command -v "$tool" >/dev/null || ln -s "$(command -v "$tool")" "$work/no_converter/$tool"
  done
  path_for_run="$work/no_converter"
fi
case ${BENCH_WORKER:-instant} in
  instant) worker="$work/instant_worker"
           cc -O2 -o "$worker" "$here/bench/instant_worker.c" -lm ;;
  shell) worker="$here/tests/fixtures/fake_worker.sh" ;;
  *) echo "BENCH_WORKER: instant or shell, not '${BENCH_WORKER}'" >&2; exit 2 ;;
esac

study_of() {  # K → a study document on stdout
  python3 "$here/bench/scale_study.py" "$here/studies/quickstart.json" "$1"
}

printf '%8s %8s %8s %10s %12s\n' jobs wall_s jobs/s orch_cpu_s cpu_ms/job
for k in "${sizes[@]}"; do
  dir="$work/k$k"
  mkdir -p "$dir"
  study_of "$k" > "$dir/study.json"
  jobs=$((108 * k))
  start=$(date +%s.%N)
  (cd "$dir" && PATH="$path_for_run" GRIDFREE_WORKER="$worker" \
     "$bin/gridfree" run study.json --db "$dir/db.sqlite" -j "$jobs_at_once" \
       "${executor_flags[@]}" > "$dir/run.log" 2>&1) &
  runner=$!
  pid=""
  cpu=0
  while kill -0 "$runner" 2>/dev/null; do
    [[ -n "$pid" ]] || pid=$(pgrep -P "$runner" -x gridfree || true)
    if [[ -n "$pid" && -r /proc/$pid/stat ]]; then
      t=$(awk '{print $14 + $15}' "/proc/$pid/stat" 2>/dev/null || true)
      [[ -z "$t" ]] || cpu=$t
    fi
    sleep 0.1
  done
  wait "$runner" || { echo "run of $jobs jobs failed: see below" >&2; tail -5 "$dir/run.log" >&2; exit 1; }
  end=$(date +%s.%N)
  awk -v j="$jobs" -v s="$start" -v e="$end" -v c="$cpu" -v t="$tick" 'BEGIN {
    w = e - s; cs = c / t;
    printf("%8d %8.1f %8.1f %10.1f %12.2f\n", j, w, j / w, cs, 1000 * cs / j) }'
done
