// The material block the G-buffer pass reads (uniform block HV_UBO_MATERIAL). Its record,
// GpuMaterial, is declared once for GLSL and C++ in gpu_records.glsl (filled by
// hv::render::packMaterial).
#ifndef HV_MATERIAL_GLSL
#define HV_MATERIAL_GLSL

#include "gpu_records.glsl"
#include "material_features.glsl"

// The draw's material: GpuScene keeps every material in one buffer and the G-buffer pass binds the
// draw's range (glBindBufferRange), so the values are uniform across the draw. A storage buffer
// indexed by a material uniform was gathered per pixel on llvmpipe (docs/performance.md "The
// material as uniforms").
layout(std140, binding = HV_UBO_MATERIAL) uniform MaterialBlock {
  GpuMaterial u_material;
};

#endif
