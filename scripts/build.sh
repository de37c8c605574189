#!/usr/bin/env bash
# Installs dependencies, fetches the packaged meshes and builds aokit into build/.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/setup.sh"
bash "$root/models/fetch-meshes.sh" "$root/models/packaged"
# AOKIT_BUILD_PARAVIEW=ON (the test command sets it): the ParaView plugin too.
extra=()
if [ -n "${AOKIT_BUILD_PARAVIEW:-}" ]; then
  extra+=("-DAOKIT_BUILD_PARAVIEW=$AOKIT_BUILD_PARAVIEW")
  case "$AOKIT_BUILD_PARAVIEW" in ON|on|1|TRUE|true) bash "$root/scripts/setup-paraview.sh" ;; esac
fi
cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE=Release "${extra[@]}" > "$root/build-configure.log" 2>&1 \
  || { cat "$root/build-configure.log"; exit 1; }
cmake --build "$root/build" -j "$(nproc)"
