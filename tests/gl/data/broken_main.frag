#version 450 core
#include "broken_inc.glsl"
out vec4 color;
void main() { color = vec4(helper(), 1.0); }
