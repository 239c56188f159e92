// The caster's material as every light-view fragment shader sees it (GpuScene::draw sets these
// uniforms per draw). discard_uncovered() drops the fragments an alpha-masked caster (glTF MASK:
// leaves, fences) does not cover, so its holes let light through exactly as the camera sees them;
// call it first in main().
in vec2 v_uv;
uniform vec4 u_base_color;
uniform int u_has_texture;
uniform sampler2D u_base_texture;
uniform float u_alpha_cutoff;  // < 0: opaque or blended material, no test

void discard_uncovered() {
  if (u_alpha_cutoff >= 0.0) {
    float a = u_base_color.a * (u_has_texture != 0 ? texture(u_base_texture, v_uv).a : 1.0);
    if (a < u_alpha_cutoff) discard;
  }
}
