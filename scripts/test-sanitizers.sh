#!/usr/bin/env bash
# Builds aokit with AddressSanitizer and UndefinedBehaviorSanitizer into build-asan/ and runs the
# whole suite there: any report fails the run (UBSan halts on the first error; LeakSanitizer's
# suppressions name third-party libraries only: tests/sanitizers/lsan.supp). The two package
# tests that build applications against an installed aokit are left out: they link a plain
# executable against the instrumented library, which the sanitizer runtime refuses. The Python
# package is not built there: python3 would have to load the sanitizer runtime first (LD_PRELOAD),
# and its own allocations would flood the reports; its C++ is the kit's, checked by the rest.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
flags="-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined"
cmake -S "$root" -B "$root/build-asan" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DAOKIT_BUILD_PYTHON=OFF "-DCMAKE_CXX_FLAGS=$flags" \
  "-DCMAKE_EXE_LINKER_FLAGS=-fsanitize=address,undefined" "-DCMAKE_SHARED_LINKER_FLAGS=-fsanitize=address,undefined" \
  > "$root/build-asan-configure.log" 2>&1 || { cat "$root/build-asan-configure.log"; exit 1; }
cmake --build "$root/build-asan" -j "$(nproc)"
unset DISPLAY
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=0
export LSAN_OPTIONS=suppressions=$root/tests/sanitizers/lsan.supp:print_suppressions=0
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
ctest --test-dir "$root/build-asan" --output-on-failure -j "$(nproc)" -E 'find_package_consumer|onscreen_consumer|^Dropin'
# The on-screen drop-in tests run with address and undefined-behaviour checks but without leak
# reports: Mesa's GLX driver is unloaded before LeakSanitizer runs, so its per-context blocks are
# reported from "<unknown module>" with no frame a suppression could name. Their own lifetime test
# counts GL objects and resident memory over 130 cycles instead (test_dropin_lifetime.cpp).
ASAN_OPTIONS=detect_leaks=0:abort_on_error=0 \
  ctest --test-dir "$root/build-asan" --output-on-failure -j "$(nproc)" -R '^Dropin'
