#!/usr/bin/env bash
# Installs the Debian packages gridfree needs to build, test and report.
# Idempotent: only missing packages are installed (needs root for that).
set -euo pipefail

packages=(
  g++ make cmake git pkg-config
  libeigen3-dev nlohmann-json3-dev libsqlite3-dev sqlite3 libspdlog-dev
  libcli11-dev libgtest-dev libvalijson-dev
)
# Extra packages for the HTML rendering test: GRIDFREE_DEPS_EXTRA="chromium".
if [[ -n "${GRIDFREE_DEPS_EXTRA:-}" ]]; then
  read -r -a extra <<<"${GRIDFREE_DEPS_EXTRA}"
  packages+=("${extra[@]}")
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
