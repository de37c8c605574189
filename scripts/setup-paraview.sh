#!/usr/bin/env bash
# ParaView 5.11 for the plugin, beside Debian's VTK 9.1 and python3-vtk9 (../shared notes: ParaView
# carries its own VTK 9.2). paraview and paraview-dev install from Debian without their
# recommends; python3-paraview conflicts with python3-vtk9 (both ship dist-packages/vtkmodules), so
# its package is unpacked into third_party/paraview/python instead, and a copy of ParaView's CMake
# package (third_party/paraview/cmake) points its Python targets there. pvbatch runs through
# scripts/pvbatch.sh, which puts that folder first on sys.path. Idempotent.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
dest="$root/third_party/paraview"
SUDO=""
[ "$(id -u)" -ne 0 ] && SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
missing=()
for p in paraview paraview-dev openmpi-bin; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup-paraview: installing ${missing[*]}"
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
version=$(dpkg-query -W -f='${Version}' paraview)
if [ "$(cat "$dest/version" 2>/dev/null)" = "$version" ]; then
  echo "setup-paraview: ParaView $version ready in $dest"
  exit 0
fi
rm -rf "$dest" "$dest.tmp"
mkdir -p "$dest.tmp/deb"
(cd "$dest.tmp/deb" && apt-get download -q "python3-paraview=$version" >/dev/null 2>&1) \
  || { echo "setup-paraview: error: apt-get download python3-paraview=$version failed" >&2; exit 1; }
dpkg-deb -x "$dest.tmp/deb"/python3-paraview_*.deb "$dest.tmp/unpacked"
mv "$dest.tmp/unpacked/usr/lib/python3/dist-packages" "$dest.tmp/python"
mv "$dest.tmp/unpacked/usr/lib/x86_64-linux-gnu/vtk/hierarchy/ParaView" "$dest.tmp/hierarchy"  # for wrapping
mv "$dest.tmp/unpacked/usr/bin" "$dest.tmp/bin"  # pvpython
# ParaView's CMake package, its prefix pinned to /usr and python3-paraview's files found here.
cp -r /usr/lib/x86_64-linux-gnu/cmake/paraview-5.11 "$dest.tmp/cmake"
find "$dest.tmp/cmake" -name '*.cmake' -exec sed -i \
  -e "s|\${_IMPORT_PREFIX}/lib/python3/dist-packages|$dest/python|g" \
  -e "s|\${_IMPORT_PREFIX}/lib/x86_64-linux-gnu/vtk/hierarchy/ParaView|$dest/hierarchy|g" \
  -e "s|\${_IMPORT_PREFIX}/bin/pvpython|$dest/bin/pvpython|g" \
  -e 's|\${_IMPORT_PREFIX}/|/usr/|g' \
  -e "s|\${_vtk_module_import_prefix}/lib/x86_64-linux-gnu/vtk/hierarchy/ParaView|$dest/hierarchy|g" \
  -e 's|^get_filename_component(_vtk_module_import_prefix .*|set(_vtk_module_import_prefix /usr)|' \
  -e 's|get_filename_component(PACKAGE_PREFIX_DIR "\${CMAKE_CURRENT_LIST_DIR}/[./]*" ABSOLUTE)|set(PACKAGE_PREFIX_DIR /usr)|' {} +
rm -rf "$dest.tmp/deb" "$dest.tmp/unpacked"
echo "$version" > "$dest.tmp/version"
mv "$dest.tmp" "$dest"
echo "setup-paraview: ParaView $version ready in $dest"
