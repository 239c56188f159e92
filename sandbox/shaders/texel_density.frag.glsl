#version 450 core
// Shadow-map texel density: how many shadow-map texels one frame pixel spans, from the screen
// derivatives of each receiver's shadow-map texel coordinate. log2 scale through the heat map:
// green = 1 texel a pixel, blue = one texel spread over many pixels (blocky shadows), red = many
// texels a pixel (aliasing, wasted resolution). Pixels with no receiver are dark grey.
#include "colormap.glsl"
#include "gbuffer/gbuffer_read.glsl"

uniform sampler2D depth;          // gbuffer_depth: linear view depth, 0 = background
uniform mat4 light_view_proj;
uniform float shadow_size;        // texels
uniform float zoom;               // the view's zoom (derivatives are per displayed pixel)
in vec2 v_uv;
out vec4 frag_color;

void main() {
  ivec2 pixel = clamp(ivec2(v_uv * vec2(frame_screen.xy)), ivec2(0), frame_screen.xy - 1);
  vec4 p = gbuffer_position(depth, pixel);
  vec4 c = light_view_proj * vec4(p.xyz, 1.0);
  vec2 texel = (c.xy / c.w * 0.5 + 0.5) * shadow_size;
  float density = max(length(dFdx(texel)), length(dFdy(texel))) * zoom;
  if (p.w <= 0.0 || c.w <= 0.0) {
    frag_color = vec4(vec3(40.0 / 255.0), 1.0);
    return;
  }
  float t = clamp(log2(max(density, 1e-6)) / 8.0 + 0.5, 0.0, 1.0);  // 1/16 .. 16 texels a pixel
  frag_color = vec4(heat_color(t), 1.0);
}
