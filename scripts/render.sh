#!/usr/bin/env bash
# Renders the default sample scene headless: installs what is missing, builds, renders.
# The image lands in out/default.png; per-pass GPU times are printed and kept in out/default.json.
# Only the `halfvec` program and the libraries it links are built (not the tests, the tools or
# the build-time shader check: scripts/test.sh builds those), so the first picture comes sooner.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh halfvec
./build/halfvec render samples/scenes/default.json --out out/default.png --hdr out/default.pfm \
  --stats out/default.json "$@"
