#version 450 core
// Depth into the depth attachment (with the polygon offset, as every shadow map here) and the
// texel's defaults into the extended map (esm_common.glsl): no edge yet (r = u_no_edge,
// b = u_no_edge_depth, mask 0) and the unbiased occluder depth in g. Alpha-masked casters are
// alpha-tested like passes/shadow_map, so their holes let light through.
in vec2 v_uv;
in vec4 v_clip;
uniform vec4 u_base_color;
uniform int u_has_texture;
uniform sampler2D u_base_texture;
uniform float u_alpha_cutoff;
uniform float u_no_edge;        // r of a texel without a quad: 0 (MAX-neutral) or the paper's default
uniform float u_no_edge_depth;  // b of a texel without a quad: 0 (MAX-neutral) or the paper's far
layout(location = 0) out vec4 o_esm;
void main() {
  if (u_alpha_cutoff >= 0.0) {
    float a = u_base_color.a * (u_has_texture != 0 ? texture(u_base_texture, v_uv).a : 1.0);
    if (a < u_alpha_cutoff) discard;
  }
  o_esm = vec4(u_no_edge, v_clip.z / v_clip.w * 0.5 + 0.5, u_no_edge_depth, 0.0);
}
