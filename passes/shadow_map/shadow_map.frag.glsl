#version 450 core
// Depth only: the fixed-function depth write is the shadow map.
//
// LINEAR_FACE_DEPTH (a point light's six faces, scene/light_faces.h): the depth written is the
// distance along the face's axis, linear between near and far ((d - near) / (far - near)), as a
// directional light's is, instead of the perspective window depth. The faces' near plane is
// 1e-3 of the far one (a caster may hang beside the lamp), and with a hyperbolic depth a
// window-depth bias of 2e-4 would be 0.3 m at 3 m. The fixed-function polygon offset does not
// apply to a written depth, so it is applied here with glPolygonOffset's own terms: factor x the
// depth's largest slope per pixel + units x the smallest step of a float depth near it.
#include "shadow_map/caster_material.glsl"
#ifdef LINEAR_FACE_DEPTH
uniform float u_light_near;      // world units
uniform float u_light_far;
uniform float u_slope_bias;      // glPolygonOffset factor
uniform float u_constant_bias;   // glPolygonOffset units
#endif
void main() {
  discard_uncovered();
#ifdef LINEAR_FACE_DEPTH
  float z = (1.0 / gl_FragCoord.w - u_light_near) / (u_light_far - u_light_near);
  float slope = max(abs(dFdx(z)), abs(dFdy(z)));
  float step = exp2(floor(log2(max(z, 1e-30))) - 23.0);
  gl_FragDepth = clamp(z + u_slope_bias * slope + u_constant_bias * step, 0.0, 1.0);
#endif
}
