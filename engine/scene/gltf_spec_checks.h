#pragma once
// The value ranges the glTF 2.0 specification states, checked on the file's JSON before its
// values are used: tinygltf reads a light of negative intensity or a camera with znear 0 as
// readily as a good one, and the renderer would draw nonsense from it.
//
//   if (Status s = check_gltf_spec_values(json_text, path); !s) return s.error();
//
// Checked (each error names the file and a JSON pointer: /cameras/2/perspective/yfov):
//   - `extensionsUsed`, `extensionsRequired`: arrays of strings; `scene`: an existing scene;
//   - KHR_lights_punctual lights: intensity >= 0, colour components in [0, 1], range > 0, spot
//     0 <= innerConeAngle < outerConeAngle <= pi/2;
//   - cameras: perspective 0 < yfov < pi, znear > 0, zfar > znear, aspectRatio > 0;
//     orthographic xmag, ymag != 0, 0 <= znear < zfar;
//   - nodes: a rotation that is a quaternion of non-zero length.
// Text that is not JSON is left to tinygltf, which reports the syntax error.
#include <string>
#include <string_view>

#include "util/error.h"

namespace penumbra::scene {

Status check_gltf_spec_values(std::string_view json_text, const std::string& file);

}  // namespace penumbra::scene
