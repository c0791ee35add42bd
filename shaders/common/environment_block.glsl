// The members of EnvironmentBlock (binding HV_UBO_ENVIRONMENT), written once per environment,
// listed once for both languages as frame_block.glsl lists FrameBlock's: HV_BLOCK_MEMBER(type,
// name) and HV_BLOCK_ARRAY(type, name, count) lines, declared `type u_name;` in GLSL
// (ambient.comp) and `glm::type name;` in C++ (engine/render/src/ambient_pass.cpp,
// EnvironmentBlock). std140: vec4 members and arrays of vec4 only (stride 16 in both languages).
HV_BLOCK_ARRAY(vec4, sh, 9)  // radiance SH9 (ibl.glsl order)
HV_BLOCK_MEMBER(vec4, env)   // max mip, env BRDF table size, 1 = environment present, unused
