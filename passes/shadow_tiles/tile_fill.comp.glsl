#version 450 core
// The lit and umbra tiles of a tiled filter's output get their constant value here, one work
// group per tile of the whole screen; penumbra tiles are left to the filter, which runs over
// the classifier's tile list only. MASK_FORMAT is the output's image format qualifier.
#include "screen_pass.glsl"
#include "shadow_tiles/tile_class.glsl"

layout(MASK_FORMAT, binding = 0) uniform writeonly image2D u_mask;
uniform sampler2D u_tile_class;
uniform vec4 u_lit_value;
uniform vec4 u_umbra_value;

void main() {
  float c = tile_class_of(texelFetch(u_tile_class, ivec2(gl_WorkGroupID.xy), 0).r);
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (c == TILE_PENUMBRA || any(greaterThanEqual(p, imageSize(u_mask)))) return;
  imageStore(u_mask, p, c == TILE_LIT ? u_lit_value : u_umbra_value);
}
