#!/usr/bin/env bash
# Installs every build, test and demo dependency of sillage with apt (Debian 12).
# Idempotent: does nothing but a quick check when everything is already there.
set -euo pipefail

PACKAGES=(
  build-essential cmake pkg-config
  libgtest-dev libgmock-dev libbenchmark-dev
  libmpfr-dev libgmp-dev libmpfi-dev libboost-dev
  libtbb-dev
  pybind11-dev python3-dev python3-numpy python3-matplotlib python3-pytest
  python3-distributed python3-dask
  python3-venv python3-pip python3-setuptools python3-wheel git
  libcli11-dev libtomlplusplus-dev nlohmann-json3-dev chromium chromium-driver
)

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

echo "setup: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
