// Resource slots and tile sizes every pass agrees on, written once: the shaders include this file
// (through frame.glsl) and so does the renderer's C++ (halfvec/render/frame_data.hpp,
// engine/render/src/passes.hpp), as "halfvec/shaders/common/bindings.glsl". Plain #defines only,
// so that both languages read the same numbers (zeux/niagara's config.h does the same).
#ifndef HV_BINDINGS_GLSL
#define HV_BINDINGS_GLSL

// ---- Uniform blocks ----------------------------------------------------------------------------
#define HV_UBO_FRAME 0        // FrameBlock (frame.glsl), bound for the whole frame
#define HV_UBO_ENVIRONMENT 1  // EnvironmentBlock (ambient.comp): SH9, mip count, presence
#define HV_UBO_MATERIAL 2     // MaterialBlock (material.glsl): the draw's material, bound per draw
#define HV_UBO_CULL_BATCH 3   // light culling: the dispatch's CullBatch (cull_layout.glsl)
#define HV_UBO_SUN_SHADOWS 4  // light and forward passes: the directional lights' shadow maps

// ---- Storage buffers ---------------------------------------------------------------------------
// At most 8 binding points (0..7: GL 4.5's minimum of GL_MAX_SHADER_STORAGE_BUFFER_BINDINGS), so a
// pass may give a slot another meaning than a pass that does not run at the same time.
#define HV_BINDING_CULL_MASKS 0       // culling: per group of tiles, its light mask
#define HV_BINDING_CULL_TILE_STATE 1  // culling (batched): per tile, counts then write cursors
#define HV_BINDING_LIGHTS 2
#define HV_BINDING_CULL_LIGHTS 3  // culling: per light, its view-space sphere and tile rectangle
#define HV_BINDING_TILE_RANGES 4
#define HV_BINDING_TILE_INDICES 5
#define HV_BINDING_TILE_TYPES 6   // per tile: (points, spheres) of its range, tubes follow
#define HV_BINDING_CULL_BOUNDS 7  // culling: per tile, block and group, the surface AABB
#define HV_BINDING_FORWARD_LIGHTS 3  // forward pass: per blended draw, the lights that reach it
#define HV_BINDING_SHADOW_MASK_LIGHTS 4  // shadow mask pass: per dispatch layer, its light
#define HV_BINDING_SHADOW_FALLBACK 5  // shadow resolve: the indirect dispatch, then its groups
#define HV_BINDING_EMITTERS 0          // emitter culling: every sphere and tube light's instance
#define HV_BINDING_VISIBLE_EMITTERS 1  // emitter culling: those that can cover a pixel, drawn
#define HV_BINDING_EMITTER_DRAW 2      // emitter culling: the indirect draw, instances counted
#define HV_BINDING_EMITTER_GROUPS 3    // emitter culling: per workgroup, counts then offsets
// The tile index list starts with a header of this many uints (the first: the total entries).
#define HV_TILE_LIST_HEADER_UINTS 4
// The shadow mask (`shadow_resolution: half`) holds the directional lights' visibility in its
// first HV_SHADOW_MASK_SUN_LAYERS layers (hv::kMaxDirectionalLights, checked in C++), then at
// most HV_SHADOW_MASK_MAX_CUBES lights with a cube (half resolution, R8: 0.23 MB a layer at
// 1280 x 720); shadowed lights beyond render unshadowed, with a warning naming them.
#define HV_SHADOW_MASK_SUN_LAYERS 4
#define HV_SHADOW_MASK_MAX_CUBES 32

// ---- Texture units of the passes that read the G-buffer -----------------------------------------
// The four G-buffer targets, bound together by bindGBuffer (engine/render/src/passes.hpp).
#define HV_UNIT_BASE_CAVITY 0
#define HV_UNIT_MATERIAL 1
#define HV_UNIT_NORMAL 2
#define HV_UNIT_DEPTH 3
// Light pass: the light records and the tile index list as buffer textures (HV_LIGHTS_TEXTURE).
#define HV_UNIT_LIGHT_TEXELS 4
#define HV_UNIT_TILE_INDEX_TEXELS 5
// Light pass with an LTC light mode: the LTC table's two textures on units 6 and 7
// (HV_LTC_TEXTURE_UNIT0 / UNIT1, defined in ltc.glsl, which the C++ reference also compiles).
// Ambient pass: the environment's prefiltered radiance, env BRDF table and irradiance cube.
#define HV_UNIT_RADIANCE 5
#define HV_UNIT_ENV_BRDF 6
#define HV_UNIT_IRRADIANCE 7
// Light pass with shadowed lights: the shadow atlas (a depth cube map array) twice, raw distances
// and with depth comparison (shaders/common/shadows.glsl, engine/render/src/shadow_pass.cpp).
#define HV_UNIT_SHADOW_DEPTH 8
#define HV_UNIT_SHADOW_COMPARE 9
// `shadow_resolution: half` (shadow_mask.glsl): the light pass reads the resolved visibility (a
// 2D array, one layer per shadowed light, shadowMaskLayer) on the first unit; the shadow mask
// pass's resolve step reads the half-resolution mask there and its texels' inverse view
// distance and normal on the second. The units the forward pass's environment takes.
#define HV_UNIT_SHADOW_MASK 11
#define HV_UNIT_SHADOW_MASK_GEOMETRY 12
// Ambient pass with `ao: gtao`: the AO pass's output (ao_denoise.comp); unit 4 is free there. The
// AO pass's denoise reads the raw AO on the same unit.
#define HV_UNIT_AO 4
// Forward pass of blended surfaces (forward.frag): the material's textures on units 0..4, the
// LTC table on 6 and 7 and the shadow atlas on 8 and 9 as above, so the environment moves here.
#define HV_UNIT_FORWARD_RADIANCE 10
#define HV_UNIT_FORWARD_ENV_BRDF 11
#define HV_UNIT_FORWARD_IRRADIANCE 12
// Light and forward passes with a shadowed directional light: its orthographic maps (a 2D depth
// array), raw depth and with depth comparison (shadows.glsl, sunShadowVisibility).
#define HV_UNIT_SUN_SHADOW_DEPTH 13
#define HV_UNIT_SUN_SHADOW_COMPARE 14
// Light, ambient and debug-view passes of a scene with clear coat: the G-buffer's coat target
// (gbuffer.glsl, encodeCoat), bound by bindGBuffer with the other four.
#define HV_UNIT_COAT 15
// Light pass with an error budget (settings.max_error): its table (error_budget.glsl), on a unit
// the light pass leaves free; the forward pass reads it on unit 5, which it leaves free.
#define HV_UNIT_ERROR_TABLE 10
#define HV_UNIT_FORWARD_ERROR_TABLE 5
// Debug views: the predicted_error view's light-pass output, the HDR target (debug_view.frag).
#define HV_UNIT_DEBUG_HDR 4
// Tone map: the HDR target.
#define HV_UNIT_HDR 0
// G-buffer pass: a material's textures on units HV_UNIT_MATERIAL_TEXTURES + 0..7 (base color,
// metal-rough, normal, occlusion, emissive, then the clear coat's weight, roughness and normal:
// the slots HV_MAT_SLOT_*). The forward pass binds the first HV_FORWARD_MATERIAL_TEXTURES of
// them: its other units (LTC, shadows, environment) leave no room for the coat's, so a blended
// coat takes its factors alone.
#define HV_UNIT_MATERIAL_TEXTURES 0
#define HV_MATERIAL_TEXTURE_COUNT 8
#define HV_FORWARD_MATERIAL_TEXTURES 5

