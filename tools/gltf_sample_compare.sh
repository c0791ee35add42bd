#!/usr/bin/env bash
# Renders glTF-Asset-Generator models as their sample images were made (the manifest's camera at
# z = 1.3 looking at the origin, 45 degree vertical field of view, 400x400; image-based lighting
# only; PBR Neutral, sRGB, no dither, no FXAA) and prints the relative RMSE of each against its
# Figures/SampleImages PNG over the central box [40, 360)^2, inside the 1x1 quad of every model
# compared here. Only --set options are used, so any build of halfvec renders the same scene
# (a build before `--look gltf` included).
#
# Also prints the gain-fitted relative RMSE and the chromaticity distance (sample_image_rmse.py),
# which an overall difference of brightness does not move.
#
# Usage: tools/gltf_sample_compare.sh HALFVEC OUTDIR MODEL.gltf...
set -euo pipefail
exe=$1 out=$2
shift 2
mkdir -p "$out"
here=$(cd "$(dirname "$0")" && pwd)
env_hdr=${HV_ASSETS_DIR:-$here/../../shared/assets}/env/studio_small_03_1k.hdr
for model in "$@"; do
  name=$(basename "$model" .gltf)
  expected=$(dirname "$model")/Figures/SampleImages/$name.png
  "$exe" render "$model" --size 400x400 --out "$out/$name.png" --aa none --env "$env_hdr" \
    --set 'camera.position=[0,0,1.3]' --set 'camera.target=[0,0,0]' --set 'camera.fov_y_deg=45' \
    --set 'lights=[]' --set 'settings.tone_map="pbr_neutral"' --set 'settings.gamma="srgb"' \
    --set 'settings.dither=false' >/dev/null 2>"$out/$name.log"
  printf '%-40s %s\n' "$name" "$(python3 "$here/sample_image_rmse.py" "$out/$name.png" "$expected" 40 40 360 360)"
done
