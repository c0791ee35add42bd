// The tiled culling's layout, shared by the culling stages (shaders/passes/light_cull_*.comp)
// and the renderer that sizes their buffers and dispatches them (engine/render/src/
// light_cull_pass.cpp): the tile blocks, the per-light and per-batch records, the buffer strides.
// Compiled as C++ too (halfvec/shading/glsl.hpp rules); plain #defines and plain structs only.
#ifndef HV_CULL_LAYOUT_GLSL
#define HV_CULL_LAYOUT_GLSL

#include "bindings.glsl"

// A group of HV_CULL_GROUP_TILES x HV_CULL_GROUP_TILES tiles is one workgroup, one invocation per
// tile, split into blocks of HV_CULL_BLOCK_W x HV_CULL_BLOCK_H tiles: a block's 8 tiles are 8
// consecutive invocations, one SIMD vector on an 8-wide implementation (llvmpipe), so that its
// walk of the block's mask does not diverge.
#define HV_CULL_GROUP_SIZE (HV_CULL_GROUP_TILES * HV_CULL_GROUP_TILES)  // tiles = invocations
#define HV_CULL_BLOCK_W 2                                              // tiles
#define HV_CULL_BLOCK_H 4
#define HV_CULL_BLOCK_TILES (HV_CULL_BLOCK_W * HV_CULL_BLOCK_H)
#define HV_CULL_BLOCKS_X (HV_CULL_GROUP_TILES / HV_CULL_BLOCK_W)
#define HV_CULL_BLOCKS (HV_CULL_GROUP_SIZE / HV_CULL_BLOCK_TILES)
// The most lights the single-dispatch culling of a handful of lights takes (light_cull_few.comp:
// one light record per invocation of a group); the renderer's threshold is at most this.
#define HV_CULL_FEW_MAX_LIGHTS 64
// The binning stage's workgroup: this many lights of a batch (per band of group rows).
#define HV_CULL_BIN_LIGHTS 64

// The bounds buffer holds surface AABBs of HV_CULL_BOX_VEC4S vec4s each (min xyz and 1 if any
// surface, max xyz and 0): one per tile, then per group HV_CULL_BLOCKS block boxes, then per group
// one group box.
#define HV_CULL_BOX_VEC4S 2
#define HV_CULL_BOXES_PER_GROUP (HV_CULL_BLOCKS + 1)

// A tile rectangle packs a tile coordinate in 16 bits: x0 | y0 << 16, x1 | y1 << 16 (tile
// coordinates < 2^14 for viewports <= 16384 pixels wide or high). An empty rectangle (x0 > x1):
// a light that touches no tile.
#define HV_CULL_RECT_SHIFT 16u
#define HV_CULL_RECT_MASK 0xFFFFu
#define HV_CULL_RECT_EMPTY 0xFFFFu

// Per light, written by the binning stage: the view-space bounding sphere (center xyz, culling
// radius w), the packed tile rectangle (x, y: see above), its light type (z: HV_LIGHT_POINT,
// SPHERE or TUBE) and one unused word; for a spot its cone for the cone-versus-tile test (cull.glsl,
// sphereOutsideCone): apex (view space) and range, unit axis (view space) and the outer angle's
// cosine; apex.w = 0 for every other light (no cone test).
struct CullLight {
  vec4 sphere;
  uvec4 rect;
  vec4 cone_apex;
  vec4 cone_axis;
};

// One dispatch's lights, a batch [first, end), and the per-group mask layout: mask_words words of
// one bit per light of the batch, preceded by summary_words words of one bit per mask word.
// Bound per dispatch as a range of one uniform buffer (binding HV_UBO_CULL_BATCH).
struct CullBatch {
  uint first;
  uint end;
  uint mask_words;
  uint summary_words;
};

// Batched stages: per tile, its counts per type, then its write cursors per type (uvec4).
#define HV_CULL_TILE_STATE_UINTS 4

#endif
