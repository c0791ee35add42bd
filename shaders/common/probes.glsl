// Benchmark probes of the light pass (render::LightPassProbe, `halfvec bench --breakdown`), shared
// with the C++ so the tests can recompute what a probe build stores. Compiled as C++ too
// (halfvec/shading/glsl.hpp rules).
#ifndef HV_PROBES_GLSL
#define HV_PROBES_GLSL

#include "brdf.glsl"
#include "lights.glsl"

// What a probe build adds per pixel in place of the shading: a sum over every field of the
// per-pixel setup (Surface and ShadingPoint), so that the compiler cannot drop any of the work a
// probe claims to include (the G-buffer fetches, the position reconstruction, the view vector,
// the surface parameters), and so that a test can check from the stored value that it ran. Each
// term is of order 1 (positions scaled by 1e-2): the sum stays well inside half-float range.
vec3 setupProbeValue(Surface s, ShadingPoint sp) {
  return abs(s.N) + s.diffuse_color + s.f0 + vec3(s.roughness, s.alpha, s.cavity) +
         abs(sp.P) * 0.01f + abs(sp.V) + abs(sp.R) + vec3(sp.NoV);
}

#endif
