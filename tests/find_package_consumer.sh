#!/usr/bin/env bash
# Installs aokit into a scratch prefix and builds and runs examples/plain-vtk against it through
# find_package(aokit): the package config, exported target and headless recipe must all work.
set -euo pipefail
build=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build" --prefix "$work/prefix" > "$work/install.log"
cmake -S "$src/examples/plain-vtk" -B "$work/app" -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_BUILD_TYPE=Release \
  > "$work/configure.log" 2>&1 || { cat "$work/configure.log"; exit 1; }
cmake --build "$work/app" -j 2 > "$work/build.log" 2>&1 || { cat "$work/build.log"; exit 1; }
env -u DISPLAY "$work/app/plain_vtk"
