// Interleaved gradient noise (Jimenez 2014, as used by Sterna 2018, section 1):
// IGN(x, y) = fract(52.9829189 * fract(0.06711056 * x + 0.00583715 * y)), in [0, 1).
float interleaved_gradient_noise(vec2 pixel) {
  return fract(52.9829189 * fract(dot(pixel, vec2(0.06711056, 0.00583715))));
}

// Vogel disk sample i of n, rotated by phi (Sterna 2018, section 1):
// r = sqrt(i + 0.5) / sqrt(n), theta = i * 2.4 + phi (2.4 rad ~ the golden angle).
vec2 vogel_disk_sample(int i, int n, float phi) {
  const float golden_angle = 2.4;
  float r = sqrt(float(i) + 0.5) / sqrt(float(n));
  float theta = float(i) * golden_angle + phi;
  return r * vec2(cos(theta), sin(theta));
}
