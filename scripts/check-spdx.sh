#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Lists every tracked source file that lacks an SPDX-License-Identifier line in
# its first three lines; exits 1 if there is one. `--add` inserts the line
# (after a shebang) instead. Source: C and C++ (.c .cc .cpp .h .hpp .cpp.in), shell, Python,
# CMake, Makefiles and LAMMPS inputs; data, documents and OpenFOAM case
# dictionaries are not source (THIRD_PARTY.md says what they are under).
set -euo pipefail
cd "$(dirname "$0")/.."
# Outside a git checkout there is no list of tracked files to check: say so.
# A checkout owned by another user (a CI clone) is read all the same.
git() { command git -c safe.directory="$PWD" "$@"; }
git rev-parse --is-inside-work-tree >/dev/null || { echo "check-spdx: not a git checkout" >&2; exit 2; }
spdx="SPDX-License-Identifier: GPL-3.0-or-later"
mode="${1:-check}"
missing=0
while IFS= read -r f; do
  case "$f" in
    *.c|*.cc|*.cpp|*.h|*.hpp|*.cpp.in) comment="//" ;;
    *.sh|*.py|*.cmake|*/CMakeLists.txt|CMakeLists.txt|Makefile|*.in|.ci/*) comment="#" ;;
    *) continue ;;
  esac
  if head -n 3 "$f" | grep -q "SPDX-License-Identifier:"; then continue; fi
  if [[ "$mode" == "--add" ]]; then
    if head -n 1 "$f" | grep -q '^#!'; then
      sed -i "1a $comment $spdx" "$f"
    else
      sed -i "1i $comment $spdx" "$f"
    fi
  else
    echo "no SPDX line: $f"
    missing=1
  fi
done < <(git ls-files)
exit $missing
