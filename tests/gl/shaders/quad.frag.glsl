#version 450 core
#include "constants.glsl"
layout(location = 0) out vec4 colour;
void main() { colour = vec4(0.25, gl_FragCoord.x, PI > 3.0 ? 0.0 : 1.0, 1.0); }
