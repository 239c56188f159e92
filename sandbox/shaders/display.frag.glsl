#version 450 core
// Presents one texture (a graph resource) to the window with a colour map. A fragment shader,
// not compute: it draws into the window's framebuffer (or the sandbox's presentation target).
#include "colormap.glsl"

uniform sampler2D src;
uniform int map_mode;       // 0 colour (rgb), 1 grey, 2 heat, 3 signed (one channel; ViewerSettings::Map)
uniform int channel;        // 0..3: which channel grey/heat/signed read
uniform vec4 channel_mask;  // colour: 1 for each channel shown; alpha alone is shown as grey
uniform vec2 value_range;   // [min, max] mapped to [0, 1]
uniform int linearize_depth;  // 1: src holds window-space depth of the camera's projection
uniform vec2 near_far;      // camera near/far planes, world units
uniform int coverage_in_g;  // 1: g channel is receiver coverage; background shown dark grey
in vec2 v_uv;
out vec4 frag_color;

// Window depth [0, 1] of a perspective projection -> view distance in world units.
float linear_depth(float d) {
  float z = d * 2.0 - 1.0;
  float n = near_far.x, f = near_far.y;
  return 2.0 * n * f / (f + n - z * (f - n));
}

void main() {
  vec4 texel = texture(src, v_uv);
  if (coverage_in_g == 1 && texel.g < 0.5) {
    frag_color = vec4(vec3(40.0 / 255.0), 1.0);
    return;
  }
  float scale = 1.0 / max(value_range.y - value_range.x, 1e-12);
  if (map_mode == 0) {  // displayed_colour() in sandbox/view_mapping.cpp writes PNGs alike
    vec3 rgb = channel_mask.rgb == vec3(0.0) ? vec3(texel.a * channel_mask.a) : texel.rgb * channel_mask.rgb;
    frag_color = vec4(clamp((rgb - value_range.x) * scale, 0.0, 1.0), 1.0);
    return;
  }
  float v = texel[channel];
  if (linearize_depth == 1) v = linear_depth(v);
  float t = clamp((v - value_range.x) * scale, 0.0, 1.0);
  frag_color = vec4(map_mode == 2 ? heat_color(t) : map_mode == 3 ? diverging_color(t) : vec3(t), 1.0);
}
