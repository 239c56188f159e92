#include "sandbox/ui_state_dump.h"

#include <imgui.h>
#include <nlohmann/json.hpp>

#include "sandbox/inspector.h"
#include "sandbox/param_applicability.h"
#include "sandbox/user_presets.h"
#include "util/file_write.h"

namespace penumbra::sandbox {

namespace {

using nlohmann::json;

json rect(const Rect& r) { return json::array({r.x, r.y, r.w, r.h}); }
json rect(const std::optional<UiProbe::Rect>& r) { return r ? json(*r) : json(nullptr); }
json vec3(const glm::vec3& v) { return json::array({v.x, v.y, v.z}); }

json inspector_under_mouse(SandboxController& c, const Layout& layout) {
  const ImVec2 m = ImGui::GetIO().MousePos;
  const int px = int(m.x) - layout.viewport.x, py = int(m.y) - layout.viewport.y;
  if (px < 0 || py < 0 || px >= c.width() || py >= c.height() || c.frames() == 0) return nullptr;
  Result<PixelReadout> r = inspect_pixel(c, {px, py});
  if (!r || !r->texel) return nullptr;
  return {{"pixel", {px, py}}, {"texel", {r->texel->x, r->texel->y}}, {"source", r->source}, {"text", readout_text(*r)}};
}

}  // namespace

Status write_ui_state(const std::string& path, SandboxController& c, const UiState& ui, const Layout& layout,
                      std::uint64_t frame, int window_w, int window_h) {
  json j;
  j["frame"] = frame;
  j["window"] = {window_w, window_h};
  j["panel"] = rect(layout.panel);
  j["divider"] = rect(layout.divider);
  j["viewport"] = rect(layout.viewport);
  j["frame_size"] = {c.width(), c.height()};
  j["items"] = json::object();
  for (const auto& [id, r] : ui.probe.items) j["items"][id] = r;
  j["combos"] = ui.probe.combos;
  j["open_popup"] = ui.probe.open_popup;
  j["popup"] = rect(ui.probe.popup);
  j["tooltip"] = rect(ui.probe.tooltip);
  j["keys"] = ui.probe.keys;
  j["texts"] = ui.probe.texts;
  j["active"] = ui.probe.active;
  j["fields"] = {{"preset name", ui.preset_name}, {"glTF", ui.scene_path}, {"screenshot path", ui.screenshot_path},
                 {"metrics file", ui.metrics_path}, {"into", ui.sequence_dir}, {"save to", ui.save_dir},
                 {"frames", std::to_string(ui.sequence.frames)}};
  j["scene"] = c.scene_name();
  j["technique"] = c.session().technique();
  technique::TechniqueSession& s = c.session();
  j["params"] = json::object();
  j["capped"] = json::object();
  for (const graph::ParamDesc& d : s.params().descs()) {
    if (const graph::ParamValue* v = s.params().get(d.name)) j["params"][d.name] = graph::param_value_to_string(*v);
    const Applicability a = param_applicability(d, s.params(), s.graph(), s.plan());
    if (!a.capped.empty()) j["capped"][d.name] = a.capped;
  }
  j["presets"] = {{"shipped", c.shipped_presets()}, {"saved", user_presets(user_preset_dir(), s.technique())}};
  j["graph_open"] = ui.graph_open;
  const CompareState& cs = c.compare();
  j["compare"] = {{"enabled", cs.enabled}, {"view", cs.view == CompareState::View::split ? "split" : "error"},
                  {"split", cs.split}, {"split2", cs.split2}, {"three_way", c.reference_session() != nullptr},
                  {"classes", cs.show_classes},
                  {"with", c.secondary() ? c.secondary()->technique() : ""},
                  {"stats", cs.stats ? json{{"rmse", cs.stats->rmse}} : json(nullptr)},
                  {"stats_b", cs.stats_b ? json{{"rmse", cs.stats_b->rmse}} : json(nullptr)}};
  j["viewer"] = {{"resource", c.viewer().resource}, {"zoom", c.viewer().zoom.zoom}};
  j["pool_textures"] = s.pool().texture_count();
  j["timing"] = exec::timing_mode_name(s.executor().timing_mode());
  j["inspector"] = inspector_under_mouse(c, layout);
  j["light_direction"] = vec3(c.light().direction);
  j["camera_forward"] = vec3(c.camera().forward());
  j["camera_position"] = vec3(c.camera().position);
  j["light_frozen"] = c.light_frozen();
  j["message"] = c.message();
  j["note"] = ui.note;
  const ImGuiStyle& style = ImGui::GetStyle();
  j["style"] = {{"popup_alpha", style.Colors[ImGuiCol_PopupBg].w}, {"window_alpha", style.Colors[ImGuiCol_WindowBg].w}};
  return write_file_whole(path, j.dump() + "\n");
}

}  // namespace penumbra::sandbox
