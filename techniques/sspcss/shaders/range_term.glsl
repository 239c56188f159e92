// The range term of the cross-bilateral filters (section 2: "a function of the depth difference
// in camera space between two points"). Needs screen_geometry.glsl.
//
// The difference is taken between a tap's view depth and the depth at which the centre pixel's
// tangent plane crosses the tap's view ray, not the centre's own depth: on a receiver seen at a
// grazing angle the view depth changes by several per cent per pixel, and a plain difference
// would cut a wide kernel short along the slope. Across a depth discontinuity (a foreground
// object over a shadow boundary) the tap is far from the plane and gets no weight. The sigma is
// relative to the centre's view depth (depth precision and scene scale both grow with it).
uniform float u_depth_sigma;  // fraction of the centre's view depth
uniform int u_range_term;     // 0: range weight 1 (the filter bleeds across depth edges)

struct RangeCentre {
  float depth;       // view depth of the centre pixel, world units
  vec3 normal_view;  // its unit normal in view space
  float plane;       // n . X for X on its tangent plane (view space, world units)
  bool use_plane;    // false where the plane is seen edge-on: compare plain depths there
};

RangeCentre range_centre(ivec2 pixel, float depth, vec3 normal_world) {
  RangeCentre c;
  c.depth = depth;
  c.normal_view = normalize(mat3(u_view) * normal_world);
  vec3 ray = view_ray(vec2(pixel));
  float n_dot_ray = dot(c.normal_view, ray);
  c.plane = depth * n_dot_ray;
  // Within ~6 degrees of edge-on the plane's depth along nearby rays is ill-conditioned.
  c.use_plane = abs(n_dot_ray) > 0.1 * length(ray);
  return c;
}

// Weight of a tap at pixel q whose view depth is z (world units; 0 = background: no weight).
float range_weight(RangeCentre c, ivec2 q, float z) {
  if (z <= 0.0) return 0.0;
  if (u_range_term == 0) return 1.0;
  float expected = c.depth;
  if (c.use_plane) {
    float n_dot_ray = dot(c.normal_view, view_ray(vec2(q)));
    // The plane crosses q's ray in front of the camera only when both have the same sign.
    if (n_dot_ray * c.plane <= 0.0) return 0.0;
    expected = c.plane / n_dot_ray;
  }
  float t = (z - expected) / (u_depth_sigma * c.depth);
  return exp(-0.5 * t * t);
}
