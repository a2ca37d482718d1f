#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Where the worker's bytes go: the bursting-bubble baseline job on one grid
# under valgrind's massif, printed as the heap at its peak by allocation
# site (the function that allocated, with its caller), in bytes per cell.
#
#   bench/memory_account.sh BIN_DIR [NX NY NZ]      (default 30 200 10: Δ* = 1)
#
# BIN_DIR holds gridfree-worker (e.g. build/bin). One thread; Δ* = 1 takes
# about a minute under massif on a quiet machine. The peak RSS of the same
# job without valgrind is printed for comparison (RSS also counts the
# executable, its libraries and freed-but-kept heap pages).
set -euo pipefail
if [[ $# -lt 1 ]]; then
  echo "usage: $0 BIN_DIR [NX NY NZ]" >&2
  exit 2
fi
bin="$1"
nx="${2:-30}" ny="${3:-200}" nz="${4:-10}"
worker="$bin/gridfree-worker"
[[ -x "$worker" ]] || { echo "no gridfree-worker in $bin" >&2; exit 2; }
command -v valgrind >/dev/null || { echo "valgrind is not installed" >&2; exit 2; }
here="$(cd "$(dirname "$0")" && pwd)"
# shellcheck source=bench/bubble_job.sh
source "$here/bubble_job.sh"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
write_bubble_job "$work/job.json" "$nx" "$ny" "$nz" '{"kind": "diffusion", "fwhm_dp": 6}'
machine_line
export OMP_WAIT_POLICY=passive
"$worker" solve "$work/job.json" -o "$work/plain.json" -q --threads 1
valgrind --tool=massif --depth=2 --threshold=0.1 --massif-out-file="$work/massif.out" \
  "$worker" solve "$work/job.json" -o "$work/massif.json" -q --threads 1 2>/dev/null
python3 - "$work/massif.out" "$work/plain.json" "$nx" "$ny" "$nz" <<'PY'
import json, re, sys
cells = int(sys.argv[3]) * int(sys.argv[4]) * int(sys.argv[5])
snapshots, cur = [], None
for line in open(sys.argv[1]):
    line = line.rstrip("\n")
    if line.startswith("snapshot="):
        cur = {"heap": 0, "tree": []}
        snapshots.append(cur)
    elif line.startswith("mem_heap_B="):
        cur["heap"] = int(line.split("=")[1])
    elif cur is not None and re.match(r"^ *n\d+: ", line):
        cur["tree"].append(line)
peak = max(snapshots, key=lambda s: s["heap"])
def short(name):
    name = re.sub(r"^0x[0-9A-F]+: ", "", name)
    name = re.sub(r" \(in .*\)$", "", name).replace("gridfree::", "").replace("(anonymous namespace)::", "")
    return re.sub(r"\(.*", "", name)
rows, parent = {}, None
for line in peak["tree"]:
    m = re.match(r"^( *)n(\d+): (\d+) (.*)$", line)
    indent, children, size, name = len(m.group(1)), int(m.group(2)), int(m.group(3)), m.group(4)
    if indent == 1:
        parent = short(name)
        if children == 0:  # a leaf: no caller below it
            rows[parent] = rows.get(parent, 0) + size
    elif indent == 2 and parent is not None:
        key = f"{parent} <- {short(name)}"
        rows[key] = rows.get(key, 0) + size
r = json.load(open(sys.argv[2]))
print(f"cells {cells}; heap at its peak {peak['heap'] / cells:.0f} B/cell; "
      f"peak RSS without valgrind {r['memory']['peak_rss_mb'] * 2**20 / cells:.0f} B/cell")
for key, size in sorted(rows.items(), key=lambda kv: -kv[1]):
    if size / cells >= 2:
        print(f"{size / cells:8.1f} B/cell  {key}")
PY
