#version 450 core
#include "gbuffer/gbuffer_read.glsl"
// Checkerboard upsample (Sterna 2018, section 3): pixels with (x + y) even were computed and
// are unpacked from the RG16F screen/2 target (see shadow_mask.comp.glsl for the packing); each
// other pixel is the average of its four computed neighbours weighted by
// 1 / (eps + |linear depth difference|), so neighbours on other surfaces barely contribute
// ("only blend in those neighbours whose depths don't differ much").
#include "screen_pass.glsl"
layout(r16f, binding = 0) uniform writeonly image2D u_mask;
uniform sampler2D u_checker;   // RG16F screen/2, nearest
uniform sampler2D u_depth;     // gbuffer_depth: linear view depth, 0 = background
uniform float u_depth_epsilon; // world units

// Value of a computed pixel, or -1 when it lies outside the packed target (odd sizes).
float computed(ivec2 q) {
  ivec2 t = ivec2(q.x >> 1, q.y >> 1);
  if (any(greaterThanEqual(t, textureSize(u_checker, 0)))) return -1.0;
  vec2 rg = texelFetch(u_checker, t, 0).rg;
  return (q.y & 1) == 0 ? rg.r : rg.g;
}

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = imageSize(u_mask);
  if (any(greaterThanEqual(p, size))) return;
  float depth = gbuffer_position(u_depth, p).w;
  float result = 1.0;  // background stays lit
  if (depth > 0.0) {
    float own = ((p.x + p.y) & 1) == 0 ? computed(p) : -1.0;
    if (own >= 0.0) {
      result = own;
    } else {
      const ivec2 offsets[4] = ivec2[4](ivec2(-1, 0), ivec2(1, 0), ivec2(0, -1), ivec2(0, 1));
      float sum = 0.0;
      float weights = 0.0;
      for (int i = 0; i < 4; ++i) {
        ivec2 q = p + offsets[i];
        if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
        float d = gbuffer_position(u_depth, q).w;
        float v = computed(q);
        if (d <= 0.0 || v < 0.0) continue;
        float w = 1.0 / (u_depth_epsilon + abs(depth - d));
        sum += w * v;
        weights += w;
      }
      if (weights > 0.0) result = sum / weights;
    }
  }
  imageStore(u_mask, p, vec4(result));
}
