// The caster's material as every light-view fragment shader sees it (GpuScene::draw sets these
// uniforms per draw). discard_uncovered() drops the fragments an alpha-masked caster (glTF MASK:
// leaves, fences) does not cover, so its holes let light through exactly as the camera sees them;
// call it first in main().
//
// ALPHA_TEST_NEAREST_TEXEL: the alpha of the texel nearest v_uv in the full-resolution level,
// repeat wrap (the ray-traced reference's test), instead of the filtered mip chain. esm's depth
// pass uses it where its quads follow the mask's contour, which is traced that way
// (techniques/esm/silhouette/alpha_contours.h): a depth map that agrees with the contour.
in vec2 v_uv;
uniform vec4 u_base_color;
uniform int u_has_texture;
uniform sampler2D u_base_texture;
uniform float u_alpha_cutoff;  // < 0: opaque or blended material, no test

void discard_uncovered() {
  if (u_alpha_cutoff >= 0.0) {
#ifdef ALPHA_TEST_NEAREST_TEXEL
    ivec2 size = textureSize(u_base_texture, 0);
    ivec2 texel = min(ivec2(fract(v_uv) * vec2(size)), size - 1);
    float a = u_base_color.a * (u_has_texture != 0 ? texelFetch(u_base_texture, texel, 0).a : 1.0);
#else
    float a = u_base_color.a * (u_has_texture != 0 ? texture(u_base_texture, v_uv).a : 1.0);
#endif
    if (a < u_alpha_cutoff) discard;
  }
}
