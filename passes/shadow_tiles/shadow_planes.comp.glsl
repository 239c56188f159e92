#version 450 core
// The shadow map as a plane per block: one invocation per output texel, which covers a block of
// ceil(map / output) texels each way (8 x 8 at shadow/8), fits the plane d = a + dot(t - c, g)
// through the block's depths (least squares, c the block centre) and keeps the range of the
// residuals d(t) - dot(t - c, g):
//   r, g = the plane's gradient d(window depth)/d(uv);  b = the smallest residual;  a = the largest,
//   or kCleared when the block has texels nothing was drawn into (depth 1: the far plane).
// On a surface seen by the light the residuals are ~0 at any slope, so the classifier
// (shadow_tiles.comp.glsl) can bound a receiver's comparisons over a whole block with the
// receiver's own plane (Isidoro 2006) without the block's slope counting as a blocker; a caster in
// the block widens the range. Cleared texels are left out of the fit (a caster's outline against
// them would tilt it). One invocation per block, sums in registers: a work group per block with
// shared-memory reductions took 381 us at 2048^2 on an H100.
layout(local_size_x = 8, local_size_y = 8) in;

layout(rgba32f, binding = 0) uniform writeonly image2D u_planes;
uniform sampler2D u_shadow_map;  // raw depth: no comparison

const float kCleared = 1e30;

void main() {
  ivec2 q = ivec2(gl_GlobalInvocationID.xy);
  ivec2 out_size = imageSize(u_planes);
  if (any(greaterThanEqual(q, out_size))) return;
  ivec2 map_size = textureSize(u_shadow_map, 0);
  ivec2 block = (map_size + out_size - 1) / out_size;
  ivec2 first = min(q * block, map_size - 1);
  ivec2 last = min(first + block, map_size);
  vec2 centre = 0.5 * vec2(first + last);  // texel space, texel i's centre at i + 0.5

  // Moments over the drawn texels: n, x, y, xx, yy, xy, d, xd, yd (x, y: texels from the centre).
  float n = 0.0, sx = 0.0, sy = 0.0, sxx = 0.0, syy = 0.0, sxy = 0.0, sd = 0.0, sxd = 0.0, syd = 0.0;
  bool cleared = false;
  for (int y = first.y; y < last.y; ++y)
    for (int x = first.x; x < last.x; ++x) {
      float d = texelFetch(u_shadow_map, ivec2(x, y), 0).r;
      if (d >= 1.0) {
        cleared = true;
        continue;
      }
      vec2 o = vec2(x, y) + 0.5 - centre;
      n += 1.0;
      sx += o.x;
      sy += o.y;
      sxx += o.x * o.x;
      syy += o.y * o.y;
      sxy += o.x * o.y;
      sd += d;
      sxd += o.x * d;
      syd += o.y * d;
    }
  // Least squares from the centred second moments: exact for a plane, whatever subset of the
  // block it covers (the residual range below is exact for whatever plane comes out).
  vec2 slope = vec2(0.0);  // per texel
  if (n >= 3.0) {
    vec2 mean_o = vec2(sx, sy) / n;
    float mean_d = sd / n;
    float cxx = sxx / n - mean_o.x * mean_o.x, cyy = syy / n - mean_o.y * mean_o.y;
    float cxy = sxy / n - mean_o.x * mean_o.y;
    float cxd = sxd / n - mean_o.x * mean_d, cyd = syd / n - mean_o.y * mean_d;
    float det = cxx * cyy - cxy * cxy;
    if (det > 1e-6 * max(cxx * cyy, 1e-12)) slope = vec2(cyy * cxd - cxy * cyd, cxx * cyd - cxy * cxd) / det;
  }
  float lo = kCleared, hi = -kCleared;
  for (int y = first.y; y < last.y; ++y)
    for (int x = first.x; x < last.x; ++x) {
      float d = texelFetch(u_shadow_map, ivec2(x, y), 0).r;
      if (d >= 1.0) continue;
      float residual = d - dot(vec2(x, y) + 0.5 - centre, slope);
      lo = min(lo, residual);
      hi = max(hi, residual);
    }
  imageStore(u_planes, q, vec4(slope * vec2(map_size), lo, cleared ? kCleared : hi));
}
