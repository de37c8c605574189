#!/usr/bin/env bash
# One command from a clean clone: set up, build, and run every test (CTest, all offscreen).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/build.sh"
unset DISPLAY
ctest --test-dir "$root/build" --output-on-failure -j "$(nproc)"
