#!/usr/bin/env bash
# pvbatch with the AOKit view: ParaView's Python (unpacked by scripts/setup-paraview.sh, first on
# sys.path so that Debian's VTK 9.1 vtkmodules never load beside ParaView's 9.2) and the plugin of
# the build tree (PV_PLUGIN_PATH: pvbatch loads it at start). Needs an X server (DISPLAY) as
# pvbatch does. Under MPI: mpiexec -n 2 scripts/pvbatch.sh script.py
#   scripts/pvbatch.sh script.py [args]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
python="$root/third_party/paraview/python"
plugin="${AOKIT_PARAVIEW_PLUGIN_DIR:-$root/build/paraview/lib/paraview-5.11/plugins/AOKitView}"
[ -d "$python/paraview" ] || { echo "pvbatch.sh: error: no ParaView Python in $python (run scripts/setup-paraview.sh)" >&2; exit 1; }
[ -f "$plugin/AOKitView.so" ] || { echo "pvbatch.sh: error: no plugin $plugin/AOKitView.so (run scripts/build.sh)" >&2; exit 1; }
[ -n "${DISPLAY:-}" ] || { echo "pvbatch.sh: error: pvbatch needs an X server: DISPLAY is not set (xvfb-run, or tests/xvfb.sh)" >&2; exit 1; }
export PYTHONPATH="$python${PYTHONPATH:+:$PYTHONPATH}"
export PV_PLUGIN_PATH="$plugin"
exec pvbatch "$@"
