// Shared pieces of the mpg passes (Cherry & Kooima, "Multi-pass Gaussian Contact-hardening Soft
// Shadows"), section 3.
//
// The DISTANCE MAP (RGBA16F, screen size) every pass after pass 2 reads and writes:
//   .r  S: the hard shadow bit, 1 = shadowed, 0 = lit; pass 4 turns it into a fraction
//       (section 3.2; shadow_mask = 1 - S, pass 5)
//   .g  D: the filter control (section 3.2, "(occluder distance)^Dp * Dm"), dimensionless:
//       the kernel size in pixels for the PCF and single-pass Gaussian alterations, the number
//       of blur passes left for the multi-pass one. D <= 0: never filtered.
//   .b  linear view depth of the receiver, world units (0 = background), for depth-aware taps
//   .a  scratch of the separable passes (umbra early-out, dilation)

// Depth-aware taps (not in the paper): a tap whose view depth is off the centre receiver's plane
// -- the centre's depth extrapolated to the tap with the plane's screen-space depth gradient
// (kernel_shape.glsl) -- by more than u_depth_tolerance x the centre's depth belongs to another
// surface (a picket in front of the ground, the lit top of a pole over its own shadow) and is
// left out of the filter. Off: every tap counts, as in the paper.
uniform int u_depth_aware;        // 1: on
uniform float u_depth_tolerance;  // relative view-depth difference

float tap_depth_weight(float centre_depth, vec2 depth_gradient, vec2 offset_px, float tap_depth) {
  if (u_depth_aware == 0) return 1.0;
  if (tap_depth <= 0.0) return 0.0;  // background
  float expected = centre_depth + dot(depth_gradient, offset_px);
  return abs(tap_depth - expected) <= u_depth_tolerance * centre_depth ? 1.0 : 0.0;
}

// Weight of the texel `t` pixels from the centre (along one axis) in a kernel `size` pixels
// wide: how much of the texel [t - 0.5, t + 0.5] lies inside [-size/2, size/2]. A continuous
// size gives a continuous kernel (the outer ring fades in), so the penumbra width follows D
// without steps; an odd integer size is the paper's plain size x size box.
float kernel_coverage(float t, float size) {
  return clamp(0.5 * size + 0.5 - abs(t), 0.0, 1.0);
}

// Gaussian of the single-pass alteration: sigma = size / 3 pixels (section 1, the 3-sigma rule).
float kernel_gaussian(float t, float size) {
  float sigma = max(size, 1.0) / 3.0;
  return exp(-t * t / (2.0 * sigma * sigma));
}
