#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Installs the Debian packages gridfree needs to build, test and report:
#   scripts/install-deps.sh        build and run (what `make demo` needs)
#   scripts/install-deps.sh test   also what the tests use (`make test`)
#   scripts/install-deps.sh fuzz   also clang for the fuzz targets
#   scripts/install-deps.sh deb    also what CPack needs to build the Debian package (`make deb`)
# Idempotent: only missing packages are installed (needs root for that).
set -euo pipefail

packages=(
  g++ make cmake git pkg-config
  libeigen3-dev nlohmann-json3-dev libsqlite3-dev sqlite3 libspdlog-dev
  libcli11-dev libfftw3-dev
  librsvg2-bin
)
# librsvg2-bin: rsvg-convert writes the PDF/PNG copies of the report's charts.
# `install-deps.sh test` adds what only the tests need: GoogleTest, headless Chromium
# renders and prints the HTML report, pdftotext (poppler-utils) reads the
# PDF; a single-node Slurm (munge, slurmctld, slurmd, started by
# tests/integration/slurm/slurm_cluster.sh) runs the Slurm executor tests;
# openfoam (Debian's OpenFOAM v1912, about 40 s and 500 MB) runs the external
# solver tests (tests/integration/external), which fail without it; man-db
# and lmod render the installed man pages and load the module file
# (tests/install/), dpkg-dev and file let CPack compute the Debian
# package's Depends (scripts/check-deb.sh).
if [[ "${1:-}" == "test" ]]; then
  packages+=(libgtest-dev chromium poppler-utils munge slurmctld slurmd slurm-client openfoam
             man-db lmod dpkg-dev file)
fi
# `install-deps.sh deb`: dpkg-shlibdeps (dpkg-dev) and file compute the
# package's Depends (cmake/Packaging.cmake).
if [[ "${1:-}" == "deb" ]]; then
  packages+=(dpkg-dev file)
fi
# `install-deps.sh fuzz`: clang with libFuzzer and OpenMP for `make fuzz`.
if [[ "${1:-}" == "fuzz" ]]; then
  packages+=(clang libclang-rt-14-dev libomp-dev)
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [[ ${#missing[@]} -eq 0 ]]; then
  exit 0
fi
echo "Installing: ${missing[*]}"
SUDO=""
if [[ $(id -u) -ne 0 ]]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
