// The work-group shape of every screen-space compute pass (one invocation per pixel): 16 x 16.
// Measured on an H200 at 3840x2160 (docs/results/bandwidth.md): with 8 x 8 groups every
// full-screen pass took at least about 85 us, whatever it read or wrote (resolve_mask, moving
// 83 MB, as long as a blur moving 199 MB); 16 x 16 groups took hard_mask from 86 to 53 us and
// resolve_mask from 86 to 36 us. 32 x 8 and 16 x 8 were close behind.
//
// A pass that can run over the penumbra tiles only (passes/shadow_tiles/tiled_dispatch.h) is
// compiled with SCREEN_TILED 1 and SCREEN_TILE = the classifier's tile edge: one work group per
// listed tile, so its shape is the tile. screen_pixel() is the pixel of this invocation either way.
#ifndef SCREEN_TILE
#define SCREEN_TILE 16
#endif
#ifndef SCREEN_TILED
#define SCREEN_TILED 0
#endif
layout(local_size_x = SCREEN_TILE, local_size_y = SCREEN_TILE) in;
// Every screen pass sees the tile list at binding 7 (declared, unused, when untiled: the
// preprocessor pastes a file once, so the include cannot sit inside the #if).
#define TILE_LIST_BINDING 7
#include "tile_list.glsl"
#if SCREEN_TILED
ivec2 screen_pixel() { return tile_list_pixel(); }
#else
ivec2 screen_pixel() { return ivec2(gl_GlobalInvocationID.xy); }
#endif
