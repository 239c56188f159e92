// Taps of the 2D cross-bilateral Poisson filter (section 2: "a 2D random Poisson disk as the
// domain filter"): a fixed best-candidate Poisson set in the unit disk (kPoissonDisk,
// sspcss_pass_common.h), rotated per pixel by 2 pi IGN(pixel) (sampling/sampling.glsl) so that
// its pattern turns into fine noise, scaled to the kernel's radius; uniform domain weights (a disk kernel, like PCSS's).
const int kMaxPoissonTaps = 64;
uniform vec2 u_poisson[kMaxPoissonTaps];  // unit disk
uniform int u_poisson_taps;

// Offset of tap i, whole pixels, for a disk of radius radius_px rotated by (cos phi, sin phi)
// and mapped to the screen by the receiver footprint (receiver_footprint.glsl).
ivec2 poisson_offset(int i, vec2 rotation, float radius_px, mat2 footprint) {
  vec2 s = u_poisson[i];
  vec2 r = vec2(s.x * rotation.x - s.y * rotation.y, s.x * rotation.y + s.y * rotation.x);
  return ivec2(round(footprint * (r * radius_px)));
}

vec2 poisson_rotation(ivec2 pixel) {
  float phi = noise_rotation(vec2(pixel));
  return vec2(cos(phi), sin(phi));
}
