#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""A stand-in for sbatch, squeue, scancel and sacct that runs array tasks
on this machine at once, without a controller: the Slurm executor's own
cost measured apart from Slurm's (bench/orchestrator_scale.sh,
BENCH_EXECUTOR=slurm-stub). Called through symlinks named after the
command (or as `slurm_stub.py --as NAME ARGS...`); the state lives in
$SLURM_STUB_DIR.

  sbatch --parsable ... --array=0-K%N ... SCRIPT
      prints a new id and starts, detached, a runner that runs the script
      once per task (SLURM_ARRAY_TASK_ID=i, stdout/stderr to /dev/null),
      N at a time, in index order; the runner keeps <dir>/queue/<id> as
      squeue would print the array: one line per running task, one line
      for the waiting ones ("<id>_[a-K%N]|PENDING|JobArrayTaskLimit|0:00").
  squeue ... -o FORMAT
      prints those lines (with -r the waiting ones one per line); only the
      format "%i|%T|%r|%M" is known, any other prints nothing.
  scancel, sacct
      print nothing (a bench run cancels nothing; exit_code files decide).

Not a Slurm: no node, no limits, no accounting, no cancelling.
"""
import os
import fcntl
import subprocess
import sys


def state_dir():
    d = os.environ.get("SLURM_STUB_DIR")
    if not d:
        sys.exit("slurm_stub: SLURM_STUB_DIR is not set")
    os.makedirs(os.path.join(d, "queue"), exist_ok=True)
    return d


def write_atomic(path, text):
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, path)


def sbatch(args):
    d = state_dir()
    last, throttle, script = 0, 1, args[-1]
    for a in args:
        if a.startswith("--array=0-"):
            spec = a[len("--array=0-"):]
            last = int(spec.split("%")[0])
            throttle = int(spec.split("%")[1]) if "%" in spec else last + 1
    counter = os.path.join(d, "next_id")
    lock = os.open(counter + ".lock", os.O_CREAT | os.O_RDWR)
    fcntl.flock(lock, fcntl.LOCK_EX)
    try:
        job = int(open(counter).read()) if os.path.exists(counter) else 1
        write_atomic(counter, str(job + 1))
    finally:
        os.close(lock)
    queue = os.path.join(d, "queue", str(job))
    write_atomic(queue, f"{job}_[0-{last}%{throttle}]|PENDING|JobArrayTaskLimit|0:00\n")
    subprocess.Popen([sys.executable, os.path.abspath(__file__), "--run", str(job), str(last), str(throttle), script, queue],
                     stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                     start_new_session=True)
    print(job)


def run_array(job, last, throttle, script, queue):
    running = {}  # pid -> index
    nxt = 0

    def publish():
        lines = [f"{job}_{i}|RUNNING|None|0:00\n" for i in sorted(running.values())]
        if nxt <= last:
            lines.insert(0, f"{job}_[{nxt}-{last}%{throttle}]|PENDING|JobArrayTaskLimit|0:00\n")
        write_atomic(queue, "".join(lines))

    devnull = os.open(os.devnull, os.O_RDWR)
    actions = [(os.POSIX_SPAWN_DUP2, devnull, 0), (os.POSIX_SPAWN_DUP2, devnull, 1), (os.POSIX_SPAWN_DUP2, devnull, 2)]
    env = dict(os.environ, SLURM_ARRAY_JOB_ID=str(job))
    while nxt <= last or running:
        while nxt <= last and len(running) < throttle:
            task_env = dict(env, SLURM_ARRAY_TASK_ID=str(nxt), SLURM_JOB_ID=f"{job}_{nxt}")
            running[os.posix_spawn("/bin/sh", ["/bin/sh", script], task_env, file_actions=actions)] = nxt
            nxt += 1
        publish()
        pid, _ = os.wait()  # blocks until a task ends
        running.pop(pid, None)
        while running:
            pid, _ = os.waitpid(-1, os.WNOHANG)
            if pid == 0:
                break
            running.pop(pid, None)
        publish()
    os.remove(queue)


def squeue(args):
    d = state_dir()
    if "%i|%T|%r|%M" not in args:
        return
    expand = "-r" in args
    out = []
    qdir = os.path.join(d, "queue")
    for name in os.listdir(qdir):
        if name.endswith(".tmp"):
            continue
        try:
            text = open(os.path.join(qdir, name)).read()
        except FileNotFoundError:
            continue
        for line in text.splitlines():
            ident = line.split("|", 1)[0]
            if expand and "_[" in ident:
                job, rng = ident[:-1].split("_[")
                first, last = rng.split("%")[0].split("-")
                rest = line[len(ident):]
                out.extend(f"{job}_{i}{rest}" for i in range(int(first), int(last) + 1))
            else:
                out.append(line)
    sys.stdout.write("".join(line + "\n" for line in out))


def main():
    if len(sys.argv) > 1 and sys.argv[1] == "--run":
        job, last, throttle, script, queue = sys.argv[2:7]
        run_array(int(job), int(last), int(throttle), script, queue)
        return
    args = sys.argv[1:]
    name = os.path.basename(sys.argv[0])
    if len(args) > 1 and args[0] == "--as":
        name, args = args[1], args[2:]
    if name == "sbatch":
        sbatch(args)
    elif name == "squeue":
        squeue(args)
    elif name in ("scancel", "sacct"):
        pass
    else:
        sys.exit(f"slurm_stub: called as '{name}': sbatch, squeue, scancel or sacct")


if __name__ == "__main__":
    main()
