#!/usr/bin/env bash
# The checks a machine with a hardware GPU can make that llvmpipe cannot (docs/performance.md,
# "On a hardware GPU"): run with a built halfvec on such a machine, then compare its renders here.
#
#   bash scripts/gpu_check.sh run OUTDIR [--exe PATH] [--frames N] [--quick]
#       on the GPU machine: the renderer's name; every sample scene rendered at 320x180 (PFM and
#       PNG, as scripts/same_renders.sh renders them) into OUTDIR/renders; then the cost goals'
#       benchmarks at 1280x720, frames interleaved, each into OUTDIR/bench_*.txt (--quick: the
#       renders and the frame table only), then, where this build has them, the GPU test binaries
#       (build/tests/test_{gl,ibl,render,eval,app}: what fails on this driver, not on llvmpipe).
#       Every step has a time limit and a failed step does not stop the rest;
#       OUTDIR/summary.txt lists each step with its exit status and seconds.
#   bash scripts/gpu_check.sh compare OUTDIR [--exe PATH]
#       here: renders the same scenes with this machine's driver and prints, per scene,
#       `halfvec compare` of the two HDR images (relative RMSE, largest difference): what one
#       driver draws differently from another (portability, not accuracy).
set -uo pipefail
cd "$(dirname "$0")/.."
mode="${1:-}"
out="${2:-}"
if [ -z "$mode" ] || [ -z "$out" ] || { [ "$mode" != run ] && [ "$mode" != compare ]; }; then
  sed -n '2,16p' "$0"
  exit 2
fi
shift 2
hv=build/halfvec
frames=15
quick=0
while [ $# -gt 0 ]; do
  case "$1" in
    --exe) hv="$2"; shift 2 ;;
    --frames) frames="$2"; shift 2 ;;
    --quick) quick=1; shift ;;
    *) echo "gpu_check: unknown option '$1'" >&2; exit 2 ;;
  esac
done
if [ ! -x "$hv" ]; then echo "gpu_check: no halfvec at $hv (bash scripts/build.sh halfvec)" >&2; exit 2; fi
if [ -z "${HV_ASSETS_DIR:-}" ] && [ -d ../shared/assets ]; then
  export HV_ASSETS_DIR="$(cd ../shared/assets && pwd)"
fi
mkdir -p "$out/renders"
size=320x180

# Renders every sample scene as scripts/same_renders.sh does, into $1.
render_all() {
  for scene in samples/scenes/*.json; do
    name=$(basename "$scene" .json)
    timeout 120 "$hv" render "$scene" --size "$size" --out "$1/$name.png" --hdr "$1/$name.pfm" \
      >"$1/$name.log" 2>&1 || echo "render failed: $name (see $1/$name.log)"
  done
}

if [ "$mode" = compare ]; then
  mine=$(mktemp -d)
  trap 'rm -rf "$mine"' EXIT
  render_all "$mine"
  printf '| scene | rel. RMSE | p99 relative | largest difference | PNG levels (max) |\n'
  printf '|---|---:|---:|---:|---:|\n'
  for f in "$out"/renders/*.pfm; do
    name=$(basename "$f" .pfm)
    [ -f "$mine/$name.pfm" ] || { echo "| $name | (not rendered here) | | | |"; continue; }
    "$hv" compare "$f" "$mine/$name.pfm" --json "$mine/$name.hdr.json" >/dev/null 2>&1
    "$hv" compare "${f%.pfm}.png" "$mine/$name.png" --json "$mine/$name.png.json" >/dev/null 2>&1
    python3 - "$mine/$name.hdr.json" "$mine/$name.png.json" "$name" <<'PY'
import json, sys
h, p = (json.load(open(f)) for f in sys.argv[1:3])
print(f"| {sys.argv[3]} | {h['rel_rmse']:.5f} | {h['p99_rel']:.4f} | {h['max_abs']:.4g} "
      f"| {round(p['max_abs'] * 255)} |")
PY
  done
  exit 0
fi

summary="$out/summary.txt"
: >"$summary"
# step NAME SECONDS CMD...: runs CMD under a time limit, output to $out/NAME.txt.
step() {
  local name="$1" limit="$2"
  shift 2
  local t0=$SECONDS
  timeout "$limit" "$@" >"$out/$name.txt" 2>&1
  local rc=$?
  printf '%-28s rc %3d  %4d s\n' "$name" "$rc" "$((SECONDS - t0))" | tee -a "$summary"
}

step renderer 120 "$hv" render samples/scenes/default.json --size 64x36 --out "$out/probe.png" \
  --stats "$out/probe.json"
t0=$SECONDS
render_all "$out/renders" >"$out/renders.txt" 2>&1
printf '%-28s rc %3d  %4d s\n' renders "$(grep -c 'render failed' "$out/renders.txt")" \
  "$((SECONDS - t0))" | tee -a "$summary"
step bench_frame 400 "$hv" bench --frame --frames "$frames" --report "$out/bench_frame.md"
[ "$quick" = 1 ] && exit 0

big=(--size 1280x720 --frames "$frames")
# Shadows: the light pass's and frame's extra cost per filter and shadowed light (cached maps).
step bench_shadows 200 "$hv" bench --frame --shadow-sweep "${big[@]}" --scene samples/scenes/shadows.json
step bench_shadows_default 200 "$hv" bench --frame --shadow-sweep "${big[@]}" \
  --scene samples/scenes/default.json
# Ambient occlusion at its default quality, half and full resolution.
step bench_gtao 200 "$hv" bench --frame "${big[@]}" --scene samples/scenes/default.json \
  --settings 'ao="gtao"' --settings 'ao="gtao",ao_resolution="full"'
# The error budget against the scene's own settings and against ltc everywhere.
for s in many_lights area_lights; do
  step "bench_budget_$s" 200 "$hv" bench --frame "${big[@]}" --scene "samples/scenes/$s.json" \
    --settings max_error=0.05 --settings 'sphere_specular="ltc"'
done
# A handful to a thousand lights: the bench scenes, and culling per stage where lights are large.
for n in 4 32 256 1024; do
  for r in 5m 1p5m; do
    step "bench_floor_${n}_$r" 200 "$hv" bench --frame "${big[@]}" \
      --scene "samples/bench/floor_spheres_${n}_lights_$r.json"
  done
done
for n in 256 1024; do
  step "bench_cull_stages_$n" 200 "$hv" bench --frame --cull-stages "${big[@]}" \
    --scene "samples/bench/floor_spheres_${n}_lights_5m.json"
done
# Where tiled culling starts to pay on this GPU (culling: auto's crossover is llvmpipe's).
for n in 4 32 256 1024; do
  for r in 5m 1p5m; do
    step "bench_vs_brute_${n}_$r" 200 "$hv" bench --frame --vs-brute "${big[@]}" \
      --scene "samples/bench/floor_spheres_${n}_lights_$r.json"
  done
done
for t in gl ibl render eval app; do
  bin=$(dirname "$hv")/tests/test_$t
  [ -x "$bin" ] && step "test_$t" 300 "$bin" --gtest_brief=1
done
exit 0
