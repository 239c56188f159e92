#version 450 core
#include "gbuffer/gbuffer_read.glsl"
in vec3 v_normal;
in vec2 v_uv;
in float v_view_depth;
uniform vec4 u_base_color;
uniform int u_has_texture;
uniform sampler2D u_base_texture;
uniform float u_alpha_cutoff;  // < 0: opaque
layout(location = 0) out float out_depth;   // linear view depth (> 0; cleared to 0 = background)
layout(location = 1) out vec2 out_normal;   // octahedral world normal
layout(location = 2) out vec4 out_albedo;
void main() {
  vec4 base = u_base_color;
  if (u_has_texture != 0) base *= texture(u_base_texture, v_uv);
  if (u_alpha_cutoff >= 0.0 && base.a < u_alpha_cutoff) discard;
  vec3 n = normalize(v_normal);
  // Double-sided surfaces seen from behind face the camera.
  if (!gl_FrontFacing) n = -n;
  out_depth = v_view_depth;
  out_normal = encode_normal(n);
  out_albedo = vec4(base.rgb, 1.0);
}
