// The techniques' shared sampling on the GPU (the CPU side, Poisson-disk tap sets, is
// poisson_disk.h beside this file): per-pixel noise to rotate a tap pattern, so that its
// banding turns into fine noise, and the Vogel disk.

// Interleaved gradient noise (Jimenez 2014, as used by Sterna 2018, section 1):
// IGN(x, y) = fract(52.9829189 * fract(0.06711056 * x + 0.00583715 * y)), in [0, 1).
float interleaved_gradient_noise(vec2 pixel) {
  return fract(52.9829189 * fract(dot(pixel, vec2(0.06711056, 0.00583715))));
}

// The rotation of a pixel's tap pattern (Sterna 2018, section 1): phi = 2 pi IGN(pixel), radians.
float noise_rotation(vec2 pixel) {
  return 6.28318530718 * interleaved_gradient_noise(pixel);
}

// Vogel disk sample i of n, rotated by phi (Sterna 2018, section 1):
// r = sqrt(i + 0.5) / sqrt(n), theta = i * 2.4 + phi (2.4 rad ~ the golden angle). The radii grow
// with i and each sample stands for an equal area (r^2 is uniform in i), inside the unit disk.
vec2 vogel_disk_sample(int i, int n, float phi) {
  const float golden_angle = 2.4;
  float r = sqrt(float(i) + 0.5) / sqrt(float(n));
  float theta = float(i) * golden_angle + phi;
  return r * vec2(cos(theta), sin(theta));
}
