#!/usr/bin/env bash
# Installs aokit's Debian 12 dependencies. Idempotent: skips apt when all are present.
set -euo pipefail
packages=(
  build-essential cmake pkg-config
  libvtk9-dev libglm-dev libosmesa6-dev libopenmesh-dev libembree-dev
  libgtest-dev googletest nlohmann-json3-dev libcli11-dev
  zlib1g-dev libx11-dev xvfb xauth
  python3-vtk9 python3-dev python3-numpy python3-pytest python3-vedo
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages present"
  exit 0
fi
echo "setup: installing ${missing[*]}"
SUDO=""
[ "$(id -u)" -ne 0 ] && SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "setup: done"
