#!/usr/bin/env bash
# Fuzzes the loaders of hostile input with libFuzzer (clang 14 from Debian) under AddressSanitizer
# and UndefinedBehaviorSanitizer: scene files and overrides, glTF/GLB, Radiance .hdr, PFM, PNG.
# Builds the harnesses of fuzz/ in build-fuzz, seeds each corpus (out/fuzz/corpus/TARGET, kept
# between runs) from the samples, the shared assets (scripts/fuzz_seeds.py) and the regression
# inputs in tests/fuzz/TARGET, then runs each target for the given time, one after the other, at
# low priority. Crashes go to out/fuzz/artifacts/TARGET; minimize one with
#   build-fuzz/fuzz/fuzz_TARGET -minimize_crash=1 -runs=10000 CRASH
# and commit the result under tests/fuzz/TARGET (the tests replay every file there).
# Usage: bash scripts/fuzz.sh [--seconds N] [--parallel] [TARGET...]
#   (default: 1800 s, all five targets, one after the other; --parallel runs them all at once)
# Exit 0 when no target found anything; 1 otherwise. Prints execs and coverage per target.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=1800
parallel=0
targets=()
while [ $# -gt 0 ]; do
  case "$1" in
    --seconds) seconds="$2"; shift 2 ;;
    --parallel) parallel=1; shift ;;
    -h|--help) sed -n '2,13p' "$0"; exit 0 ;;
    *) targets+=("$1"); shift ;;
  esac
done
[ ${#targets[@]} -gt 0 ] || targets=(scene gltf hdr pfm png)
HV_FUZZ_SETUP=1 bash scripts/setup.sh
launcher=""
if command -v ccache >/dev/null; then launcher="-DCMAKE_CXX_COMPILER_LAUNCHER=ccache"; fi
flags="-fsanitize=address,undefined,fuzzer-no-link -fno-sanitize-recover=undefined -fno-omit-frame-pointer -g -O1"
CC=clang-14 CXX=clang++-14 cmake -S . -B build-fuzz -G Ninja $launcher -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_C_FLAGS="$flags" -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-g -O1" \
  -DHV_FUZZ=ON -DHV_BUILD_TESTS=OFF -DHV_WERROR=OFF >/dev/null
cmake --build build-fuzz -j2 --target $(printf 'fuzz_%s ' "${targets[@]}") >/dev/null
seeds=out/fuzz/seeds
rm -rf "$seeds"
python3 scripts/fuzz_seeds.py "$seeds" >&2
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=0
fuzz_target() {
  local t=$1 status=0 corpus artifacts log marker started elapsed execs cov ft unit cpu
  corpus=out/fuzz/corpus/$t
  artifacts=out/fuzz/artifacts/$t
  mkdir -p "$corpus" "$artifacts" "$seeds/$t"
  log=out/fuzz/$t.log
  echo "[fuzz] $t: ${seconds} s" >&2
  marker=$(mktemp)
  started=$(date +%s)
  # -rss_limit_mb: "a few GB" at most per input (the goal), ASan's overhead included.
  # -timeout is wall time, and at nice 19 on a machine busy with other work the fuzzer gets a few
  # percent of a core: an input that takes 0.6 s of CPU took 71 s there (a false "timeout").
  # So the wall-time limit only catches real hangs (300 s), and every input the fuzzer reports as
  # slow (over 10 s of wall time: -report_slow_units) or timed out is re-run below at normal
  # priority, where it must finish within 10 s of CPU time; one that does not is a finding.
  if ! nice -n 19 build-fuzz/fuzz/fuzz_$t -max_total_time="$seconds" -rss_limit_mb=3072 \
      -malloc_limit_mb=3072 -timeout=300 -report_slow_units=10 -max_len=262144 \
      -print_final_stats=1 -artifact_prefix="$artifacts/" "$corpus" "$seeds/$t" > "$log" 2>&1; then
    if find "$artifacts" -newer "$marker" -type f ! -name 'slow-unit-*' ! -name 'timeout-*' | grep -q . ||
        ! find "$artifacts" -newer "$marker" -name 'timeout-*' | grep -q .; then
      status=1
      echo "[fuzz] $t: FOUND a problem (see $log and $artifacts)" >&2
    else
      echo "[fuzz] $t: stopped early on a timeout (wall time, at nice 19); re-checked below" >&2
    fi
  fi
  for unit in $(find "$artifacts" -newer "$marker" \( -name 'slow-unit-*' -o -name 'timeout-*' \)); do
    if cpu=$( { TIMEFORMAT='%U %S'; time (ulimit -t 10; build-fuzz/fuzz/fuzz_$t "$unit" >/dev/null 2>&1); } 2>&1 ); then
      echo "[fuzz] $t: $(basename "$unit") was slow only under load: $(echo "$cpu" | awk '{print $1 + $2}') s of CPU at normal priority" >&2
    else
      status=1
      echo "[fuzz] $t: FOUND a slow input: $unit takes over 10 s of CPU at normal priority" >&2
    fi
  done
  rm -f "$marker"
  elapsed=$(( $(date +%s) - started ))
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1 | cut -d' ' -f2)
  ft=$(grep -o 'ft: [0-9]*' "$log" | tail -1 | cut -d' ' -f2)
  echo "fuzz $t: ${execs:-?} execs in ${elapsed} s (asked ${seconds} s), coverage ${cov:-?} edges, ${ft:-?} features, corpus $(ls "$corpus" | wc -l) files"
  return $status
}

status=0
if [ $parallel = 1 ]; then
  pids=()
  for t in "${targets[@]}"; do
    fuzz_target "$t" > "out/fuzz/$t.summary" &
    pids+=($!)
  done
  for i in "${!pids[@]}"; do
    wait "${pids[$i]}" || status=1
    cat "out/fuzz/${targets[$i]}.summary"
  done
else
  for t in "${targets[@]}"; do fuzz_target "$t" || status=1; done
fi
exit $status