// ---- Image units -------------------------------------------------------------------------------
#define HV_IMAGE_HDR 0    // the RGBA16F accumulation target the compute passes add into
#define HV_IMAGE_FLOOR 1  // the floor pass's scratch target (DebugOptions::floor_pass)
#define HV_IMAGE_AO 2     // the AO pass's targets: raw (gtao.comp), then denoised (ao_denoise.comp)
#define HV_IMAGE_READBACK 1  // Renderer::readGBuffer's decoded base color (gbuffer_decode.comp)
#define HV_IMAGE_SHADOW_MASK 3           // the shadow mask's visibility (one layer a light)
#define HV_IMAGE_SHADOW_MASK_GEOMETRY 4  // and its texels' inverse view distance and normal

// ---- Uniform locations (explicit, so the C++ never looks a name up) ------------------------------
#define HV_LOC_MODEL 0          // gbuffer.vert: object to world
#define HV_LOC_NORMAL_MATRIX 1  // gbuffer.vert: inverse transpose of the model matrix
#define HV_LOC_SHADOW_VIEW_PROJ 3  // shadow.vert: the cube face's view-projection
#define HV_LOC_SHADOW_LIGHT 4      // shadow.frag: light center, 1 / far
#define HV_LOC_AO_PARAMS 5         // gtao.comp, ao_denoise.comp: radius (m), scale, AO size
#define HV_LOC_FORWARD_LIGHTS 6    // forward.frag: the draw's range of HV_BINDING_FORWARD_LIGHTS
#define HV_LOC_SHADOW_MASK_LIGHTS 7  // shadow_resolve.comp: the shadowed lights to resolve

// ---- FrameBlock::frame_flags bits (hv::render::FrameFlag), set for the per-term debug views ---
#define HV_FRAME_NO_BACKGROUND 1u  // background pixels stay black (ambient.comp)
#define HV_FRAME_NO_EMISSIVE 2u    // no emissive in the HDR target (C++ masks the G-buffer write)

// ---- Tiles -------------------------------------------------------------------------------------
// Light culling tile: HV_TILE_SIZE x HV_TILE_HEIGHT pixels (also the light pass's workgroup;
// the ambient pass uses HV_TILE_SIZE square groups). Why 8 x 4: docs/lights.md "Tiled culling".
#define HV_TILE_SIZE 8
#define HV_TILE_HEIGHT 4
// Tiles per workgroup of the light pass (stacked vertically, each with its own light list): with
// 4 pixels per invocation a tile is 8 invocations, which alone would fill a quarter of a 32-wide
// GPU SIMD unit. 8 tiles = 64 invocations. Neutral on llvmpipe (1, 2, 4, 8: same time, measured).
#define HV_LIGHT_GROUP_TILES 8
// Light culling: a workgroup culls a group of HV_CULL_GROUP_TILES x HV_CULL_GROUP_TILES tiles (64 x
// 32 pixels), one invocation per tile, the unit the lights are binned into (docs/lights.md "Tiled
// culling").
#define HV_CULL_GROUP_TILES 8
// Group rows per invocation of the binning stage: a light is binned by one invocation per band.
#define HV_CULL_BIN_GROUP_ROWS 4
// Up to this many lights are binned and walked in one step; above, in batches of this many lights
// (count, reserve, fill; docs/lights.md). A batch bounds the masks' memory and the loop
// iterations of one invocation (at most about 2 per light of the batch): llvmpipe ends any shader
// invocation's loops after 65,535 iterations in all, silently.
#define HV_CULL_FUSED_MAX_LIGHTS 16384

#endif
