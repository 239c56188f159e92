#version 450 core
// Depth only; alpha-masked casters (leaves, fences) are alpha-tested here too, so their holes
// let light through exactly as the camera sees them.
in vec2 v_uv;
uniform vec4 u_base_color;
uniform int u_has_texture;
uniform sampler2D u_base_texture;
uniform float u_alpha_cutoff;
void main() {
  if (u_alpha_cutoff >= 0.0) {
    float a = u_base_color.a * (u_has_texture != 0 ? texture(u_base_texture, v_uv).a : 1.0);
    if (a < u_alpha_cutoff) discard;
  }
}
