#!/usr/bin/env bash
# Builds halfvec with AddressSanitizer + UndefinedBehaviorSanitizer (GCC, the project's compiler)
# in build-asan and runs the test suite under them; any report fails it (exit 1). Leaks are
# checked (LeakSanitizer) and only Mesa's and LLVM's are suppressed (scripts/sanitize.supp says
# why, entry by entry): a leak in the project's code fails the run.
# Mesa's driver (swrast_dri.so, which carries llvmpipe) is dlopen'ed and dlclose'd with each GL
# context; its allocations would then show as leaks in an "<unknown module>" that no suppression
# can name. It is preloaded, after the ASan runtime, so it stays loaded for the leak scan.
# Usage: bash scripts/sanitize.sh [--ci] [ctest arguments, e.g. -R Scene]
#   --ci: the CI subset, sized for CI's time limit: the test binaries of the modules that read
#         hostile input and their CPU code (test_core, test_image, test_scene, test_ibl,
#         test_shading: every loader, hostile-file and FuzzInputs test, the shared assets' glTF
#         files, the CPU BRDF/IBL math). Without --ci: the whole suite (GPU and viewer tests
#         included) but Install.ConsumerExampleAgainstCopiedPrefix (see below).
set -euo pipefail
cd "$(dirname "$0")/.."
ci_subset=()
targets=()
if [ "${1:-}" = --ci ]; then
  shift
  targets=(--target test_core test_image test_scene test_ibl test_shading)
  # Left out: the placeholders of the test binaries not built, and the tests that run programs
  # the subset does not build (the installed package's consumer, the golden render, the compile
  # tests of the light variants, below).
  ci_subset=(-E '_NOT_BUILT|^Install[.]|^golden[.]|^LightVariants[.](CompiledRequestBuilds|MissingRequestIsACompileError)$')
else
  # Left out of the whole suite too: the installed-package test builds a consumer program
  # without the sanitizers against the instrumented libraries, which cannot link; it checks
  # packaging, which the normal build's suite covers. And the light variants' compile tests: they
  # run the compiler (under the preloaded ASan runtime, whose leak check fails cc1plus) to test
  # what it accepts, nothing the sanitizers could check.
  ci_subset=(-E '^Install[.]|^LightVariants[.](CompiledRequestBuilds|MissingRequestIsACompileError)$')
fi
bash scripts/setup.sh
shared_assets=""
if [ -d ../shared/assets ]; then shared_assets="-DHV_ASSETS_DIR=$(cd ../shared/assets && pwd)"; fi
launcher=""
if command -v ccache >/dev/null; then launcher="-DCMAKE_CXX_COMPILER_LAUNCHER=ccache"; fi
# -Wno-maybe-uninitialized: GCC 12 reports false positives inside libstdc++ (std::regex's
# std::function members) once the sanitizers instrument it; the normal build keeps the warning.
flags="-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer -g -O1"
flags="$flags -Wno-maybe-uninitialized"
cmake -S . -B build-asan -G Ninja $launcher -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_C_FLAGS="$flags" -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-g -O1" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" -DHV_WERROR=ON $shared_assets >/dev/null
cmake --build build-asan -j"$(nproc)" "${targets[@]}"
driver=$(find /usr/lib -name swrast_dri.so -path '*dri*' 2>/dev/null | head -1)
asan=$(gcc -print-file-name=libasan.so)
export LD_PRELOAD="$asan${driver:+ $driver}"
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=0:halt_on_error=1:detect_stack_use_after_return=0:check_initialization_order=1:strict_init_order=1"
export LSAN_OPTIONS="suppressions=$(pwd)/scripts/sanitize.supp:print_suppressions=0"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
# Sanitized code runs 2-3x slower: the per-test timeout is raised accordingly.
ctest --test-dir build-asan --output-on-failure -j"$(nproc)" --timeout 900 "${ci_subset[@]}" "$@"
