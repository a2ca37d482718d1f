#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Installs the build into a fresh prefix and uses it as a user would, from
# another directory, with no GRIDFREE_WORKER and the build tree nowhere on
# PATH: the layout (cmake/Install.cmake), a study run from the installed
# studies (a three-grid cut of quickstart.json, so that the test takes
# seconds; the full demo is measured in docs/INSTALL.md), an external study
# whose template resolves inside the prefix, the man pages as `man` renders
# them, and the bash completion of commands, options and choices.
#   install_prefix.sh BUILD_DIR WORK_DIR
set -euo pipefail
build="$1"
work="$2"
rm -rf "$work"
mkdir -p "$work"
prefix="$work/prefix"
fail() { echo "FAIL: $*" >&2; exit 1; }

cmake --install "$build" --prefix "$prefix" >"$work/install.log"
version=$(sed -n 's/^project(gridfree VERSION \([0-9.]*\).*/\1/p' "$(dirname "$0")/../../CMakeLists.txt")
for f in bin/gridfree bin/gridfree-worker \
         share/gridfree/studies/quickstart.json share/gridfree/studies/external/cavity/system/controlDict \
         share/doc/gridfree/README.md share/doc/gridfree/LICENSE share/doc/gridfree/THIRD_PARTY.md \
         share/doc/gridfree/CHANGELOG.md share/doc/gridfree/CITATION.cff share/doc/gridfree/docs/INTERFACE.md \
         share/man/man1/gridfree.1 share/man/man1/gridfree-worker.1 \
         share/bash-completion/completions/gridfree share/bash-completion/completions/gridfree-worker \
         "share/modulefiles/gridfree/$version.lua"; do
  [[ -e "$prefix/$f" ]] || fail "not installed: $f"
done
echo "installed layout: ok"

# A user's shell: the prefix's bin on PATH, nothing of the build.
user_env=(env -u GRIDFREE_WORKER "PATH=$prefix/bin:/usr/bin:/bin")
elsewhere="$work/elsewhere"
mkdir -p "$elsewhere"
cd "$elsewhere"
# (Output is read whole before grep -q: with pipefail, grep -q leaving a pipe
# early would fail the writer with SIGPIPE.)
out=$("${user_env[@]}" gridfree --version)
grep -q "^gridfree $version (commit " <<<"$out" || fail "gridfree --version: $out"

studies="$prefix/share/gridfree/studies"
python3 - "$studies/quickstart.json" >install_demo.json <<'PY'
import json, sys
doc = json.load(open(sys.argv[1]))
doc["name"] = "install_demo"
doc["factors"]["convection"] = ["superbee"]
doc["grids"] = {"delta_star": [4.0, 3.333, 2.5]}
json.dump(doc, sys.stdout, indent=2)
PY
"${user_env[@]}" gridfree plan "$studies/quickstart.json" >plan.txt || fail "plan of the installed quickstart.json"
"${user_env[@]}" gridfree run install_demo.json -j 2 >run.log 2>&1 || { cat run.log; fail "run exited $?"; }
[[ -s reports/install_demo/report.html && -s reports/install_demo/report.md ]] || fail "no report in $elsewhere/reports"
grep -q "install_demo" reports/install_demo/report.md || fail "report does not name the study"
# Relative paths of a study (an external template) resolve against the
# installed study file, not the working directory.
"${user_env[@]}" gridfree validate "$studies/external_cavity.json" >validate.log 2>&1 ||
  { cat validate.log; fail "validate of the installed external_cavity.json"; }
echo "run from another directory: ok"

# Man pages: rendered by man without troff warnings, found through MANPATH.
for program in gridfree gridfree-worker; do
  page=$(MANPAGER=cat MANWIDTH=100 man --warnings -l "$prefix/share/man/man1/$program.1" 2>"$work/man-$program.err")
  [[ ! -s "$work/man-$program.err" ]] || { cat "$work/man-$program.err"; fail "man warnings for $program.1"; }
  for section in NAME SYNOPSIS OPTIONS COMMANDS "EXIT STATUS"; do
    grep -q "^$section" <<<"$page" || fail "$program.1 has no $section section"
  done
done
page=$(MANPAGER=cat MANWIDTH=100 man -l "$prefix/share/man/man1/gridfree.1")
grep -q -- "--memory-budget" <<<"$page" || fail "gridfree.1 lacks run's --memory-budget"
grep -q "gridfree run STUDY" <<<"$page" || fail "gridfree.1 lacks the run command"
page=$(MANPATH="$prefix/share/man" MANPAGER=cat man gridfree-worker)
grep -q -- "--threads" <<<"$page" || fail "man gridfree-worker via MANPATH"
echo "man pages: ok"

# Completion, as bash calls it: COMP_WORDS / COMP_CWORD, then COMPREPLY.
complete_words() {  # program word... (the last word is the one completed)
  bash -c 'source "$1"; shift; COMP_WORDS=("$@"); COMP_CWORD=$(($# - 1)); _${1//-/_}; printf "%s\n" "${COMPREPLY[@]}"' \
    _ "$prefix/share/bash-completion/completions/$1" "$@"
}
words=$(complete_words gridfree "")
grep -qx run <<<"$words" || fail "completion: gridfree <TAB> lacks run"
grep -qx status <<<"$words" || fail "completion: gridfree <TAB> lacks status"
[[ "$(complete_words gridfree st)" == $'status' ]] || fail "completion: gridfree st<TAB> is not status"
words=$(complete_words gridfree run --mem)
grep -qx -- --memory-budget <<<"$words" || fail "completion: run --mem<TAB>"
[[ "$(complete_words gridfree run --executor "" | sort | tr '\n' ' ')" == "local slurm " ]] ||
  fail "completion: run --executor <TAB> is not 'local slurm'"
words=$(complete_words gridfree-worker "")
grep -qx solve <<<"$words" || fail "completion: gridfree-worker <TAB> lacks solve"
echo "bash completion: ok"
