#!/usr/bin/env bash
# Installs hullopt's build dependencies from Debian 12 packages (idempotent; run as root).
set -euo pipefail
PKGS=(build-essential cmake pkg-config
      libeigen3-dev libnlopt-cxx-dev libceres-dev libyaml-cpp-dev catch2 libcerf-dev
      libcli11-dev nlohmann-json3-dev libbenchmark-dev libopenmpi-dev openmpi-bin librsvg2-bin
      pybind11-dev python3-dev python3-numpy python3-pytest python3-matplotlib python3-yaml python3-pandas
      clang-14 libclang-rt-14-dev libomp-14-dev lld ninja-build)
missing=()
for p in "${PKGS[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
echo "hullopt dependencies present."
