#!/usr/bin/env bash
# Cross-checks the glTF loader against the Khronos glTF Validator: runs both on every
# .gltf/.glb under ../shared/assets and tests/fuzz, and prints each file where they disagree:
#   validator errors but halfvec loads it, or no validator error but halfvec rejects it.
# The validator (npm gltf-validator, pinned) is installed by this script into
# ${HV_CACHE_DIR:-~/.cache/halfvec}/gltf-validator on first use; without npm (or node) the check
# is skipped with the reason, exit 0. The engine's verdict comes from build/tests/hv_gltf_check
# (scripts/build.sh builds it). docs/hostile-input.md lists each disagreement with its reason.
# Usage: bash scripts/gltf_validate.sh [--all]   (--all: print every file, not only disagreements)
# Exit 0 when every disagreement is one listed in docs/hostile-input.md ("expected" below), else 1.
set -euo pipefail
cd "$(dirname "$0")/.."
all=0
[ "${1:-}" = "--all" ] && all=1
version=2.0.0-dev.3.10
if ! command -v npm >/dev/null || ! command -v node >/dev/null; then
  echo "gltf_validate: skipped: npm or node not found (Debian: apt-get install npm)"
  exit 0
fi
cache="${HV_CACHE_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/halfvec}/gltf-validator"
module="$cache/node_modules/gltf-validator"
if [ ! -f "$module/package.json" ] || ! grep -q "\"version\": \"$version\"" "$module/package.json"; then
  mkdir -p "$cache"
  if ! npm install --silent --no-audit --no-fund --prefix "$cache" "gltf-validator@$version" >&2; then
    echo "gltf_validate: skipped: npm install gltf-validator@$version failed (offline?)"
    exit 0
  fi
fi
check=build/tests/hv_gltf_check
[ -x "$check" ] || { echo "gltf_validate: $check missing: run scripts/build.sh" >&2; exit 1; }
files=()
while IFS= read -r -d '' f; do files+=("$f"); done < <(
  find ../shared/assets tests/fuzz \( -name '*.gltf' -o -name '*.glb' \) -print0 2>/dev/null | sort -z)
[ ${#files[@]} -gt 0 ] || { echo "gltf_validate: no glTF files found"; exit 0; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
node scripts/gltf_validate.mjs "$module" "${files[@]}" > "$tmp/validator.tsv"
"$check" "${files[@]}" > "$tmp/halfvec.tsv" || true
# Disagreements documented in docs/hostile-input.md ("Cross-check with the Khronos glTF
# Validator"), matched by file name: the loader's verdict there is intended.
expected="$(sed -n 's/^| `\([^`]*\)` | .*| expected |$/\1/p' docs/hostile-input.md)"
status=0
agree=0
total=0
while IFS=$'\t' read -r file errors warnings codes && IFS=$'\t' read -r verdict file2 detail <&3; do
  total=$((total + 1))
  [ "$file" = "$file2" ] || { echo "gltf_validate: out of step at $file / $file2" >&2; exit 1; }
  if [ "$errors" -gt 0 ] && [ "$verdict" = OK ]; then
    kind="validator: $errors errors ($codes); halfvec loads it"
  elif [ "$errors" = 0 ] && [ "$verdict" = ERROR ]; then
    kind="validator: valid ($warnings warnings); halfvec: $detail"
  else
    agree=$((agree + 1))
    [ $all = 1 ] && echo "agree: $file: validator $errors errors, halfvec $verdict"
    continue
  fi
  name=$(basename "$file")
  if printf '%s\n' "$expected" | grep -qxF "$name"; then
    echo "DISAGREE (documented): $file: $kind"
  else
    echo "DISAGREE: $file: $kind"
    status=1
  fi
done < "$tmp/validator.tsv" 3< "$tmp/halfvec.tsv"
echo "gltf_validate: $agree of $total files agree (validator $version)"
exit $status
