// Screen geometry of the sspcss passes: the camera's view, the pixel grid and the paper's
// d_screen (section 1). Set by set_screen_uniforms() (passes/sspcss_pass_common.cpp).
uniform mat4 u_view;          // world -> view space (the camera looks down -Z), world units
uniform vec2 u_tan_half_fov;  // (tan(fov_x / 2), tan(fov_y / 2)), unitless
uniform vec2 u_screen_px;     // screen width and height, pixels
uniform float u_d_screen;     // 1 / (2 tan(fov_y / 2)), section 1: the image plane's distance
                              // when the screen is one unit high

// View-space point at view depth 1 through the centre of pixel `pixel` (its ray; x, y scale
// with depth, z = -1).
vec3 view_ray(vec2 pixel) {
  vec2 ndc = (pixel + 0.5) / u_screen_px * 2.0 - 1.0;
  return vec3(ndc * u_tan_half_fov, -1.0);
}

// A world-space length at view depth d_eye (world units), seen face-on, in pixels: the paper's
// W_screen = W · d_screen / d_eye (section 1) is a fraction of the screen height; times the
// height in pixels.
float world_to_pixels(float length_world, float d_eye) {
  return length_world * u_d_screen / d_eye * u_screen_px.y;
}

bool inside_screen(ivec2 q) {
  return all(greaterThanEqual(q, ivec2(0))) && all(lessThan(vec2(q), u_screen_px));
}
