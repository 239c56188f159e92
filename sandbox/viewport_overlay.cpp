#include "sandbox/viewport_overlay.h"

#include <algorithm>
#include <cstdio>

#include <imgui.h>

#include "exec/gbuffer_readback.h"
#include "sandbox/compare_metrics.h"
#include "sandbox/inspector.h"
#include "sandbox/light_gizmo.h"
#include "sandbox/shadow_debug.h"
#include "sandbox/ui_widgets.h"
#include "technique/frame_graph.h"
#include "util/row_order.h"

namespace penumbra::sandbox {

namespace {

constexpr ImGuiWindowFlags kBare = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoBackground |
                                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                                   ImGuiWindowFlags_NoNav;

// An invisible button filling a bare window at `x`, `y` of `w` x `h`; returns the horizontal
// drag this frame (0 when not dragged) and whether it is hovered or held.
float drag_handle(const char* id, float x, float y, float w, float h, bool* hot) {
  ImGui::SetNextWindowPos(ImVec2(x, y));
  ImGui::SetNextWindowSize(ImVec2(w, h));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowMinSize, ImVec2(1, 1));
  ImGui::Begin(id, nullptr, kBare);
  ImGui::InvisibleButton("##handle", ImVec2(w, h));
  const bool active = ImGui::IsItemActive();
  *hot = active || ImGui::IsItemHovered();
  if (*hot) ImGui::SetMouseCursor(ImGuiMouseCursor_ResizeEW);
  ImGui::End();
  ImGui::PopStyleVar(2);
  return active ? ImGui::GetIO().MouseDelta.x : 0.0f;
}

void label(ImDrawList* dl, ImVec2 at, const std::string& text, float wrap) {
  const ImVec2 size = ImGui::CalcTextSize(text.c_str(), nullptr, false, wrap);
  dl->AddRectFilled(ImVec2(at.x - 4, at.y - 2), ImVec2(at.x + size.x + 4, at.y + size.y + 2), IM_COL32(0, 0, 0, 170), 3.0f);
  dl->AddText(nullptr, 0.0f, at, IM_COL32(240, 240, 240, 255), text.c_str(), nullptr, wrap);
}

// The error view's legend at the bottom-right corner (right, bottom): the signed map from
// -scale (A darker than B) to +scale (A lighter).
void error_legend(ImDrawList* dl, float right, float bottom, float scale) {
  const char* title = "A - B: blue A darker, red lighter";
  const float kW = std::max(170.0f, ImGui::CalcTextSize(title).x), kH = 10.0f;
  const float x = right - kW - 14.0f, y = bottom - kH - 26.0f;
  dl->AddRectFilled(ImVec2(x - 6, y - 20), ImVec2(x + kW + 6, y + kH + 20), IM_COL32(0, 0, 0, 170), 3.0f);
  dl->AddText(ImVec2(x, y - 17), IM_COL32(240, 240, 240, 255), title);
  draw_colour_bar(dl, ImVec2(x, y), ImVec2(kW, kH), ViewerSettings::Map::signed_error);
  char lo[24], hi[24];
  std::snprintf(lo, sizeof lo, "-%.3g", scale);
  std::snprintf(hi, sizeof hi, "+%.3g", scale);
  dl->AddText(ImVec2(x, y + kH + 2), IM_COL32(240, 240, 240, 255), lo);
  dl->AddText(ImVec2(x + kW * 0.5f - 3, y + kH + 2), IM_COL32(240, 240, 240, 255), "0");
  dl->AddText(ImVec2(x + kW - ImGui::CalcTextSize(hi).x, y + kH + 2), IM_COL32(240, 240, 240, 255), hi);
}

// The light gizmo (light_gizmo.h) centred at `centre`: drag inside the disk to move the light;
// the light's diameter in world units beside it.
void draw_light_gizmo(SandboxController& c, ImDrawList* dl, ImVec2 centre, UiProbe& probe) {
  const float r = kGizmoRadius;
  bool hot = false;
  ImGui::SetNextWindowPos(ImVec2(centre.x - r, centre.y - r));
  ImGui::SetNextWindowSize(ImVec2(2 * r, 2 * r));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
  ImGui::Begin("##light_gizmo", nullptr, kBare);
  ImGui::InvisibleButton("##disk", ImVec2(2 * r, 2 * r));
  hot = ImGui::IsItemHovered() || ImGui::IsItemActive();
  if (ImGui::IsItemActive() && !c.light_frozen()) {
    const ImVec2 m = ImGui::GetIO().MousePos;
    (void)c.set_light_direction(gizmo_direction(glm::vec2(m.x - centre.x, centre.y - m.y) / r, c.camera()));
  }
  probe_item(probe, "light gizmo");
  ImGui::End();
  ImGui::PopStyleVar();
  dl->AddCircleFilled(centre, r, IM_COL32(10, 12, 20, hot ? 210 : 160), 48);
  for (float ring : {1.0f / 3.0f, 2.0f / 3.0f, 1.0f}) dl->AddCircle(centre, r * ring, IM_COL32(150, 160, 180, 140), 48);
  dl->AddTriangleFilled(ImVec2(centre.x, centre.y - r - 6), ImVec2(centre.x - 4, centre.y - r + 2), ImVec2(centre.x + 4, centre.y - r + 2),
                        IM_COL32(200, 200, 220, 200));  // up: where the camera looks
  const glm::vec2 p = gizmo_point(c.light().direction, c.camera());
  const ImVec2 dot(centre.x + p.x * r, centre.y - p.y * r);
  dl->AddLine(centre, dot, IM_COL32(255, 160, 50, 160), 1.0f);
  dl->AddCircleFilled(dot, 6.0f, c.light_frozen() ? IM_COL32(140, 140, 150, 255) : IM_COL32(255, 170, 40, 255));
  char size[48];
  std::snprintf(size, sizeof size, "light %.3g wu across", c.light().size);
  label(dl, ImVec2(centre.x - r, centre.y + r + 6), size, 2 * r + 60);
}

// The light's frustum (yellow) and emitter (orange), projected over the frame.
void draw_light_frustum(SandboxController& c, ImDrawList* dl, float x0, float y0) {
  if (!c.session().has_scene()) return;
  const scene::ShadowFrustum f = scene::shadow_frustum(c.light(), c.session().scene().bounds);
  const ImVec2 o(x0, y0);
  for (const auto& [a, b] : project_segments(frustum_segments(f), c.camera(), c.width(), c.height()))
    dl->AddLine(ImVec2(o.x + a.x, o.y + a.y), ImVec2(o.x + b.x, o.y + b.y), IM_COL32(255, 230, 80, 200), 1.5f);
  for (const auto& [a, b] : project_segments(emitter_segments(c.light()), c.camera(), c.width(), c.height()))
    dl->AddLine(ImVec2(o.x + a.x, o.y + a.y), ImVec2(o.x + b.x, o.y + b.y), IM_COL32(255, 140, 40, 255), 2.0f);
}

// Beside the cursor: the light's size in world units and the penumbra it casts here, from the
// nearest blocker the shadow map holds in the receiver's blocker-search region (its bounding
// box read back in one piece, or every k-th texel of a box larger than 256 x 256).
void penumbra_label(SandboxController& c, ImDrawList* dl, ImVec2 at, const glm::vec3& receiver, const scene::ShadowFrustum& f,
                    const std::vector<glm::vec2>& region, UiProbe& probe) {
  const float size = c.light().size;
  gl::Texture* map = c.session().executor().resource("shadow_map");
  const int n = c.session().settings().shadow_size;
  char text[160];
  if (region.empty() || !map || !map->info().is_depth || map->width() != n || map->height() != n) {
    std::snprintf(text, sizeof text, "light %.3g wu across", size);
    label(dl, at, text, 260);
    probe.texts["penumbra"] = text;
    return;
  }
  glm::vec2 lo(1.0f), hi(0.0f);
  for (const glm::vec2& q : region) {
    lo = glm::min(lo, q);
    hi = glm::max(hi, q);
  }
  const glm::ivec2 t0 = glm::clamp(glm::ivec2(lo * float(n)), glm::ivec2(0), glm::ivec2(n - 1));
  const glm::ivec2 t1 = glm::clamp(glm::ivec2(hi * float(n)), glm::ivec2(0), glm::ivec2(n - 1));
  const glm::ivec2 extent = t1 - t0 + 1, step = (extent + 255) / 256;  // at most 256 x 256 texels
  const glm::ivec2 read = (extent + step - 1) / step;
  const float receiver_depth = shadow_depth(f, receiver);
  float nearest = 2.0f;
  std::vector<float> depths(static_cast<size_t>(step == glm::ivec2(1) ? read.x * read.y : 1));
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  if (step == glm::ivec2(1))
    glGetTextureSubImage(map->id(), 0, t0.x, t0.y, 0, extent.x, extent.y, 1, GL_DEPTH_COMPONENT, GL_FLOAT,
                         static_cast<GLsizei>(depths.size() * sizeof(float)), depths.data());
  for (int j = 0; j < read.y; ++j)
    for (int i = 0; i < read.x; ++i) {
      float d = 1.0f;
      if (step == glm::ivec2(1)) d = depths[static_cast<size_t>(j * read.x + i)];
      else glGetTextureSubImage(map->id(), 0, t0.x + i * step.x, t0.y + j * step.y, 0, 1, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, sizeof d, &d);
      if (d < receiver_depth - 1e-4f) nearest = std::min(nearest, d);
    }
  const float dr = light_distance(f, receiver_depth);
  if (nearest > 1.0f) {
    std::snprintf(text, sizeof text, "light %.3g wu across; no blocker between here and the light", size);
  } else {
    const float db = light_distance(f, nearest);
    std::snprintf(text, sizeof text, "light %.3g wu across -> penumbra %.3g wu here (blocker %.3g, receiver %.3g wu from the light)",
                  size, penumbra_width(size, dr, db), db, dr);
  }
  label(dl, at, text, 300);
  probe.texts["penumbra"] = text;
}

// The receiver under the cursor: its cone to the emitter in the scene and, when the viewer
// shows a shadow-map-sized resource, the blocker-search region on it.
void draw_blocker_region(SandboxController& c, ImDrawList* dl, float x0, float y0, int px, int py, UiProbe& probe) {
  gl::Texture* depth = c.session().executor().resource("gbuffer_depth");
  if (!depth || !c.session().has_scene() || depth->width() != c.width() || depth->height() != c.height()) return;
  const ViewZoom& z = c.viewer().zoom;
  const std::optional<glm::ivec2> t =
      pixel_to_texel({px, flipped_row(py, c.height())}, {0, 0, c.width(), c.height()}, zoomed_uv_rect(z), depth->width(), depth->height());
  if (!t) return;
  float view_depth = 0.0f;
  glGetTextureSubImage(depth->id(), 0, t->x, t->y, 0, 1, 1, 1, GL_RED, GL_FLOAT, sizeof view_depth, &view_depth);
  if (!(view_depth > 0.0f)) return;
  const float aspect = static_cast<float>(c.width()) / static_cast<float>(c.height());
  const exec::PixelRays rays = exec::pixel_rays(c.camera().view(), c.camera().projection(aspect), c.width(), c.height());
  const glm::vec3 receiver = exec::world_from_view_depth(rays, t->x, t->y, view_depth);
  const scene::Light& light = c.light();
  std::vector<Segment> cone;
  for (const glm::vec3& e : emitter_outline(light, 12)) cone.push_back({receiver, e});
  for (const auto& [a, b] : project_segments(cone, c.camera(), c.width(), c.height()))
    dl->AddLine(ImVec2(x0 + a.x, y0 + a.y), ImVec2(x0 + b.x, y0 + b.y), IM_COL32(80, 255, 200, 150), 1.0f);
  const scene::ShadowFrustum f = scene::shadow_frustum(light, c.session().scene().bounds);
  const std::vector<glm::vec2> region = blocker_search_region(receiver, light, f);
  penumbra_label(c, dl, ImVec2(x0 + float(px) + 14, y0 + float(py) + 14), receiver, f, region, probe);
  const ViewerSettings& v = c.viewer();
  const int shadow = c.session().settings().shadow_size;
  gl::Texture* shown = v.resource.empty() ? nullptr : c.session().executor().resource(v.resource);
  if (region.empty() || !shown || shown->width() != shadow || shown->height() != shadow) return;
  const bool full = v.placement == ViewerSettings::Placement::full;
  const glm::ivec4 rect = full ? fitted_rect(c.width(), c.height(), shadow, shadow) : inset_rect(c.width(), c.height(), shadow, shadow);
  const glm::vec4 uv = full ? zoomed_uv_rect(z) : glm::vec4(0, 0, 1, 1);
  std::vector<ImVec2> poly;
  for (const glm::vec2& q : region) {
    const glm::vec2 f01((q.x - uv.x) / uv.z, (q.y - uv.y) / uv.w);
    poly.push_back(ImVec2(x0 + rect.x + f01.x * rect.z, y0 + c.height() - (rect.y + f01.y * rect.w)));
  }
  dl->AddPolyline(poly.data(), static_cast<int>(poly.size()), IM_COL32(80, 255, 200, 255), ImDrawFlags_Closed, 2.0f);
}

}  // namespace

