#pragma once
// Penumbra width of the ball's ground shadow for the contact-hardening tests.
//
// The ball scene's low light (20 degrees) throws an elongated shadow onto the ground. The probe
// starts at the centroid of the shadowed (mask < 0.5) GROUND pixels (world y < 0.05, which leaves
// out the ball's own dark side) and runs straight up the image for `length_px`: across the
// shadow's short axis, from its umbra to the lit ground. It moves with the shadow as the ball
// rises, so it crosses the same edge of the same shadow at every height. The width is the 10%-90%
// rise (metrics::penumbra_width with lo 0.1, hi 0.9): a wide, soft shadow of a high ball need not
// keep a point at or below 0.02 on its short axis, and the 10%-90% width ignores the Gaussian
// kernels' long tails.
#include "metrics/mask_image.h"
#include "util/error.h"

namespace penumbra::test {

// ground_y: world height per pixel (NaN on background), rows top to bottom, like `mask`.
Result<float> ball_penumbra_width(const metrics::MaskImage& mask, const metrics::MaskImage& ground_y,
                                  float length_px = 60.0f);

}  // namespace penumbra::test
