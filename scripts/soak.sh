#!/usr/bin/env bash
# Soak test, about 30 minutes on llvmpipe:
#  1. HV_SOAK_FRAMES (default 3000) frames of many_lights in one process and HV_SOAK_RELOADS
#     (default 300) headless reloads of the glTF sample through the viewer's SceneReloader, with
#     RSS and live GL objects (tests/app/test_soak.cpp, the suite runs short versions);
#  2. the viewer itself under Xvfb: `halfvec view` on a copy of samples/scenes/gltf.json whose
#     modification time is changed VIEWER_RELOADS (default 300) times, each reload waited for;
#     after each, the viewer's VmRSS (from /proc) and live GL objects (printed by the reloader)
#     go to out/soak/viewer_reloads.csv.
# Passes when the peak RSS after the first 20 reloads (after frame 500 for the frames) stays
# within 2% of the peak before, and live GL objects stay constant.
# Usage: bash scripts/soak.sh [--frames N] [--reloads N] [--viewer-only]
set -euo pipefail
cd "$(dirname "$0")/.."
frames=3000
reloads=300
viewer_only=0
while [ $# -gt 0 ]; do
  case "$1" in
    --frames) frames="$2"; shift 2 ;;
    --reloads) reloads="$2"; shift 2 ;;
    --viewer-only) viewer_only=1; shift ;;
    -h|--help) sed -n '2,13p' "$0"; exit 0 ;;
    *) echo "unknown option $1" >&2; exit 2 ;;
  esac
done
bash scripts/build.sh >/dev/null
if [ -d ../shared/assets ]; then export HV_ASSETS_DIR="$(cd ../shared/assets && pwd)"; fi
mkdir -p out/soak
status=0
if [ $viewer_only = 0 ]; then
  HV_SOAK_FRAMES=$frames HV_SOAK_RELOADS=$reloads build/tests/test_app --gtest_filter='Soak.*' \
    | tee out/soak/test_soak.log | grep -E '\[ soak \].*(->|frame [0-9]*000:)|OK|FAILED|SKIPPED' || true
  grep -q 'FAILED' out/soak/test_soak.log && status=1
fi

# The viewer under Xvfb.
xvfb_pid=""
if [ -z "${DISPLAY:-}" ]; then
  for d in $(seq 90 140); do
    [ -e /tmp/.X11-unix/X$d ] || [ -e /tmp/.X$d-lock ] && continue
    Xvfb :$d -screen 0 1280x1024x24 -nolisten tcp >/dev/null 2>&1 &
    xvfb_pid=$!
    export DISPLAY=:$d
    for _ in $(seq 100); do [ -e /tmp/.X11-unix/X$d ] && break; sleep 0.1; done
    break
  done
fi
scene=out/soak/gltf.json
cp samples/scenes/gltf.json "$scene"
log=out/soak/viewer.log
build/halfvec view "$scene" --size 320x180 --frames 100000000 > "$log" 2>&1 &
viewer=$!
cleanup() { kill $viewer 2>/dev/null || true; [ -n "$xvfb_pid" ] && kill $xvfb_pid 2>/dev/null || true; }
trap cleanup EXIT
csv=out/soak/viewer_reloads.csv
echo "reload,rss_mb,live_gl_objects" > "$csv"
base=$(date +%s)
for i in $(seq 1 "$reloads"); do
  touch -d "@$((base + i))" "$scene"
  for _ in $(seq 600); do  # up to 60 s per reload
    [ "$(grep -c '^reloaded' "$log" || true)" -ge "$i" ] && break
    kill -0 $viewer 2>/dev/null || { echo "viewer exited:" >&2; tail -5 "$log" >&2; exit 1; }
    sleep 0.1
  done
  sleep 1  # let the viewer draw a few frames with the new scene (deferred frees)
  rss=$(awk '/^VmRSS/ { printf "%.1f", $2 / 1024 }' /proc/$viewer/status)
  gl=$(grep '^reloaded' "$log" | tail -1 | sed 's/.*live GL objects: \([0-9]*\).*/\1/')
  echo "$i,$rss,$gl" >> "$csv"
  if [ $((i % 25)) = 0 ]; then echo "[ soak ] viewer reload $i: RSS $rss MB, live GL objects $gl"; fi
done
# Peak RSS during the first 20 reloads vs after them (a sample may or may not include the
# driver's deferred frees of the previous scene: peaks are compared), live GL objects constant.
awk -F, 'NR == 1 { next } NR <= 21 { if ($2 > warm) warm = $2; gl = $3; next }
  { if ($2 > after) after = $2; if ($3 != gl) glchanged = 1; n++ }
  END { if (!n) { print "[ soak ] viewer reloads: fewer than 21, nothing to compare"; exit 0 }
        growth = 100 * (after / warm - 1)
        printf "[ soak ] viewer reloads: peak RSS %.1f MB in reloads 1-20, %.1f MB in 21-%d (%+.2f%%), live GL objects %s\n", warm, after, n + 20, growth, glchanged ? "CHANGED" : "constant"
        exit (growth > 2 || glchanged) }' "$csv" || status=1
exit $status
