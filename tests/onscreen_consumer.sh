#!/usr/bin/env bash
# Installs aokit into a scratch prefix and checks the kit library that applications link: its
# DT_NEEDED holds no libOSMesa and it defines no GLX entry points; then builds
# examples/onscreen-vtk (an ordinary vtkRenderWindow on X11, linking aokit::aokit only) through
# find_package(aokit) and runs it under Xvfb.
set -euo pipefail
build=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build" --prefix "$work/prefix" > "$work/install.log"
lib=$(find "$work/prefix" -name 'libaokit.so.*' -type f | head -n 1)
if readelf -d "$lib" | grep -q 'NEEDED.*OSMesa'; then echo "libaokit.so links libOSMesa" >&2; exit 1; fi
if nm -D --defined-only "$lib" | grep -q ' glX'; then echo "libaokit.so defines GLX entry points" >&2; exit 1; fi
# OSMesa made unfindable: an application of aokit::aokit alone must not need it.
cmake -S "$src/examples/onscreen-vtk" -B "$work/app" -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_DISABLE_FIND_PACKAGE_OSMesa=ON \
  > "$work/configure.log" 2>&1 || { cat "$work/configure.log"; exit 1; }
cmake --build "$work/app" -j 2 > "$work/build.log" 2>&1 || { cat "$work/build.log"; exit 1; }
if readelf -d "$work/app/onscreen_vtk" | grep -q 'NEEDED.*OSMesa'; then echo "the on-screen app links libOSMesa" >&2; exit 1; fi
command -v xvfb-run > /dev/null || { echo "xvfb-run not found (scripts/setup.sh installs xvfb)" >&2; exit 1; }
xvfb-run -a -s "-screen 0 800x600x24" "$work/app/onscreen_vtk"
