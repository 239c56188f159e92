#pragma once
// The resource viewer's data, read back from the GPU: the viewed channel's values (view distance
// for screen depth), their range (auto range), histogram, and the resource saved as a PNG of what
// the display shows or a PFM of its float values, named after the resource and the frame.
//
//   c.viewer().resource = "shadow_mask";
//   Result<std::string> path = save_viewed_resource(c, "out", ViewFormat::pfm);  // out/shadow_mask_frame120.pfm
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "sandbox/controller.h"

namespace penumbra::sandbox {

// Window depth [0, 1] of the camera's perspective projection -> view distance, world units.
float linear_depth(float window_depth, float near_plane, float far_plane);
// A depth texture of the frame's size: shown as view distance when the viewer linearises depth.
bool screen_depth(const gl::Texture& t, const SandboxController& c);

struct ViewedImage {
  int width = 0, height = 0, channels = 0;
  std::vector<float> texels;  // as stored, row 0 at the bottom (GL)
  std::vector<float> values;  // the viewed channel as shown; NaN for background at the far plane
};
// The viewed resource; an error when none is viewed or the graph does not produce it.
Result<ViewedImage> read_viewed(SandboxController& c, const std::string& what);

// Min and max of the viewed channel (background and non-finite texels skipped).
Result<glm::vec2> resource_range(SandboxController& c);
// resource_range into the viewer's min/max (a flat resource gets a range of 1e-6 around it).
Status apply_auto_range(SandboxController& c);
// The viewer's histogram (ViewerSettings::counts) of the viewed channel over [min, max].
inline constexpr int kHistogramBins = 64;
Status update_histogram(SandboxController& c);
// Every ~15 frames: the range (when it follows the resource) and the histogram from one read-back.
void refresh_viewed(SandboxController& c);

enum class ViewFormat { png, pfm };
// "png" | "pfm"; none for another name.
std::optional<ViewFormat> parse_view_format(const std::string& name);
// Saves the viewed resource into `dir` as RESOURCE_frameN.png (the colours the display shows:
// map, range, channels) or .pfm (the shown channels' float values: one for grey/heat/signed, RGB
// for colour; rows bottom to top as the format has them). Returns the path written.
Result<std::string> save_viewed_resource(SandboxController& c, const std::string& dir, ViewFormat format);

}  // namespace penumbra::sandbox
