// The members of FrameBlock (binding HV_UBO_FRAME), the per-frame values every pass may read,
// listed once for both languages (zeux/niagara's src/shaders/mesh.h shares its structs the same
// way): HV_BLOCK_MEMBER(type, name) lines that the includer defines before it includes this file
// inside its declaration:
//  - GLSL (frame.glsl) declares `type u_name;` in the uniform block;
//  - C++ (halfvec/render/frame_data.hpp, hv::render::FrameBlock) declares `glm::type name;` in a
//    struct whose static_asserts hold the std140 offsets.
// A member added, removed or moved here changes both. No include guard: the shader include
// resolver takes a file once per stage, and C++ includes it once, inside the struct.
// std140: a vec4, uvec4 or mat4 sits on a 16-byte boundary and the four uints after `viewport`
// fill one 16-byte row, so neither language pads.
HV_BLOCK_MEMBER(mat4, view)
HV_BLOCK_MEMBER(mat4, proj)
HV_BLOCK_MEMBER(mat4, view_proj)
HV_BLOCK_MEMBER(mat4, inv_view_proj)
HV_BLOCK_MEMBER(vec4, camera_pos)     // xyz world position
HV_BLOCK_MEMBER(uvec4, viewport)      // width, height, tiles x, tiles y
HV_BLOCK_MEMBER(uint, light_count)
HV_BLOCK_MEMBER(uint, tile_capacity)  // entries the tile index list holds after its header
HV_BLOCK_MEMBER(uint, debug_view)     // hv::DebugView (debug_view.frag)
HV_BLOCK_MEMBER(uint, frame_flags)    // HV_FRAME_* bits (bindings.glsl)
// exposure, dither strength, environment intensity, environment rotation (rad)
HV_BLOCK_MEMBER(vec4, output)
// near plane, settings.max_error (error_budget.glsl; 0: no budget), settings.ao_radius (the
// traced specular occlusion's reach, ambient.comp), unused
HV_BLOCK_MEMBER(vec4, frame_params)
// The directional lights (HV_LIGHT_DIRECTIONAL), which the culling does not bin: their indices in
// the light buffer + 1, in scene order, 0 after the last (at most hv::kMaxDirectionalLights, the
// four components). The light and forward passes loop over them at every lit pixel.
HV_BLOCK_MEMBER(uvec4, directional_lights)
