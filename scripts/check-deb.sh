#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The Debian package as a user meets it (docs/INSTALL.md "Debian package"):
# builds gridfree_<version>_<arch>.deb from a configured, built BUILD_DIR
# (cpack), installs it with apt (which must satisfy its declared Depends),
# runs the demo study from /usr/share/gridfree/studies in a fresh folder,
# checks `man gridfree` and the completion of subcommands, and removes the
# package again (also on failure). Needs root; .ci/run runs it.
#   scripts/check-deb.sh BUILD_DIR
set -euo pipefail
build="$(cd "${1:?usage: check-deb.sh BUILD_DIR}" && pwd)"
export DEBIAN_FRONTEND=noninteractive
status=$(dpkg-query -W -f='${Status}' gridfree 2>/dev/null || true)
if [[ "$status" == "install ok installed" ]]; then
  echo "check-deb: a gridfree package is already installed; remove it first" >&2
  exit 1
fi
(cd "$build" && cpack -G DEB >cpack.log) || { cat "$build/cpack.log"; exit 1; }
deb=$(ls "$build"/gridfree_*_*.deb)
echo "== $(basename "$deb"): $(dpkg-deb -f "$deb" Depends)"
work=$(mktemp -d)
cleanup() {
  apt-get remove -y -qq gridfree >/dev/null 2>&1 || true
  rm -rf "$work"
}
trap cleanup EXIT
apt-get install -y -qq --no-install-recommends "$deb" >"$work/apt.log" 2>&1 || { cat "$work/apt.log"; exit 1; }
cd "$work"
start=$(date +%s)
env -u GRIDFREE_WORKER gridfree run /usr/share/gridfree/studies/quickstart.json >run.log 2>&1 ||
  { tail -20 run.log; echo "check-deb: the demo from the package failed"; exit 1; }
test -s reports/quickstart/report.html
echo "demo from the package: $(($(date +%s) - start)) s, report written"
page=$(MANPAGER=cat man gridfree)  # read whole: grep -q in a pipe would SIGPIPE man under pipefail
grep -q "gridfree run STUDY" <<<"$page" || { echo "check-deb: man gridfree"; exit 1; }
reply=$(bash -c 'source /usr/share/bash-completion/completions/gridfree; COMP_WORDS=(gridfree st); COMP_CWORD=1; _gridfree; echo "${COMPREPLY[*]}"')
[[ "$reply" == "status" ]] || { echo "check-deb: completion of 'gridfree st' gave '$reply'"; exit 1; }
echo "check-deb: ok"
