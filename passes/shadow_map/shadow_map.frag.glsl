#version 450 core
// Depth only: the fixed-function depth write is the shadow map.
#include "shadow_map/caster_material.glsl"
void main() { discard_uncovered(); }
