#version 450 core
// Emitter culling (emitter_pass.cpp): keeps the sphere and tube lights whose capsule can cover a
// pixel center and compacts them, in light order, into the visible list the indirect draws read
// (grouped by capsule template), each template's count and first instance into its
// indirect draw.
// A capsule is the convex hull of its two end spheres, so its image lies in the union of their
// images' bounding boxes; an emitter whose box holds no pixel center (smaller than a pixel and
// between centers, or outside the viewport) cannot be rasterized and is dropped.
// Three stages (HV_EMITTER_CULL_STAGE), so that the order is the lights' order whatever the
// scheduling (emitters do not write depth: where two overlap, the one drawn last shows, as
// before the culling): 0 counts per workgroup, 1 scans the counts (one invocation), 2 writes.
#include "../common/frame.glsl"

#define GROUP 256
layout(local_size_x = GROUP) in;

struct EmitterInstance {
  vec4 center_radius;
  vec4 axis_half_length;
  vec4 color_intensity;
};
layout(std430, binding = HV_BINDING_EMITTERS) readonly buffer Emitters {
  EmitterInstance emitters[];
};
layout(std430, binding = HV_BINDING_VISIBLE_EMITTERS) writeonly buffer VisibleEmitters {
  EmitterInstance visible[];
};
// One DrawElementsIndirectCommand (count, instanceCount, firstIndex, baseVertex, baseInstance)
// per capsule template, coarsest first (draws[3 - k] for template k): emitters do not test each
// other's depth, so where two overlap the one drawn last shows, and the larger on screen (the
// finer template) is more often the nearer. Stage 1 sets instanceCount and baseInstance.
struct DrawCommand {
  uint index_count;
  uint instance_count;
  uint first_index;
  int base_vertex;
  uint base_instance;
};
layout(std430, binding = HV_BINDING_EMITTER_DRAW) buffer EmitterDraw {
  DrawCommand draws[4];
};
// Per workgroup: the emitters kept per template, then (stage 1) their offsets in the lists.
layout(std430, binding = HV_BINDING_EMITTER_GROUPS) buffer EmitterGroups {
  uvec4 group_counts[];
};
layout(location = 0) uniform uint u_emitter_count;

// The templates (emitter_pass.cpp, kLods): 24, 12, 8 and 4 segments around the axis. Template k
// is drawn at a projected radius up to kLodMaxRadiusPx[k]: a polygon of n sides inscribed in the
// sphere's outline lies within r (1 - cos(pi / n)) of it, 0.034 r, 0.076 r and 0.29 r for
// 12, 8, 4 sides, which these radii keep under 0.12 pixel.
const float kLodMaxRadiusPx[3] = float[3](3.5, 1.5, 0.4);

// Bounds of tan(angle) of a view-space circle (center (x, z), z the distance in front, radius r)
// seen from the origin: the tangent lines at angles atan(x / z) +- asin(r / |c|), whose tangents
// are (x t -+ r z) / (z t +- x r) with t = sqrt(|c|^2 - r^2) (Mara and McGuire 2013, "2D
// Polyhedral Bounds of a Clipped, Perspective-Projected 3D Sphere", section 4). False when the
// circle reaches the camera plane (unbounded image: the caller keeps the emitter).
bool tangentBounds(float x, float z, float r, out vec2 bounds) {
  const float t2 = x * x + z * z - r * r;
  if (z <= r || t2 <= 0.0) return false;
  const float t = sqrt(t2);
  const float den_lo = z * t + x * r, den_hi = z * t - x * r;
  if (den_lo <= 0.0 || den_hi <= 0.0) return false;
  bounds = vec2((x * t - r * z) / den_lo, (x * t + r * z) / den_hi);
  return true;
}

// The pixel box (x0, y0, x1, y1) of a sphere's image, or false when the image is unbounded (the
// sphere reaches the camera plane) or the sphere lies wholly behind the camera (`behind`).
bool sphereBox(vec3 center, float r, out vec4 box, out bool behind) {
  const vec3 v = (u_view * vec4(center, 1.0)).xyz;
  const float z = -v.z;  // the camera looks down -z
  behind = z < -r;
  vec2 bx, by;
  if (!tangentBounds(v.x, z, r, bx) || !tangentBounds(v.y, z, r, by)) return false;
  // NDC = P00 * tan - P20 (P20: an off-center or jittered frustum), then pixels.
  const vec2 size = vec2(u_viewport.xy);
  const vec2 ndc_x = u_proj[0][0] * bx - u_proj[2][0];
  const vec2 ndc_y = u_proj[1][1] * by - u_proj[2][1];
  box = vec4(ndc_x.x, ndc_y.x, ndc_x.y, ndc_y.y) * 0.5 + 0.5;
  box *= vec4(size, size);
  if (box.y > box.w) box = box.xwzy;  // a flipped y axis
  return true;
}

