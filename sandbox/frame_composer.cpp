#include "sandbox/frame_composer.h"

#include <algorithm>
#include <cmath>

#include "technique/frame_graph.h"
#include "scene/light.h"
#include "util/png.h"
#include "util/row_order.h"

namespace penumbra::sandbox {

Status compose_frame(DisplayPass& display, const FrameInputs& in) {
  const bool comparing = in.secondary != nullptr;
  // Compose: base layer (colour, split or error map), then the viewed resource.
  display.begin();
  DisplayPass::Layer base;
  base.viewport = {0, 0, in.width, in.height};
  base.uv_rect = zoomed_uv_rect(in.viewer.zoom);
  gl::Texture* color_a = in.primary.executor().resource(technique::kColor);
  if (!color_a) return make_error("the frame has no 'color' resource", ErrorKind::internal);
  if (in.texel_density) {
    gl::Texture* depth = in.primary.executor().resource("gbuffer_depth");
    if (!depth) return make_error("texel density: the frame has no gbuffer_depth", ErrorKind::internal);
    const scene::ShadowFrustum f = scene::shadow_frustum(in.primary.light(), in.primary.scene().bounds);
    if (Status s = display.texel_density(*depth, in.primary.camera(), f.view_proj, in.primary.settings().shadow_size, base.uv_rect,
                                         in.viewer.zoom.zoom);
        !s)
      return s;
  } else if (comparing && in.compare.view == CompareState::View::error && in.compare.show_classes &&
             in.compare.classes.width == in.width && in.compare.classes.height == in.height) {
    if (display.picture_version() != in.compare.classes_version || !display.picture_texture())
      if (Status s = display.upload_picture(metrics::pixel_class_image(in.compare.classes), in.compare.classes_version); !s)
        return s;
    base.texture = &display.picture_texture();
    if (Status s = display.draw(base); !s) return s;
  } else if (comparing && in.compare.view == CompareState::View::error) {
    gl::Texture* a = in.primary.executor().resource(technique::kShadowMask);
    gl::Texture* b = in.secondary->executor().resource(technique::kShadowMask);
    gl::Texture* depth = in.primary.executor().resource("gbuffer_depth");
    if (!a || !b || !depth) return make_error("compare: shadow_mask or gbuffer_depth missing", ErrorKind::internal);
    if (Status s = display.difference(*a, *b, *depth); !s) return s;
    base.texture = &display.difference_texture();
    base.map = ViewerSettings::Map::signed_error;
    const float scale = std::max(in.compare.error_max, 1e-4f);
    base.range = {-scale, scale};
    base.coverage_in_g = true;
    if (Status s = display.draw(base); !s) return s;
  } else if (comparing) {
    // Columns A | B (| reference), each the same pixels of its own session's image.
    std::vector<technique::TechniqueSession*> sessions = {&in.primary, in.secondary};
    if (in.third) sessions.push_back(in.third);
    const std::vector<int> edges = column_edges(in.compare, in.width, static_cast<int>(sessions.size()));
    for (size_t i = 0; i < sessions.size(); ++i) {
      const int x0 = edges[i], x1 = edges[i + 1];
      if (x1 <= x0) continue;
      gl::Texture* color = sessions[i]->executor().resource(technique::kColor);
      DisplayPass::Layer column = base;
      column.texture = color ? color : color_a;
      column.viewport = {x0, 0, x1 - x0, in.height};
      column.uv_rect = zoomed_uv_rect(in.viewer.zoom, {float(x0) / in.width, 0.0f, float(x1 - x0) / in.width, 1.0f});
      if (Status s = display.draw(column); !s) return s;
    }
  } else {
    base.texture = color_a;
    if (Status s = display.draw(base); !s) return s;
  }

  if (!in.viewer.resource.empty()) {
    if (gl::Texture* t = in.primary.executor().resource(in.viewer.resource)) {
      DisplayPass::Layer v;
      v.texture = t;
      v.map = in.viewer.map;
      v.channel = in.viewer.channel;
      v.channel_mask = in.viewer.channel_mask;
      v.range = {in.viewer.min, in.viewer.max};
      v.linearize_depth = in.viewer.linearize_depth && t->info().is_depth && t->width() == in.width &&
                          t->height() == in.height;
      v.near_far = {in.primary.camera().near_plane, in.primary.camera().far_plane};
      if (in.viewer.placement == ViewerSettings::Placement::full) {
        // The texture's own aspect (a square shadow map stays square), zoomed like the frame.
        v.viewport = fitted_rect(in.width, in.height, t->width(), t->height());
        v.uv_rect = zoomed_uv_rect(in.viewer.zoom);
      } else {
        v.viewport = inset_rect(in.width, in.height, t->width(), t->height());
      }
      if (Status s = display.draw(v); !s) return s;
    }
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return {};
}

Status save_target_png(const DisplayPass& display, const std::string& path) {
  const gl::Texture& t = display.target();
  std::vector<unsigned char> bottom_up(static_cast<size_t>(t.width()) * t.height() * 4);
  glGetTextureImage(t.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, static_cast<GLsizei>(bottom_up.size()),
                    bottom_up.data());
  return write_png_rgba8(path, t.width(), t.height(), rows_flipped(bottom_up, static_cast<size_t>(t.width()) * 4, t.height()));
}

}  // namespace penumbra::sandbox
