#!/usr/bin/env bash
# Installs the Debian packages gridfree needs to build, test and report:
#   scripts/install-deps.sh        build and run
#   scripts/install-deps.sh test   also what the tests use
# Idempotent: only missing packages are installed (needs root for that).
set -euo pipefail

packages=(
  g++ make cmake git pkg-config
  libeigen3-dev nlohmann-json3-dev libsqlite3-dev sqlite3 libspdlog-dev
  libcli11-dev libgtest-dev libvalijson-dev libfftw3-dev
)
# `install-deps.sh test` adds what only the tests need: headless Chromium
# renders the HTML report once.
if [[ "${1:-}" == "test" ]]; then
  packages+=(chromium)
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
