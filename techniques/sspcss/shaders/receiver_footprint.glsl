// Shape of the penumbra on screen. Needs shadow_common.glsl and screen_geometry.glsl.
//
// The paper maps W_penumbra to the screen as W_screen = W_penumbra · d_screen / d_eye, which is
// exact for a penumbra lying in a plane facing the camera. W_penumbra is measured across the
// light direction; on a receiver at incidence angle i it is stretched by 1 / cos i along the
// light's direction in the receiver plane, and the view then foreshortens the receiver plane.
// receiver_footprint() returns the 2x2 matrix F that maps an offset across the light direction,
// in units of the isotropic W_screen, to a screen offset in pixels: the kernel of diameter W_screen
// becomes the ellipse F · disk. F = identity (up to a rotation) for a receiver facing both the
// camera and the light.
//
// Derivation (view space, camera at the origin looking down -Z): a light-space offset a t1 + b t2
// (t1, t2 orthonormal, across the light direction L) moves the receiver point P along L back onto
// its tangent plane (normal n): e_k = t_k - (n.t_k / n.L) L. The projection x / -z has the
// derivative (dX.xy + (X.xy / -X.z) dX.z) / -X.z; the isotropic mapping is 1 / -X.z. Pixels are
// square, so both axes scale alike.
uniform int u_footprint;  // 0: the paper's isotropic W_screen (F = identity)

const float kMinCosIncidence = 0.15;  // caps the stretch at grazing light to ~6.7x

mat2 receiver_footprint(ivec2 pixel, vec3 world, vec3 normal_world) {
  if (u_footprint == 0) return mat2(1.0);
  mat3 to_view = mat3(u_view);
  vec3 l = normalize(to_view * (u_light_ortho == 1 ? u_light_dir : world - u_light_pos));
  vec3 n = normalize(to_view * normal_world);
  vec3 helper = abs(l.y) < 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
  vec3 t1 = normalize(cross(helper, l));
  vec3 t2 = cross(l, t1);
  float n_dot_l = dot(n, l);
  n_dot_l = sign(n_dot_l) * max(abs(n_dot_l), kMinCosIncidence);
  if (n_dot_l == 0.0) n_dot_l = kMinCosIncidence;
  vec3 e1 = t1 - dot(n, t1) / n_dot_l * l;
  vec3 e2 = t2 - dot(n, t2) / n_dot_l * l;
  vec2 pi = view_ray(vec2(pixel)).xy;
  return mat2(e1.xy + pi * e1.z, e2.xy + pi * e2.z);
}

// The two passes of the separable filter for the kernel F · (Gaussian of diameter width_px).
// Its covariance is Sigma = sigma^2 F F^T = sigma^2 [a b; b c] (sigma = width / 4). A 2D Gaussian
// is exactly a horizontal Gaussian of the conditional variance sigma^2 (a - b^2 / c) followed by
// a Gaussian of variance sigma^2 c along the sheared column direction (b / c, 1): the sum of the
// two independent offsets has covariance Sigma. So the second pass still takes one tap per row,
// shifted along the row by shear x its row offset; for a round kernel (F = identity, or
// receiver_footprint off) the shear is 0 and the passes are plain horizontal and vertical.
struct SeparableKernel {
  float width_x;  // diameter (4 sigma) of the horizontal pass, pixels
  float width_y;  // diameter of the second pass, counted in rows
  float shear;    // pixels along the row per row of the second pass
};

SeparableKernel separable_kernel(mat2 f, float width_px) {
  vec2 row_x = vec2(f[0][0], f[1][0]);
  vec2 row_y = vec2(f[0][1], f[1][1]);
  float a = dot(row_x, row_x), b = dot(row_x, row_y), c = dot(row_y, row_y);
  SeparableKernel k;
  k.shear = c > 1e-6 * a ? b / c : 0.0;
  k.width_x = width_px * sqrt(max(a - b * k.shear, 0.0));
  k.width_y = width_px * sqrt(c);
  return k;
}
