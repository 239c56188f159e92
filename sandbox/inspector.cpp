#include "sandbox/inspector.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include <nlohmann/json.hpp>

#include "sandbox/viewed_resource.h"
#include "technique/frame_graph.h"
#include "util/file_write.h"
#include "util/row_order.h"

namespace penumbra::sandbox {

namespace {

std::array<float, 4> read_texel(const gl::Texture& t, glm::ivec2 texel) {
  const gl::FormatInfo& f = t.info();
  std::array<float, 4> v{};
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTextureSubImage(t.id(), 0, texel.x, texel.y, 0, 1, 1, 1, f.pixel_format, GL_FLOAT,
                       static_cast<GLsizei>(sizeof(float) * f.channels), v.data());
  return v;
}


}  // namespace

Result<PixelReadout> inspect_pixel(SandboxController& c, glm::ivec2 pixel) {
  PixelReadout r;
  r.pixel = pixel;
  const glm::ivec2 gl_pixel(pixel.x, flipped_row(pixel.y, c.height()));
  const ViewerSettings& v = c.viewer();
  const gl::Texture* tex = nullptr;
  std::optional<glm::ivec2> texel;
  if (!v.resource.empty())
    if (gl::Texture* t = c.session().executor().resource(v.resource)) {
      const bool full = v.placement == ViewerSettings::Placement::full;
      const glm::ivec4 rect = full ? fitted_rect(c.width(), c.height(), t->width(), t->height())
                                   : inset_rect(c.width(), c.height(), t->width(), t->height());
      texel = pixel_to_texel(gl_pixel, rect, full ? zoomed_uv_rect(v.zoom) : glm::vec4(0, 0, 1, 1), t->width(),
                             t->height());
      if (texel || full) {
        tex = t;
        r.source = v.resource;
      }
    }
  if (!tex) {  // the final image under the pixel
    const CompareState& cs = c.compare();
    const bool comparing = cs.enabled && c.secondary();
    technique::TechniqueSession* side = &c.session();
    r.source = "color (A)";
    if (comparing && cs.view == CompareState::View::error) {
      tex = &c.display().difference_texture();
      r.source = "A - B";
    } else {
      if (comparing) {
        const std::vector<technique::TechniqueSession*> shown = c.shown_sessions();
        const std::vector<int> edges = column_edges(cs, c.width(), static_cast<int>(shown.size()));
        static const char* kSides[] = {"color (A)", "color (B)", "color (reference)"};
        for (size_t i = 1; i < shown.size(); ++i)
          if (pixel.x >= edges[i]) {
            side = shown[i];
            r.source = kSides[i];
          }
      }
      tex = side->executor().resource(technique::kColor);
    }
    if (!tex) return make_error("the frame has no image to inspect yet");
    texel = pixel_to_texel(gl_pixel, {0, 0, c.width(), c.height()}, zoomed_uv_rect(v.zoom), tex->width(), tex->height());
  }
  // The error image's second channel is receiver coverage, not a value to show.
  r.channels = r.source == "A - B" ? 1 : tex->info().channels;
  if (!texel) return r;
  r.texel = glm::ivec2(texel->x, flipped_row(texel->y, tex->height()));
  r.value = read_texel(*tex, *texel);
  if (screen_depth(*tex, c))
    r.linear_depth = linear_depth(r.value[0], c.camera().near_plane, c.camera().far_plane);
  return r;
}

std::string readout_text(const PixelReadout& r) {
  if (!r.texel) return "";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%s (%d, %d) =", r.source.c_str(), r.texel->x, r.texel->y);
  std::string out = buf;
  for (int i = 0; i < std::min(r.channels, 4); ++i) {
    std::snprintf(buf, sizeof buf, " %.5g", r.value[i]);
    out += buf;
  }
  if (r.linear_depth) {
    std::snprintf(buf, sizeof buf, "  (distance %.4g)", *r.linear_depth);
    out += buf;
  }
  return out;
}

Status write_inspection(SandboxController& c, int x, int y, const std::string& path) {
  if (x >= c.width() || y >= c.height())
    return make_error("inspect: pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") is outside the " +
                      std::to_string(c.width()) + "x" + std::to_string(c.height()) + " frame");
  Result<PixelReadout> r = inspect_pixel(c, {x, y});
  if (!r) return r.error();
  nlohmann::json j;
  j["source"] = r->source;
  j["pixel"] = {x, y};
  j["texel"] = r->texel ? nlohmann::json({r->texel->x, r->texel->y}) : nlohmann::json(nullptr);
  j["channels"] = r->channels;
  j["value"] = nlohmann::json::array();
  for (int k = 0; k < std::min(r->channels, 4); ++k) j["value"].push_back(r->value[k]);
  j["linear_depth"] = r->linear_depth ? nlohmann::json(*r->linear_depth) : nlohmann::json(nullptr);
  j["text"] = readout_text(*r);
  return write_file_whole(path, j.dump(2) + "\n");
}

}  // namespace penumbra::sandbox
