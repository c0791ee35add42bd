#!/usr/bin/env bash
# Renders the default sample scene headless: installs what is missing, builds, renders.
# The image lands in out/default.png; per-pass GPU times are printed and kept in out/default.json.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
./build/halfvec render samples/scenes/default.json --out out/default.png --hdr out/default.pfm \
  --stats out/default.json "$@"
