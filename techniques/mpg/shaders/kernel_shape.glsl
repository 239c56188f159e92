// The screen-space shape of a receiver's penumbra (not in the paper, whose kernels are round in
// screen space): a disk light of diameter w seen from a receiver throws a penumbra whose spread
// (standard deviation) is w / 4 in every direction ACROSS the light, in world units. On the
// receiver surface that footprint is stretched by 1 / cos(theta_L) along the light's direction
// projected onto the surface (theta_L between the normal and the light), and the camera then
// projects the surface into pixels (foreshortening). Per pixel:
//   m1 = J(l_t) / cos(theta_L),  m2 = J(b)      J(t): pixels moved per world unit along tangent t
//   C  = m1 m1^T + m2 m2^T                      pixels^2 per (world unit of spread)^2
// For a spread s (world units) the kernel covariance is s^2 C. We split C into a size and a
// shape: g = det(C)^(1/4) (pixels per world unit: the geometric mean of the two axes) and
// A = sqrt(C / sqrt(det C)), symmetric with det 1, whose eigenvalues (axis stretch) are capped
// at sqrt(kMaxAnisotropy). Every screen-space kernel of pass 3 and pass 4 is defined on a round
// unit kernel of size D and mapped to the screen by A (offset o -> A o), so D keeps its meaning
// (the kernel size of a round kernel with the same area).
//
// The same tangent frame gives the receiver plane's screen-space view-depth gradient dz/dpixel,
// for the depth-aware taps (mpg_common.glsl): the depth change along the two tangents mapped
// through the inverse of the tangent-to-pixel Jacobian.
//
// Stored per pixel as (A11, A12, dz/dx, dz/dy) (A22 = (1 + A12^2) / A11 since det A = 1;
// shape_offset.glsl decodes it).
//
// Needs: shadow_common.glsl (direction_to_light).

const float kMaxAnisotropy = 6.0;  // largest ratio of the two axes' spreads

struct KernelShape {
  vec3 a;                  // A = [a.x a.y; a.y a.z]
  float pixels_per_world;  // g
  vec2 depth_gradient;     // view depth (world units) per pixel along x and y
};

// Pixel coordinates (xy) and linear view depth (z, = clip w of a perspective camera).
vec3 to_pixels(mat4 view_proj, vec2 screen, vec3 world) {
  vec4 c = view_proj * vec4(world, 1.0);
  return vec3((c.xy / c.w * 0.5 + 0.5) * screen, c.w);
}

// anisotropic false: A = identity, g = focal_px / z (a receiver facing the camera); the depth
// gradient is computed either way.
KernelShape receiver_kernel_shape(mat4 view_proj, vec2 screen, vec3 x, vec3 n, float view_depth,
                                  bool anisotropic, float focal_px) {
  vec3 l = direction_to_light(x);
  float cos_l = max(dot(n, l), 0.05);
  vec3 along = l - n * dot(n, l);
  along = dot(along, along) > 1e-8 ? normalize(along) : normalize(cross(n, abs(n.y) < 0.9 ? vec3(0, 1, 0) : vec3(1, 0, 0)));
  vec3 across = cross(n, along);
  float eps = 1e-3 * max(view_depth, 1e-3);  // world units
  vec3 p = to_pixels(view_proj, screen, x);
  vec3 j1 = (to_pixels(view_proj, screen, x + eps * along) - p) / eps;   // per world unit along
  vec3 j2 = (to_pixels(view_proj, screen, x + eps * across) - p) / eps;  // per world unit across
  KernelShape k;
  // dz/dpixel = J^-T (dz/d along, dz/d across), J = [j1.xy j2.xy].
  float det_j = j1.x * j2.y - j1.y * j2.x;
  k.depth_gradient = abs(det_j) > 1e-12 ? vec2(j2.y * j1.z - j1.y * j2.z, j1.x * j2.z - j2.x * j1.z) / det_j : vec2(0.0);
  k.a = vec3(1.0, 0.0, 1.0);
  k.pixels_per_world = focal_px / max(view_depth, 1e-6);
  if (!anisotropic) return k;
  vec2 m1 = j1.xy / cos_l, m2 = j2.xy;
  float c11 = m1.x * m1.x + m2.x * m2.x, c12 = m1.x * m1.y + m2.x * m2.y, c22 = m1.y * m1.y + m2.y * m2.y;
  float root_det = abs(m1.x * m2.y - m1.y * m2.x);  // sqrt(det C)
  if (root_det < 1e-12) {  // surface seen edge-on: no area on screen
    k.pixels_per_world = sqrt(0.5 * (c11 + c22));
    return k;
  }
  k.pixels_per_world = sqrt(root_det);
  // Normalised covariance Cn (det 1), eigenvalues mu and 1/mu; cap mu.
  vec3 cn = vec3(c11, c12, c22) / root_det;
  float half_trace = 0.5 * (cn.x + cn.z);
  float mu = half_trace + sqrt(max(half_trace * half_trace - 1.0, 0.0));
  if (mu > kMaxAnisotropy) {
    // Cn = mu E + (1/mu) (I - E), E the projector on the major axis; rebuild with the cap.
    vec3 e = (cn - vec3(1.0 / mu, 0.0, 1.0 / mu)) / (mu - 1.0 / mu);
    cn = kMaxAnisotropy * e + (vec3(1.0, 0.0, 1.0) - e) / kMaxAnisotropy;
  }
  // Square root of a 2x2 symmetric positive matrix with det 1: (Cn + I) / sqrt(trace + 2).
  k.a = (cn + vec3(1.0, 0.0, 1.0)) / sqrt(cn.x + cn.z + 2.0);
  return k;
}

