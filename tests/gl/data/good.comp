#version 450 core
#include "good_inc.glsl"
layout(local_size_x = 1) in;
layout(std430, binding = 0) buffer Out { float values[]; };
void main() { values[0] = twice(VALUE); }
