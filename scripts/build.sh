#!/usr/bin/env bash
# Configures and builds halfvec in ./build (Release, warnings as errors when HV_WERROR=ON).
# Arguments, if any, are the targets to build (default: all of them, tests included).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
shared_assets=""
if [ -d ../shared/assets ]; then shared_assets="-DHV_ASSETS_DIR=$(cd ../shared/assets && pwd)"; fi
launcher=""
if command -v ccache >/dev/null; then launcher="-DCMAKE_CXX_COMPILER_LAUNCHER=ccache"; fi
cmake -S . -B build -G Ninja $launcher -DCMAKE_BUILD_TYPE=Release -DHV_WERROR="${HV_WERROR:-ON}" $shared_assets >/dev/null
targets=()
for t in "$@"; do targets+=(--target "$t"); done
cmake --build build -j"$(nproc)" "${targets[@]}"
