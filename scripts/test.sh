#!/usr/bin/env bash
# One command from a clean clone: set up, build, and run every test (CTest, all offscreen), then the
# same suite again in a build with AddressSanitizer and UndefinedBehaviorSanitizer.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
AOKIT_BUILD_PARAVIEW=ON bash "$root/scripts/build.sh"  # the ParaView plugin and its pvbatch tests too
unset DISPLAY
export AOKIT_REQUIRE_MESHES=1  # a missing packaged mesh fails its tests instead of skipping them
ctest --test-dir "$root/build" --output-on-failure -j "$(nproc)"
bash "$root/scripts/test-sanitizers.sh"
