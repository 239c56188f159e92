// The work-group shape of every screen-space compute pass (one invocation per pixel): 16 x 16.
// Measured on an H200 at 3840x2160 (docs/results/bandwidth.md): with 8 x 8 groups every
// full-screen pass took at least about 85 us, whatever it read or wrote (resolve_mask, moving
// 83 MB, as long as a blur moving 199 MB); 16 x 16 groups took hard_mask from 86 to 53 us and
// resolve_mask from 86 to 36 us. 32 x 8 and 16 x 8 were close behind.
layout(local_size_x = 16, local_size_y = 16) in;
