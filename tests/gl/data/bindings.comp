#version 450 core
// tests/gl/test_bindings.cpp: reads storage slot 3 and texture unit 2, writes storage slot 0.
layout(local_size_x = 1) in;
layout(std430, binding = 0) buffer Out { float result[]; };
layout(std430, binding = 3) readonly buffer In { float source[]; };
layout(binding = 2) uniform sampler2D t_source;
void main() { result[0] = source[0] + texelFetch(t_source, ivec2(0), 0).r; }
