#!/usr/bin/env bash
# Checks that every sample scene renders bit-identically to another revision (default: HEAD):
# builds REV in a temporary worktree (no tests), renders each sample scene headless with both
# builds (HDR PFM and tone-mapped PNG at --size, default 320x180) and compares the files byte for
# byte. Exit 0 when every image is identical, 1 otherwise (the differing files are listed). A
# sample scene REV cannot load (newer than REV) is reported as NEW and compared with nothing.
# The working tree renders each scene twice and must produce the same bytes both times (renders
# are reproducible since the culling keeps every tile's list in light order): a tree image that
# differs between its two runs fails as NONDETERMINISTIC. REV renders each scene twice too: where
# REV itself is not reproducible (revisions before the per-tile culling summed tile lists in a
# run-dependent order), the tree's image may differ from REV's by no more than REV's two runs
# differ from each other (reported as REV-NONDETERMINISTIC, not a failure).
# Usage: bash scripts/same_renders.sh [REV] [--size WxH] [--base-exe PATH]
# --base-exe: a halfvec binary already built from REV (skips building REV; for a series of steps).
# Behaviour-preserving refactors are checked with it (docs/architecture.md).
set -euo pipefail
cd "$(dirname "$0")/.."
rev=HEAD
size=320x180
base_exe=""
while [ $# -gt 0 ]; do
  case "$1" in
    --size) size="$2"; shift 2 ;;
    --base-exe) base_exe="$(cd "$(dirname "$2")" && pwd)/$(basename "$2")"; shift 2 ;;
    -h|--help) sed -n '2,15p' "$0"; exit 0 ;;
    *) rev="$1"; shift ;;
  esac
done
root=$(pwd)
if [ -d ../shared/assets ]; then export HV_ASSETS_DIR="$(cd ../shared/assets && pwd)"; fi
work=$(mktemp -d)
cleanup() { git -C "$root" worktree remove --force "$work/base" >/dev/null 2>&1 || true; rm -rf "$work"; }
trap cleanup EXIT
launcher=()
if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi

if [ -n "$base_exe" ]; then
  echo "[same_renders] $rev: $base_exe" >&2
  mkdir -p "$work/base/build" && ln -s "$base_exe" "$work/base/build/halfvec"
else
  echo "[same_renders] building $rev in a temporary worktree" >&2
  git worktree add --detach "$work/base" "$rev" >/dev/null 2>&1
  cmake -S "$work/base" -B "$work/base/build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DHV_BUILD_TESTS=OFF \
    "${launcher[@]}" >/dev/null
  cmake --build "$work/base/build" --target halfvec >/dev/null
fi
echo "[same_renders] building the working tree" >&2
bash scripts/build.sh halfvec >/dev/null  # only the program it renders with

# Largest absolute channel difference of two PFM files (halfvec compare's max_abs).
maxabs() { "$root/build/halfvec" compare "$1" "$2" | sed -n 's/.*"max_abs": \([^,]*\),.*/\1/p'; }

status=0
n=0
for scene in samples/scenes/*.json; do
  name=$(basename "$scene" .json)
  failed=""
  for side in base base2 tree tree2; do
    case "$side" in
      tree*) exe="$root/build/halfvec"; dir="$root" ;;
      *) exe="$work/base/build/halfvec"; dir="$work/base" ;;
    esac
    mkdir -p "$work/out/$side"
    (cd "$dir" && XDG_CACHE_HOME="$work/cache-$side" "$exe" render "$root/$scene" --size "$size" \
      --out "$work/out/$side/$name.png" --hdr "$work/out/$side/$name.pfm" >/dev/null 2>"$work/out/$side/$name.err") || {
      failed="$failed $side"; }
  done
  # A scene REV cannot load (one newer than REV, using what REV lacks) has nothing to compare
  # with: reported as NEW when the working tree renders it, a failure when the tree fails too.
  if [ "$failed" = " base base2" ]; then
    echo "NEW        $name: $rev cannot render it ($(head -c 160 "$work/out/base/$name.err"))"
    continue
  elif [ -n "$failed" ]; then
    for side in $failed; do
      echo "[same_renders] $name: render failed ($side):" >&2; cat "$work/out/$side/$name.err" >&2
    done
    status=1
    continue
  fi
  for ext in pfm png; do
    n=$((n + 1))
    o="$work/out"
    if ! cmp -s "$o/tree/$name.$ext" "$o/tree2/$name.$ext"; then
      echo "NONDETERMINISTIC $name.$ext: the working tree renders it differently in two runs"; status=1
    elif cmp -s "$o/base/$name.$ext" "$o/tree/$name.$ext" && cmp -s "$o/base/$name.$ext" "$o/base2/$name.$ext" \
      && cmp -s "$o/tree/$name.$ext" "$o/tree2/$name.$ext"; then
      echo "same       $name.$ext"
    elif [ "$ext" = pfm ] && ! { cmp -s "$o/base/$name.pfm" "$o/base2/$name.pfm" && cmp -s "$o/tree/$name.pfm" "$o/tree2/$name.pfm"; }; then
      self=$(printf '%s\n%s\n' "$(maxabs "$o/base/$name.pfm" "$o/base2/$name.pfm")" \
        "$(maxabs "$o/tree/$name.pfm" "$o/tree2/$name.pfm")" | sort -g | tail -1)
      cross=$(for a in base base2; do for b in tree tree2; do maxabs "$o/$a/$name.pfm" "$o/$b/$name.pfm"; done; done | sort -g | head -1)
      if awk -v a="$cross" -v b="$self" 'BEGIN { exit !(a <= b) }'; then
        echo "REV-NONDETERMINISTIC $name.$ext: runs of $rev differ by up to $self, the builds by $cross"
      else
        echo "DIFFERENT  $name.$ext: by $cross (runs of one build differ by up to $self)"; status=1
      fi
    else
      echo "DIFFERENT  $name.$ext"; status=1
    fi
  done
done
if [ $status -eq 0 ]; then echo "[same_renders] all $n images identical to $rev (up to the nondeterminism noted)" >&2; fi
exit $status
