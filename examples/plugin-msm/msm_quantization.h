#pragma once
// The optimised quantisation of four moments (Peters & Klein 2015, the 16-bit variant): the
// moments b = (z, z^2, z^3, z^4) of a depth z in [0, 1] become to_optimised * b + offset, every
// component in [0, 1], so 16-bit UNORM keeps them; to_canonical inverts it. The matrices' rows
// are the paper's, listed in glm's column order so that `M * b` applies them as the paper does.
#include <glm/glm.hpp>

namespace msm {

inline const glm::mat4 kToOptimised(-2.07224649f, 13.7948857237f, 0.105877704f, 9.7924062118f,      //
                                    32.23703778f, -59.4683975703f, -1.9077466311f, -33.7652110555f,  //
                                    -68.571074599f, 82.0359750338f, 9.3496555107f, 47.9456096605f,   //
                                    39.3703274134f, -35.364903257f, -6.6543490743f, -23.9728048165f);
inline const glm::mat4 kToCanonical(0.2227744146f, 0.1549679261f, 0.1451988946f, 0.163127443f,  //
                                    0.0771972861f, 0.1394629426f, 0.2120202157f, 0.2591432266f,  //
                                    0.7926986636f, 0.7963415838f, 0.7258694464f, 0.6539092497f,  //
                                    0.0319417555f, -0.1722823173f, -0.2758014811f, -0.3376131734f);
inline const glm::vec4 kOptimisedOffset(0.035955884801f, 0.0f, 0.0f, 0.0f);

// The optimised moments of a single depth z (the far plane's, z = 1, where nothing casts).
inline glm::vec4 optimised_moments(float z) {
  return kToOptimised * glm::vec4(z, z * z, z * z * z, z * z * z * z) + kOptimisedOffset;
}

}  // namespace msm
