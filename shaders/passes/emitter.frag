#version 450 core
// Emitter geometry: the light's surface radiance, unlit (emitter.vert).
layout(location = 0) flat in vec3 v_radiance;
layout(location = 0) out vec4 o_hdr;

void main() { o_hdr = vec4(v_radiance, 1.0); }