std::string settings_label(const technique::TechniqueSession& session) {
  std::string out = session.technique();
  std::string changed;
  for (const graph::ParamDesc& d : session.params().descs()) {
    const graph::ParamValue* v = session.params().get(d.name);
    if (v && *v != d.default_value) changed += " " + d.name + "=" + graph::param_value_to_string(*v);
  }
  return out + (changed.empty() ? "  (defaults)" : " " + changed);
}

void draw_panel_divider(int& panel_width, const Layout& layout) {
  bool hot = false;
  const float dx = drag_handle("##panel_divider", float(layout.divider.x), float(layout.divider.y),
                               float(std::max(layout.divider.w, 1)), float(layout.divider.h), &hot);
  if (dx != 0.0f) panel_width = layout.panel_width + static_cast<int>(dx);
  ImDrawList* dl = ImGui::GetForegroundDrawList();
  dl->AddRectFilled(ImVec2(float(layout.divider.x), float(layout.divider.y)),
                    ImVec2(float(layout.divider.x + layout.divider.w), float(layout.divider.y + layout.divider.h)),
                    hot ? IM_COL32(90, 140, 220, 255) : IM_COL32(55, 58, 66, 255));
}

void draw_viewport_overlay(SandboxController& c, const Layout& layout, UiProbe& probe) {
  const Rect& vp = layout.viewport;
  const float x0 = float(vp.x), y0 = float(vp.y);
  const float w = float(std::min(c.width(), vp.w)), h = float(std::min(c.height(), vp.h));
  ImDrawList* dl = ImGui::GetForegroundDrawList();
  // Nothing drawn here may spill onto the panel.
  dl->PushClipRect(ImVec2(x0, y0), ImVec2(x0 + float(vp.w), y0 + float(vp.h)), false);
  CompareState& cs = c.compare();
  if (cs.enabled && c.secondary()) {
    if (cs.view == CompareState::View::split) {
      // A | B (| reference): a draggable divider between columns, each column's label at its top.
      const std::vector<technique::TechniqueSession*> shown = c.shown_sessions();
      const std::vector<int> edges = column_edges(cs, c.width(), static_cast<int>(shown.size()));
      static const char* kNames[] = {"A: ", "B: ", "reference: "};
      for (size_t i = 0; i < shown.size(); ++i) {
        const float left = x0 + float(edges[i]), right = x0 + float(edges[i + 1]);
        label(dl, ImVec2(left + 8, y0 + 6), kNames[i] + settings_label(*shown[i]), std::max(right - left - 16, 60.0f));
      }
      for (size_t k = 1; k + 1 < edges.size(); ++k) {
        const float split_x = x0 + float(edges[k]);
        bool hot = false;
        const float dx = drag_handle(k == 1 ? "##split_divider" : "##split_divider_2", split_x - 4.0f, y0, 8.0f, h, &hot);
        float& split = k == 1 ? cs.split : cs.split2;
        if (dx != 0.0f && c.width() > 0) split = std::clamp(split + dx / float(c.width()), 0.0f, 1.0f);
        if (cs.split > cs.split2 && shown.size() == 3) (k == 1 ? cs.split2 : cs.split) = split;  // they never cross
        dl->AddLine(ImVec2(split_x, y0), ImVec2(split_x, y0 + h),
                    hot ? IM_COL32(120, 180, 255, 255) : IM_COL32(255, 255, 255, 200), hot ? 3.0f : 2.0f);
      }
    } else {
      label(dl, ImVec2(x0 + 8, y0 + 6),
            "A - B  A: " + settings_label(c.session()) + "   B: " + settings_label(*c.secondary()), w - 16);
      error_legend(dl, x0 + w, y0 + h, cs.error_max);
    }
    // The statistics on the view itself, in every view mode, so window screenshots carry them.
    const bool three = cs.three_way && c.reference_session();
    float y = y0 + 28;
    for (const auto& [who, e] : {std::pair{three ? "A vs reference: " : "", &cs.stats}, std::pair{"B vs reference: ", &cs.stats_b}}) {
      if (!*e || (e == &cs.stats_b && !three)) continue;
      char stats[200];
      std::snprintf(stats, sizeof stats, "%sRMSE %.4f  penumbra %s  MAE %.4f  max %.3f", who, (*e)->rmse,
                    penumbra_rmse_text(**e).c_str(), (*e)->mae, (*e)->max_error);
      std::string line = stats;
      if (const std::string p = progress_text(c); !p.empty() && e == &cs.stats) line += "  |  " + p;
      label(dl, ImVec2(x0 + 8, y), line, std::max(w - 16, 60.0f));
      y += 20;
    }
  }
  const ViewerSettings& v = c.viewer();
  if (!v.resource.empty() && !c.session().executor().resource(v.resource))
    label(dl, ImVec2(x0 + 8, y0 + h - 48), "viewed resource '" + v.resource + "' is not produced by the current graph",
          std::max(w - 16, 60.0f));
  if (v.zoom.zoom > 1.0f) {
    char z[32];
    std::snprintf(z, sizeof z, "zoom %.3gx", v.zoom.zoom);
    label(dl, ImVec2(x0 + w - 90, y0 + h - 24), z, 90);
  }
  if (c.debug_views().light_frustum) draw_light_frustum(c, dl, x0, y0);
  if (c.debug_views().light_gizmo) draw_light_gizmo(c, dl, ImVec2(x0 + 20 + kGizmoRadius, y0 + h - 48 - kGizmoRadius), probe);
  // The pixel inspector: the value under the cursor.
  const ImVec2 mouse = ImGui::GetIO().MousePos;
  const int px = int(mouse.x) - vp.x, py = int(mouse.y) - vp.y;
  if (c.debug_views().blocker_region && px >= 0 && py >= 0 && px < int(w) && py < int(h) && c.frames() > 0)
    draw_blocker_region(c, dl, x0, y0, px, py, probe);
  if (px >= 0 && py >= 0 && px < int(w) && py < int(h) && !ImGui::GetIO().WantCaptureMouse && c.frames() > 0)
    if (Result<PixelReadout> r = inspect_pixel(c, {px, py}); r && r->texel)
      label(dl, ImVec2(x0 + 8, y0 + h - 24), readout_text(*r), std::max(w - 110, 60.0f));
  if (!c.refused().empty())
    label(dl, ImVec2(x0 + 12, y0 + h * 0.5f - 20), "frame refused: " + c.refused(), std::max(w - 24, 60.0f));
  dl->PopClipRect();
}

}  // namespace penumbra::sandbox
