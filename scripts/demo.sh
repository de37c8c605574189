#!/usr/bin/env bash
# One command from a clean clone: set up, build, and run `aokit demo` (output in aokit-demo/).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/build.sh"
unset DISPLAY
"$root/build/apps/aokit" demo --output "${1:-$root/aokit-demo}"
