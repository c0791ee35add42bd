#!/usr/bin/env bash
# halfvec as an installed package, checked the way a user's project would use it:
#   1. `cmake --install` of the configured build (BUILD, default ./build) into a temporary prefix;
#   2. the prefix moved to another folder (nothing may point back into it or the source tree);
#   3. samples/library configured with only that prefix (find_package(halfvec CONFIG REQUIRED)),
#      built, and run on SCENE (default samples/scenes/default.json) at 160x90: it must write a
#      PNG of that size.
# Run by CTest (Install.ConsumerExampleAgainstCopiedPrefix) and usable by hand.
# Usage: bash scripts/check_install.sh [BUILD] [SCENE]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:-$root/build}" && pwd)
scene=${2:-$root/samples/scenes/default.json}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

cmake --install "$build" --prefix "$work/prefix" >/dev/null
mv "$work/prefix" "$work/moved"
if grep -rIl -e "$root" -e "$build" "$work/moved/lib/cmake" "$work/moved/include" >/dev/null 2>&1; then
  echo "check_install: the installed package refers to the source or build tree:" >&2
  grep -rIl -e "$root" -e "$build" "$work/moved/lib/cmake" "$work/moved/include" >&2
  exit 1
fi
launcher=()
if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
cmake -S "$root/samples/library" -B "$work/example" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$work/moved" -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF "${launcher[@]}" >/dev/null
cmake --build "$work/example" >/dev/null
# Run outside both trees, with no shader folder: the library's embedded shaders are used.
(cd "$work" && env -u HV_SHADER_DIR "$work/example/halfvec_library_example" "$scene" "$work/out.png" 160x90)
python3 - "$work/out.png" <<'PY'
import struct, sys
data = open(sys.argv[1], 'rb').read()
assert data[:8] == b'\x89PNG\r\n\x1a\n', 'not a PNG'
w, h = struct.unpack('>II', data[16:24])
assert (w, h) == (160, 90), f'size {w}x{h}, expected 160x90'
PY
echo "check_install: OK (installed, moved, consumer built and rendered $(basename "$scene"))"
