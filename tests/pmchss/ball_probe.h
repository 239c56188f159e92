#pragma once
// The probe across the ball's ground shadow used by the contact-hardening tests.
//
// Choice: the ball scene's low light (20 degrees) throws an elongated elliptic shadow onto the
// ground. We take the centroid of shadowed (mask < 0.5) GROUND pixels (world y < 0.05, which
// excludes the ball's own dark side) and probe from there straight up the image (-y) for 60 px:
// across the ellipse's short axis, where the edge is least stretched by the view, from its
// umbra centre (mask <= 0.02) to the lit ground (>= 0.98). Heights 0.1-1 m keep the shadow's far
// side on the ground at 224x168. The probe moves with the shadow as
// the ball rises, so it always crosses the same edge of the same shadow.
#include <optional>

#include <glm/glm.hpp>

#include "metrics/mask_image.h"

namespace penumbra::test {

struct Probe {
  glm::vec2 p0, p1;  // pixel coordinates, rows top to bottom
};

// ground_y: per pixel world-space height (NaN for background), rows top to bottom.
std::optional<Probe> ball_shadow_probe(const metrics::MaskImage& mask, const metrics::MaskImage& ground_y,
                                       float length_px = 60.0f);

}  // namespace penumbra::test
