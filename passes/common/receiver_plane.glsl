// Receiver-plane depth bias (Isidoro 2006, "Shadow mapping: GPU-based tips and techniques"):
// the receiver's depth is a plane in shadow-map space, so a filter tap at uv offset `o` is
// compared against depth + dot(o, dz_duv) instead of the centre depth, which removes acne on
// slanted receivers without a large constant bias. Compute shaders have no dFdx, so the
// gradient comes from the neighbouring G-buffer positions (same surface test by normal).
//
// Needs: shadow_common.glsl, and a G-buffer position sampler passed in.
vec2 receiver_plane_gradient(sampler2D positions, ivec2 pixel, vec3 centre_coord, vec3 normal) {
  ivec2 size = textureSize(positions, 0);
  ivec2 px = pixel + ivec2(pixel.x + 1 < size.x ? 1 : -1, 0);
  ivec2 py = pixel + ivec2(0, pixel.y + 1 < size.y ? 1 : -1);
  vec4 wx = texelFetch(positions, px, 0);
  vec4 wy = texelFetch(positions, py, 0);
  if (wx.w <= 0.0 || wy.w <= 0.0) return vec2(0.0);
  vec3 dx = shadow_coord(wx.xyz) - centre_coord;
  vec3 dy = shadow_coord(wy.xyz) - centre_coord;
  // Solve [dx.xy dy.xy] * g = [dx.z dy.z] for g = d(depth)/d(uv).
  float det = dx.x * dy.y - dx.y * dy.x;
  if (abs(det) < 1e-12) return vec2(0.0);
  vec2 g = vec2(dy.y * dx.z - dx.y * dy.z, dx.x * dy.z - dy.x * dx.z) / det;
  // A neighbour on another surface (depth edge) gives a wild gradient: cap it.
  return clamp(g, vec2(-20.0), vec2(20.0));
}
