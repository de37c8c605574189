#!/bin/sh
# Fetches real test meshes from Debian packages without installing them:
#   DEST/bunny00.off, DEST/fandisk.off   from libcgal-demo (inside its data.tar.gz)
#   DEST/assimp/                         the assimp-testmodels model tree, invalid/ included
# Usage: models/fetch-meshes.sh [DEST]   (default: models/packaged next to this script)
# Idempotent: what is present is skipped. Files appear atomically (copied to a temporary name, then
# renamed), so an interrupted run never leaves half a mesh behind.
set -eu

here=$(cd "$(dirname "$0")" && pwd)
dest=${1:-$here/packaged}

fail() { echo "fetch-meshes: $*" >&2; exit 1; }

need_cgal=0; need_assimp=0
[ -f "$dest/bunny00.off" ] && [ -f "$dest/fandisk.off" ] || need_cgal=1
[ -d "$dest/assimp/invalid" ] || need_assimp=1
if [ $need_cgal = 0 ] && [ $need_assimp = 0 ]; then
  exit 0
fi

for tool in apt-get dpkg-deb tar; do
  command -v $tool >/dev/null 2>&1 || fail "'$tool' not found (needs a Debian-like system)"
done
mkdir -p "$dest" 2>/dev/null || fail "cannot create $dest"
dest=$(cd "$dest" && pwd)

work=$(mktemp -d "${TMPDIR:-/tmp}/aokit-meshes.XXXXXX") || fail "cannot create a temporary folder"
cleanup() { rm -rf "$work" "$dest/.bunny00.off.part" "$dest/.fandisk.off.part" "$dest/.assimp.part"; }
trap cleanup EXIT
trap 'exit 130' INT TERM  # exit runs the EXIT trap
cd "$work"

set --
[ $need_cgal = 1 ] && set -- "$@" libcgal-demo
[ $need_assimp = 1 ] && set -- "$@" assimp-testmodels

# apt-get download fetches the .deb only: nothing is installed, no dependency is pulled.
# Empty package lists (fresh containers) make it fail; refresh them once and retry.
if ! apt-get download "$@" >apt.log 2>&1; then
  apt-get update >>apt.log 2>&1 || true
  apt-get download "$@" >>apt.log 2>&1 ||
    fail "apt-get download $* failed: $(grep -E '^(E|W):' apt.log | tail -n 1)"
fi

# install_file SRC NAME: copy SRC to DEST/NAME through a temporary name.
install_file() {
  if ! cp "$1" "$dest/.$2.part" || ! mv -f "$dest/.$2.part" "$dest/$2"; then
    fail "cannot write $dest/$2"
  fi
}

if [ $need_cgal = 1 ]; then
  dpkg-deb -x libcgal-demo_*.deb cgal || fail "cannot unpack libcgal-demo"
  # The meshes sit in a tarball of demo data inside the package; extract just the two files.
  for name in bunny00.off fandisk.off; do
    found=$(find cgal -name "$name" -type f | head -n 1)
    if [ -z "$found" ]; then
      # Package paths hold no spaces, so splitting find's output is safe here.
      # shellcheck disable=SC2044
      for archive in $(find cgal -name '*.tar.gz' -o -name '*.tar.xz' -o -name '*.tgz'); do
        member=$(tar -tf "$archive" 2>/dev/null | grep "/$name\$" | head -n 1) || true
        if [ -n "$member" ]; then
          mkdir -p extracted
          tar -xf "$archive" -C extracted "$member" || fail "cannot extract $member"
          found=extracted/$member
          break
        fi
      done
    fi
    [ -n "$found" ] || fail "$name not found in libcgal-demo"
    install_file "$found" "$name"
  done
fi

if [ $need_assimp = 1 ]; then
  dpkg-deb -x assimp-testmodels_*.deb assimp || fail "cannot unpack assimp-testmodels"
  tree=assimp/usr/share/assimp/models
  [ -d "$tree/invalid" ] || fail "assimp-testmodels has no models/invalid folder (layout changed?)"
  rm -rf "$dest/.assimp.part"
  cp -R "$tree" "$dest/.assimp.part" || fail "cannot copy the assimp models to $dest"
  rm -rf "$dest/assimp"
  mv "$dest/.assimp.part" "$dest/assimp" || fail "cannot write $dest/assimp"
fi
echo "fetch-meshes: meshes in $dest"