// 0: culled, else 1 + the template to draw it with (0: the finest).
uint classify(uint i) {
  if (i >= u_emitter_count) return 0u;
  const EmitterInstance e = emitters[i];
  const vec3 a = e.center_radius.xyz + e.axis_half_length.xyz * e.axis_half_length.w;
  const vec3 b = e.center_radius.xyz - e.axis_half_length.xyz * e.axis_half_length.w;
  const float r = e.center_radius.w;
  vec4 box_a, box_b;
  bool behind_a, behind_b;
  const bool bounded_a = sphereBox(a, r, box_a, behind_a);
  const bool bounded_b = sphereBox(b, r, box_b, behind_b);
  if (behind_a && behind_b) return 0u;          // the whole capsule behind the camera
  if (!bounded_a || !bounded_b) return 1u;      // reaches the camera plane: unbounded image
  // A pixel center (i + 0.5, j + 0.5) inside the box, with 1/64 pixel to spare (the template's
  // triangles lie inside the spheres; the margin covers rounding).
  const vec4 box =
      vec4(min(box_a.xy, box_b.xy), max(box_a.zw, box_b.zw)) + vec4(-1.0, -1.0, 1.0, 1.0) / 64.0;
  const vec2 lo = max(ceil(box.xy - 0.5), vec2(0.0));
  const vec2 hi = min(floor(box.zw - 0.5), vec2(u_viewport.xy) - 1.0);
  if (!all(lessThanEqual(lo, hi))) return 0u;
  // The projected radius: half the smaller side of an end sphere's box, the larger end's.
  const vec2 size_a = box_a.zw - box_a.xy, size_b = box_b.zw - box_b.xy;
  const float radius_px = 0.5 * max(min(size_a.x, size_a.y), min(size_b.x, size_b.y));
  uint lod = 0u;
  for (uint k = 0u; k < 3u; ++k) {
    if (radius_px <= kLodMaxRadiusPx[k]) lod = k + 1u;
  }
  return 1u + lod;
}

uvec4 flagOf(uint kind) {
  return uvec4(equal(uvec4(kind), uvec4(1u, 2u, 3u, 4u)));
}

shared uvec4 s_scan[GROUP];

void main() {
  const uint group = gl_WorkGroupID.x, local = gl_LocalInvocationID.x;
#if HV_EMITTER_CULL_STAGE == 1
  // One invocation: exclusive prefix sums of the groups' counts (per template), at most 4096
  // groups for the 1 Mi light budget (llvmpipe ends a loop after 65,535 iterations).
  if (local != 0u) return;
  const uint groups = (u_emitter_count + GROUP - 1u) / GROUP;
  uvec4 total = uvec4(0u);
  for (uint g = 0u; g < groups; ++g) {
    const uvec4 c = group_counts[g];
    group_counts[g] = total;
    total += c;
  }
  uint first = 0u;
  for (uint k = 0u; k < 4u; ++k) {
    draws[3u - k].instance_count = total[k];
    draws[3u - k].base_instance = first;
    first += total[k];
  }
#else
  const uint kind = classify(gl_GlobalInvocationID.x);
  // Inclusive scan of the per-template flags over the workgroup (Hillis and Steele 1986).
  s_scan[local] = flagOf(kind);
  barrier();
  for (uint d = 1u; d < GROUP; d *= 2u) {
    const uvec4 add = local >= d ? s_scan[local - d] : uvec4(0u);
    barrier();
    s_scan[local] += add;
    barrier();
  }
#if HV_EMITTER_CULL_STAGE == 0
  if (local == GROUP - 1u) group_counts[group] = s_scan[local];
#else
  if (kind != 0u) {
    const uint k = kind - 1u;
    const uint at = group_counts[group][k] + s_scan[local][k] - 1u;
    visible[draws[3u - k].base_instance + at] = emitters[gl_GlobalInvocationID.x];
  }
#endif
#endif
}
