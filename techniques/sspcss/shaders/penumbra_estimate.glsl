// Penumbra estimate and blocker-search width (section 1), in world units on the receiver and
// in pixels. Needs shadow_common.glsl (light uniforms) and screen_geometry.glsl.
//
// Distances d are light distances (light_distance(), world units): from the emitter plane for a
// directional light, from the light position along its axis for a spot light.
//   spot:  W_penumbra = (d_receiver - d_blocker) / d_blocker · W_light     (the paper's formula)
//   sun:   a directional light is a disk of diameter `size` at distance D seen from the scene
//          as the angle theta = size / D (scene/light.h); W_light / d_blocker, the angle the
//          emitter subtends at the blocker, is theta for every blocker, so
//          W_penumbra = (d_receiver - d_blocker) · theta. Equivalently the sun is a spot light
//          of diameter theta · d_blocker: W_light = size · d_blocker / D.
// W_search = (d_point - z_near) / d_point · W_light is the width, on the light's near plane, of
// the cone from the receiver to the emitter (the region of the shadow map PCSS searches). The
// screen-space search looks at receivers instead: seen from the light that region projects onto
// the receiver with the factor d_point / z_near (spot; 1 for the sun), which gives
// W_penumbra(d_point, z_near): the widest penumbra a blocker at the near plane, the farthest a
// blocker can be from the receiver, can cast. So the search width is that penumbra, in pixels.
uniform float u_light_size_scale;  // multiplier on W_light (unitless)
uniform float u_max_penumbra_px;   // clamp of W_screen and of the search width, pixels
uniform float u_fixed_radius_px;   // > 0: W_screen = 2 x this (benchmark/debug), pixels

// W_penumbra in world units, measured across the light direction at the receiver.
float penumbra_world(float d_receiver, float d_blocker) {
  float h = max(d_receiver - d_blocker, 0.0);
  float w_light = u_light_size_world * u_light_size_scale;
  if (u_light_ortho == 1) return h * w_light / u_light_emitter_distance;
  // Blockers lie inside the light frustum, so d_blocker >= near > 0 (shadow_frustum()).
  return h * w_light / max(d_blocker, u_light_near);
}

// Largest screen extent (pixels) of a kernel F · disk(diameter 1) (receiver_footprint.glsl).
float footprint_scale(mat2 f) {
  return max(max(length(vec2(f[0][0], f[1][0])), length(vec2(f[0][1], f[1][1]))), 1e-6);
}

// Blocker-search width (diameter) around a receiver, pixels, before the footprint F; clamped so
// that the kernel F · disk spans at most u_max_penumbra_px.
float search_width_px(float d_receiver, float d_eye, mat2 f) {
  float w = world_to_pixels(penumbra_world(d_receiver, u_light_near), d_eye);
  return min(w, u_max_penumbra_px / footprint_scale(f));
}

// W_screen: the filter diameter, pixels (section 1), before the footprint F, clamped like the
// search; 0 where the search found no blocker (the pixel keeps its hard visibility).
// fixed_radius_px > 0 replaces it on every receiver, found or not, so a benchmark filters every
// pixel at one radius (with receiver_footprint off, the kernel is then exactly that disk).
float screen_penumbra_px(bool found, float d_receiver, float d_blocker, float d_eye, mat2 f) {
  if (u_fixed_radius_px > 0.0) return 2.0 * u_fixed_radius_px;
  if (!found) return 0.0;
  float w = world_to_pixels(penumbra_world(d_receiver, d_blocker), d_eye);
  return min(w, u_max_penumbra_px / footprint_scale(f));
}
