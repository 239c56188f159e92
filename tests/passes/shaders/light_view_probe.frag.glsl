#version 450 core
// light_view_pass_test: the author's side of a light-view pass. Writes the fragment's window
// depth and 1 (covered); the pass clears the target to (1, -1, 0, 0) where nothing is drawn.
#include "shadow_map/caster_material.glsl"
#include "common/shadow_common.glsl"
layout(location = 0) out vec4 o_probe;
void main() {
  discard_uncovered();
  o_probe = vec4(gl_FragCoord.z, 1.0, light_distance(gl_FragCoord.z), 0.0);
}
