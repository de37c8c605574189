#!/usr/bin/env bash
# Bit-identity check for refactors: every method's float AO (`aokit render --ao-float`) on the
# twelve default bench scenes, for each bench setting and a few settings off the curve, written
# by one build and compared with another's.
#
#   bash scripts/ao-identity.sh capture BUILD_DIR OUT_DIR [WxH]   # -> OUT_DIR/<scene>/<run>.f32, OUT_DIR/sums
#   bash scripts/ao-identity.sh compare OUT_A OUT_B               # exit 1 when any file differs
#
# Capture before a change, capture after, compare. Field bakes go through a private cache in OUT_DIR
# (the first capture bakes, so it takes longer). The runs list the bench curves as of the refactor
# that brought this script (issue 15) plus settings that reach other code paths.
set -euo pipefail

runs=(
  "none|"
  "vtkssao|"
  "obscurance|samples=2,m=2,thickness=1" "obscurance|samples=4,m=2,thickness=1" "obscurance|samples=8,m=2,thickness=1"
  "obscurance|samples=4,m=4,thickness=1" "obscurance|samples=8,m=4,thickness=1" "obscurance|samples=4,m=4,thickness=0.5"
  "obscurance|samples=4" "obscurance|samples=6" "obscurance|samples=4,scale=1" "obscurance|samples=4,guard=0.1"
  "obscurance|samples=6,guard=0.1"
  "obscurance|transfer=1" "obscurance|interleave=rotations,filter=0" "obscurance|silhouette=0,falloff=wendland"
  "field|kind=auto" "field|kind=auto,combine=cone" "field|kind=auto,scale=0.5" "field|kind=auto,combine=cone,near=2,far=4"
  "field|kind=grid6,resolution=32" "field|kind=cube" "field|kind=grid4"
  "field|kind=auto,scale=0.5,window=8" "field|self=0,weights=seed" "field|kind=auto,scale=0.25"
  "hybrid|res=128,rays=8,steps=4,scale=0.25,window=16" "hybrid|res=256,rays=12,steps=5,scale=0.25,window=12"
  "hybrid|res=256,rays=16,steps=6,scale=0.25,window=16" "hybrid|res=256,rays=16,steps=8" "hybrid|"
  "hybrid|frame=rotated,res=128" "hybrid|frame=dominant,span=0,res=128" "hybrid|res=128,window=4,hn=2"
  "hybrid|lift=ray,res=128" "hybrid|lift=graze,reach=2,res=128"
)
scenes=(sphere-plane sphere-offscreen cubes tank stack corridor room open-box bunny fandisk hidden behind)
extra=("courtyard|hybrid|static=1,res=128")  # scene|method|setting

capture() {
  local build=$1 out=$2 size=${3:-512x384}
  local cli="$build/apps/aokit"
  export LD_LIBRARY_PATH="$build/nodes${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"  # a copied build finds its own libraries
  [ -x "$cli" ] || { echo "ao-identity: no CLI at $cli" >&2; exit 1; }
  mkdir -p "$out/cache"
  export AOKIT_CACHE_DIR="$out/cache"
  local all=()
  for s in "${scenes[@]}"; do
    local i=0
    for r in "${runs[@]}"; do all+=("$s|$r|$i"); i=$((i + 1)); done
  done
  local i=0
  for e in "${extra[@]}"; do all+=("$e|x$i"); i=$((i + 1)); done
  local n=0 total=${#all[@]}
  for item in "${all[@]}"; do
    IFS='|' read -r scene method setting tag <<<"$item"
    n=$((n + 1))
    mkdir -p "$out/$scene"
    local name="$method-$tag"
    printf '\r[%d/%d] %-16s %-10s %-45s' "$n" "$total" "$scene" "$method" "$setting" >&2
    local args=(render "$scene" --size "$size" --method "$method" -o "$out/$scene/$name.png" --ao-float "$out/$scene/$name.f32")
    [ -n "$setting" ] && args+=(--setting "$setting")
    "$cli" "${args[@]}" > /dev/null 2> "$out/$scene/$name.err" || { echo; echo "ao-identity: failed: $item" >&2; cat "$out/$scene/$name.err" >&2; exit 1; }
    echo "$scene/$name $method $setting" >> "$out/runs"
  done
  echo >&2
  (cd "$out" && find . -name '*.f32' | sort | xargs sha256sum) > "$out/sums"
  echo "ao-identity: $total runs in $out"
}

compare() {
  local a=$1 b=$2 bad=0 same=0
  while read -r sum file; do
    local other
    other=$(grep -F "  $file" "$b/sums" | cut -d' ' -f1 || true)
    if [ -z "$other" ]; then echo "missing in $b: $file"; bad=$((bad + 1));
    elif [ "$other" != "$sum" ]; then
      local run=${file#./}
      echo "differs: $file ($(grep -F "${run%.f32} " "$a/runs" | head -1 | cut -d' ' -f2-))"; bad=$((bad + 1))
    else same=$((same + 1)); fi
  done < "$a/sums"
  echo "ao-identity: $same identical, $bad differ or are missing"
  [ "$bad" -eq 0 ]
}

case "${1:-}" in
  capture) shift; capture "$@" ;;
  compare) shift; compare "$@" ;;
  *) echo "usage: $0 capture BUILD_DIR OUT_DIR [WxH] | compare OUT_A OUT_B" >&2; exit 2 ;;
esac
