#!/usr/bin/env bash
# Runs the whole test suite: installs what is missing, builds every target (warnings are errors;
# what scripts/render.sh built is reused), runs CTest.
# Tests that need ../shared/assets report "skipped" with the reason when it is absent.
set -euo pipefail
cd "$(dirname "$0")/.."
HV_WERROR=ON bash scripts/build.sh
ctest --test-dir build --output-on-failure -j"$(nproc)" "$@"
