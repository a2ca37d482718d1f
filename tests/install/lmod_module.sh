#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The installed Lmod module file as a cluster user loads it: install the
# build into a fresh prefix, `module use <prefix>/share/modulefiles`,
# `module load gridfree`, then gridfree and its man page come from the
# prefix. Exits 77 (CTest: skipped) with a message when Lmod is not
# installed (Debian package lmod; scripts/install-deps.sh test installs it).
#   lmod_module.sh BUILD_DIR WORK_DIR
set -euo pipefail
build="$1"
work="$2"
lmod_init=""
for f in /usr/share/lmod/lmod/init/bash "${LMOD_PKG:-/nonexistent}/init/bash"; do
  [[ -r "$f" ]] && { lmod_init="$f"; break; }
done
if [[ -z "$lmod_init" ]]; then
  echo "SKIPPED: Lmod is not installed (apt-get install lmod)"
  exit 77
fi
rm -rf "$work"
mkdir -p "$work"
prefix="$work/prefix"
cmake --install "$build" --prefix "$prefix" >"$work/install.log"
version=$(sed -n 's/^project(gridfree VERSION \([0-9.]*\).*/\1/p' "$(dirname "$0")/../../CMakeLists.txt")

# A login shell of a user who has neither gridfree on PATH nor modules loaded.
out=$(env -i HOME="$work" PATH=/usr/bin:/bin bash --noprofile --norc -c '
  set -e
  source "$1"
  module use "$2/share/modulefiles"
  module load gridfree
  module list 2>&1
  command -v gridfree
  gridfree --version
  echo "GRIDFREE_ROOT=$GRIDFREE_ROOT"
  MANPAGER=cat man -w gridfree
  module unload gridfree
  command -v gridfree || echo "unloaded"
' _ "$lmod_init" "$prefix" 2>&1) || { echo "$out"; echo "FAIL: module load gridfree"; exit 1; }
echo "$out"
grep -q "gridfree/$version" <<<"$out" || { echo "FAIL: module list lacks gridfree/$version"; exit 1; }
grep -qx "$prefix/bin/gridfree" <<<"$out" || { echo "FAIL: gridfree is not the prefix's"; exit 1; }
grep -q "^gridfree $version (commit " <<<"$out" || { echo "FAIL: gridfree --version"; exit 1; }
grep -qx "GRIDFREE_ROOT=$prefix" <<<"$out" || { echo "FAIL: GRIDFREE_ROOT"; exit 1; }
grep -qx "$prefix/share/man/man1/gridfree.1" <<<"$out" || { echo "FAIL: man finds the prefix's page"; exit 1; }
grep -qx "unloaded" <<<"$out" || { echo "FAIL: unload left gridfree on PATH"; exit 1; }
echo "module load gridfree: ok"
