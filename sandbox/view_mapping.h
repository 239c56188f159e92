#pragma once
// How textures map onto the frame, GL-free so the composer draws and the pixel inspector reads
// through the same arithmetic (unit-tested): zoom and pan of the image that fills the frame
// (the same for both sides of a compare split, so their zoom is synced), a viewed texture fitted
// with its own aspect (a square shadow map stays square), and a frame pixel back to a texel.
// Rectangles are (x, y, width, height) in GL pixels (origin bottom-left) or uv.
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace penumbra::sandbox {

// The display's colour maps by name (scripts' "map", the viewer's combo), in the order of
// ViewerSettings::Map and display.frag.glsl's map_mode. "signed": blue below 0, white at 0, red
// above, over [-s, s] (the compare error view: A - reference).
inline constexpr const char* kColourMapNames[] = {"color", "grey", "heat", "signed"};
// Index of `name` in kColourMapNames; none for another name.
std::optional<int> colour_map_index(const std::string& name);
// The "signed" map at t in [0, 1] (0.5 is zero), RGB 0..1: the legend's colours.
glm::vec3 diverging_color(float t);
// The colour the display shows for a texel (display.frag.glsl's mapping, for saved PNGs): map
// index into kColourMapNames, `value` the texel's channel as shown (depth already linear),
// channel_mask as ViewerSettings's, [lo, hi] the range mapped to [0, 1].
glm::vec3 displayed_colour(int map, const glm::vec4& texel, float value, unsigned channel_mask, float lo, float hi);
// Counts of `values` in `bins` equal bins over [lo, hi]; values outside go to the end bins,
// non-finite ones nowhere.
std::vector<float> histogram(const std::vector<float>& values, float lo, float hi, int bins);

struct ViewZoom {
  float zoom = 1.0f;               // 1 = the whole image; 2 = half of it in each direction
  glm::vec2 center{0.5f, 0.5f};    // uv at the middle of the frame
};
inline constexpr float kMaxZoom = 64.0f;

// Zoom clamped to [1, kMaxZoom] and the centre kept so the window stays inside [0, 1]^2.
ViewZoom clamped(ViewZoom z);
// Zoom by `factor` keeping the uv under `anchor` (a fraction of the frame, 0..1) where it is.
ViewZoom zoom_about(ViewZoom z, float factor, glm::vec2 anchor);
// Pan by a drag of `delta` (a fraction of the frame).
ViewZoom pan_by(ViewZoom z, glm::vec2 delta);

// The uv rectangle shown in the part `screen` (fractions of the frame) of a zoomed image.
glm::vec4 zoomed_uv_rect(const ViewZoom& z, const glm::vec4& screen = {0, 0, 1, 1});

// The largest rectangle of the texture's aspect inside `frame` (w x h), centred.
glm::ivec4 fitted_rect(int frame_w, int frame_h, int tex_w, int tex_h);
// The viewer's inset: bottom-right, a third of the frame's width, the texture's aspect kept.
glm::ivec4 inset_rect(int frame_w, int frame_h, int tex_w, int tex_h);

// The texel of a texture drawn into `rect` showing `uv_rect` under the frame pixel `pixel`
// (GL, origin bottom-left); nullopt outside the rect or the texture.
std::optional<glm::ivec2> pixel_to_texel(glm::ivec2 pixel, const glm::ivec4& rect, const glm::vec4& uv_rect,
                                         int tex_w, int tex_h);

}  // namespace penumbra::sandbox
