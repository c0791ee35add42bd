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
# --blend (before HALFVEC): for blended models, instead, each model is composited over the sample
# viewer's own background (its Material_AlphaMask_03 sample image: the same camera, every fragment
# discarded) as that viewer composites, from three renders: the model, the model with every
# material opaque (a copy of its .gltf in OUTDIR) and no model (blend_composite.py says how).
#
# Usage: tools/gltf_sample_compare.sh [--blend] HALFVEC OUTDIR MODEL.gltf...
set -euo pipefail
blend=0
if [ "${1:-}" = --blend ]; then blend=1; shift; fi
exe=$1 out=$2
shift 2
mkdir -p "$out"
here=$(cd "$(dirname "$0")" && pwd)
assets=${HV_ASSETS_DIR:-$here/../../shared/assets}
env_hdr=$assets/env/studio_small_03_1k.hdr
background=$assets/gltf-asset-generator/Positive/Material_AlphaMask/Figures/SampleImages/Material_AlphaMask_03.png
# render MODEL OUT_STEM [options]: the sample images' camera, lighting and output transform.
render() {
  local model=$1 stem=$2
  shift 2
  "$exe" render "$model" --size 400x400 --out "$stem.png" --aa none \
    --env "$env_hdr" --set 'camera.position=[0,0,1.3]' --set 'camera.target=[0,0,0]' \
    --set 'camera.fov_y_deg=45' --set 'lights=[]' --set 'settings.tone_map="pbr_neutral"' \
    --set 'settings.gamma="srgb"' --set 'settings.dither=false' "$@" >/dev/null 2>"$stem.log"
}
for model in "$@"; do
  name=$(basename "$model" .gltf)
  expected=$(dirname "$model")/Figures/SampleImages/$name.png
  if [ "$blend" = 0 ]; then
    render "$model" "$out/$name"
    printf '%-40s %s\n' "$name" \
      "$(python3 "$here/sample_image_rmse.py" "$out/$name.png" "$expected" 40 40 360 360)"
    continue
  fi
  # The opaque copy: the same files, every material's alphaMode OPAQUE.
  src=$(cd "$(dirname "$model")" && pwd)
  copy=$out/opaque_$name
  rm -rf "$copy" && mkdir -p "$copy"
  for f in "$src"/*; do ln -s "$f" "$copy/$(basename "$f")"; done
  rm "$copy/$name.gltf"
  python3 - "$src/$name.gltf" "$copy/$name.gltf" <<'PY'
import json, sys
g = json.load(open(sys.argv[1]))
for m in g.get("materials", []):
    m["alphaMode"] = "OPAQUE"
json.dump(g, open(sys.argv[2], "w"))
PY
  render "$model" "$out/$name" --hdr "$out/$name.pfm"
  render "$copy/$name.gltf" "$out/${name}_opaque" --hdr "$out/${name}_opaque.pfm"
  render "$model" "$out/${name}_empty" --hdr "$out/${name}_empty.pfm" --set 'objects=[]'
  printf '%-40s %s\n' "$name" "$(python3 "$here/blend_composite.py" "$out/$name.pfm" \
    "$out/${name}_opaque.pfm" "$out/${name}_empty.pfm" "$out/${name}_opaque.png" "$expected" \
    "$background" 40 40 360 360)"
done
