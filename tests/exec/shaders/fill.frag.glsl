#version 450 core
// Raster test pass: value + 0.001 * x pixel index, so read-back checks positions too.
uniform float u_value;
layout(location = 0) out vec4 colour;
void main() { colour = vec4(u_value + 0.001 * floor(gl_FragCoord.x), 0.0, 0.0, 1.0); }
