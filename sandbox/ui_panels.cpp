#include "sandbox/ui_panels.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <system_error>

#include <imgui.h>
#include <imgui_internal.h>

#include "sandbox/viewed_resource.h"
#include "sandbox/compare_metrics.h"
#include "sandbox/graph_view.h"
#include "sandbox/inspector.h"
#include "sandbox/param_applicability.h"
#include "sandbox/user_presets.h"
#include "sandbox/viewport_overlay.h"
#include "sandbox/widget_spec.h"
#include "scene/builtin_scenes.h"

namespace penumbra::sandbox {

namespace {

const ImVec4 kRed(1.0f, 0.35f, 0.3f, 1.0f);
const ImVec4 kAmber(1.0f, 0.75f, 0.3f, 1.0f);

void tooltip(const std::string& text) { item_tooltip(text); }


std::string mib(std::uint64_t bytes) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f MiB", double(bytes) / (1024.0 * 1024.0));
  return buf;
}

// Widgets ignore returned Statuses on purpose: the controller shows every error in message().

// One parameter: the widget its description asks for, then a reset button at the right edge.
// The widget takes what the label and the button leave; a label too long for that goes on its
// own line above, so neither the label nor the button is ever cut at the panel's edge.
// Parameters with no effect under the current settings are disabled, the reason in the tooltip;
// one capped by another says so under it.
void parameter_widget(SandboxController& c, UiState& ui, const graph::ParamDesc& d) {
  const WidgetSpec w = widget_for(d);
  const graph::ParameterSet& params = c.session().params();
  const Applicability a = param_applicability(d, params, c.session().graph(), c.session().plan());
  const ImGuiStyle& style = ImGui::GetStyle();
  const float avail = ImGui::GetContentRegionAvail().x;
  const float reset_w = ImGui::CalcTextSize("reset").x + 2.0f * style.FramePadding.x;
  const float label_w = ImGui::CalcTextSize(w.label.c_str()).x;
  float widget_w = avail - reset_w - label_w - style.ItemInnerSpacing.x - style.ItemSpacing.x;
  std::string label = w.label;
  if (widget_w < avail * 0.4f) {
    ImGui::TextUnformatted(w.label.c_str());
    label = "##" + w.label;
    widget_w = avail - reset_w - style.ItemSpacing.x;
  }
  ImGui::PushID(d.name.c_str());
  if (!a.applies) ImGui::BeginDisabled();
  ImGui::SetNextItemWidth(widget_w);
  switch (w.kind) {
    case WidgetKind::checkbox: {
      bool v = params.get_bool(d.name);
      if (ImGui::Checkbox(label.c_str(), &v)) (void)c.set_param_value(d.name, v);
      break;
    }
    case WidgetKind::slider_int:
    case WidgetKind::drag_int: {
      int v = params.get_int(d.name);
      bool changed = w.kind == WidgetKind::slider_int
                         ? ImGui::SliderInt(label.c_str(), &v, int(w.min), int(w.max))
                         : ImGui::DragInt(label.c_str(), &v, float(w.drag_speed));
      // Only valid values are offered: a step (odd sizes) snaps to the nearest valid one.
      v = valid_int_value(d, v);
      // Structural ones recompile on every step of a drag: compiling is CPU-cheap and the pool
      // hands the same textures back.
      if (changed && v != params.get_int(d.name)) (void)c.set_param_value(d.name, v);
      break;
    }
    case WidgetKind::slider_float:
    case WidgetKind::drag_float: {
      float v = static_cast<float>(params.get_real(d.name));
      bool changed = w.kind == WidgetKind::slider_float
                         ? ImGui::SliderFloat(label.c_str(), &v, float(w.min), float(w.max), "%.4g")
                         : ImGui::DragFloat(label.c_str(), &v, float(w.drag_speed), 0.0f, 0.0f, "%.4g");
      if (changed) (void)c.set_param_value(d.name, double(v));
      break;
    }
    case WidgetKind::combo: {
      std::string current = params.get_enum(d.name);
      if (begin_combo(ui.probe, d.name.c_str(), current.c_str())) {
        for (const std::string& o : w.options)
          if (selectable(ui.probe, d.name.c_str(), o, o == current)) (void)c.set_param_value(d.name, o);
        ImGui::EndCombo();
      }
      break;
    }
  }
  if (w.kind != WidgetKind::combo) probe_item(ui.probe, d.name);
  if (!a.applies) {
    ImGui::EndDisabled();
    tooltip(a.reason + "\n\n" + w.tooltip);
  } else {
    tooltip(w.tooltip);
  }
  ImGui::SameLine(std::max(ImGui::GetCursorPosX(), ImGui::GetWindowContentRegionMax().x - reset_w));
  if (ImGui::SmallButton("reset")) (void)c.reset_param(d.name);
  probe_item(ui.probe, "reset:" + d.name);
  tooltip("back to the default " + graph::param_value_to_string(d.default_value));
  if (!a.capped.empty()) {
    ImGui::TextColored(kAmber, "  capped by %s", d.capped_by->param.c_str());
    probe_item(ui.probe, "capped:" + d.name);
    tooltip(a.capped);
  }
  ImGui::PopID();
}

void scene_panel(SandboxController& c, UiState& ui) {
  const bool open = ImGui::CollapsingHeader("Scene", ImGuiTreeNodeFlags_DefaultOpen);
  probe_item(ui.probe, "Scene");
  if (!open) return;
  if (begin_combo(ui.probe, "scene", c.scene_name().c_str())) {
    for (const std::string& n : scene::builtin_scene_names())
      if (selectable(ui.probe, "scene", n, n == c.scene_name())) (void)c.load_scene(n);
    ImGui::EndCombo();
  }
  ImGui::InputText("glTF", ui.scene_path, sizeof ui.scene_path);
  probe_item(ui.probe, "glTF");
  ImGui::SameLine();
  if (ImGui::Button("open")) (void)c.load_scene(ui.scene_path);
  tooltip("load a .gltf/.glb file; on failure the current scene stays");
  bool ground = c.staging().ground;
  if (ImGui::Checkbox("ground plane", &ground)) (void)c.set_ground(ground);
  tooltip(c.ground_added() ? "a plane was added under the model (it has no floor of its own); reloads the scene"
                           : "adds a plane under models that have no floor of their own (reloads the scene); "
                             "this scene has its own or the switch is off");
  const auto& cams = c.file_cameras();
  const scene::CameraChoice& choice = c.staging().camera;
  std::string current = choice.kind == scene::CameraChoice::Kind::scene ? "default" : "fitted to the model";
  if (choice.kind == scene::CameraChoice::Kind::file)
    current = "file: " + (choice.file_camera.empty() ? std::string("0") : choice.file_camera);
  // "camera", not "view": one ImGui ID per window, and the compare panel has a "view" combo.
  if (begin_combo(ui.probe, "camera", current.c_str())) {
    if (selectable(ui.probe, "camera", "fitted to the model", choice.kind != scene::CameraChoice::Kind::file))
      (void)c.set_camera_choice({.kind = scene::CameraChoice::Kind::fitted});
    for (size_t i = 0; i < cams.size(); ++i) {
      const std::string label = "file: " + std::to_string(i) + (cams[i].name.empty() ? "" : " " + cams[i].name);
      if (selectable(ui.probe, "camera", label, choice.kind == scene::CameraChoice::Kind::file &&
                                                   choice.file_camera == std::to_string(i)))
        (void)c.set_camera_choice({.kind = scene::CameraChoice::Kind::file, .file_camera = std::to_string(i)});
    }
    ImGui::EndCombo();
  }
  tooltip(cams.empty() ? "the camera fitted to the model's bounds (this scene places no camera of its own)"
                       : "the camera fitted to the model's bounds, or one the glTF file places");
  const scene::Camera& cam = c.camera();
  ImGui::TextDisabled("camera (%.2f, %.2f, %.2f) yaw %.0f pitch %.0f deg", cam.position.x, cam.position.y,
                      cam.position.z, glm::degrees(cam.yaw), glm::degrees(cam.pitch));
}

// Cascaded shadow maps (scene/cascades.h) for a directional light: how many, where the splits
// fall, the blend band, and the debug tint of the cascade each pixel reads; live, no recompile.
void cascade_controls(SandboxController& c, UiState& ui) {
  scene::CascadeSettings s = c.session().cascades();
  bool changed = ImGui::SliderInt("cascades", &s.count, 1, scene::kMaxCascades);
  probe_item(ui.probe, "cascades");
  tooltip("shadow-map cascades over the camera's view range; they share the map's texels (4 of a 2048 map are "
          "1024 each)");
  if (s.count > 1) {
    changed |= ImGui::SliderFloat("split lambda", &s.split_lambda, 0.0f, 1.0f, "%.2f");
    tooltip("where the splits fall: 0 evenly spaced, 1 logarithmic (even texel density in perspective)");
    changed |= ImGui::SliderFloat("blend band", &s.blend, 0.0f, 0.5f, "%.2f");
    tooltip("band (fraction of a cascade's half side) over which it dithers into the next");
    changed |= ImGui::Checkbox("tint cascades", &s.tint);
    probe_item(ui.probe, "tint cascades");
    tooltip("debug view: the image tinted by the cascade each pixel reads (red, green, blue, yellow from the nearest)");
  }
  if (changed) (void)c.set_cascades(s);
}

void light_panel(SandboxController& c, UiState& ui) {
  const bool open = ImGui::CollapsingHeader("Light", ImGuiTreeNodeFlags_DefaultOpen);
  probe_item(ui.probe, "Light");
  if (!open) return;
  scene::Light& l = c.light();
  bool frozen = c.light_frozen();
  if (ImGui::Checkbox("freeze light", &frozen)) c.set_light_frozen(frozen);
  probe_item(ui.probe, "freeze light");
  tooltip("keep the light and its shadow frustum (fitted to the scene, never to the camera) where they are while "
          "the camera moves: Space, the gizmo and the fields below are refused until unticked");
  if (frozen) ImGui::BeginDisabled();
  int type = static_cast<int>(l.type);  // the combo lists LightType in declaration order
  if (combo_index(ui.probe, "type", &type, {"directional", "spot", "point"}))
    (void)c.set_light_type(static_cast<scene::LightType>(type));
  if (l.type == scene::LightType::point)
    tooltip("light in every direction from its position; only esm renders it inside the scene bounds "
            "(six shadow-map faces), one-map techniques need it outside them");
  glm::vec3 dir = l.direction;
  if (ImGui::DragFloat3("direction", &dir.x, 0.01f, -1.0f, 1.0f)) (void)c.set_light_direction(dir);
  glm::vec3 position = l.position;
  if (ImGui::DragFloat3("position", &position.x, 0.05f)) (void)c.set_light_position(position);
  tooltip(l.type == scene::LightType::point ? "emitter sphere centre, world units" : "emitter disk centre, world units");
  float size = l.size;
  if (ImGui::DragFloat("size", &size, 0.005f, 0.0f, 100.0f, "%.3f")) (void)c.set_light_size(std::max(size, 0.0f));
  tooltip(l.type == scene::LightType::point ? "emitter sphere DIAMETER, world units" : "emitter disk DIAMETER, world units");
  if (l.type == scene::LightType::spot) {
    float deg = glm::degrees(l.spot_angle);
    if (ImGui::SliderFloat("spot angle", &deg, scene::kMinSpotAngleDegrees, scene::kMaxSpotAngleDegrees, "%.0f deg")) (void)c.set_spot_angle(glm::radians(deg));
  }
  if (frozen) ImGui::EndDisabled();
  static const int kSizes[] = {256, 512, 1024, 2048, 4096};
  int shadow = c.session().settings().shadow_size;
  if (begin_combo(ui.probe, "shadow map", (std::to_string(shadow) + " texels").c_str())) {
    for (int s : kSizes)
      if (selectable(ui.probe, "shadow map", std::to_string(s), s == shadow)) (void)c.set_shadow_size(s);
    ImGui::EndCombo();
  }
  if (l.type == scene::LightType::directional) cascade_controls(c, ui);
  ImGui::Checkbox("light gizmo", &c.debug_views().light_gizmo);
  probe_item(ui.probe, "light gizmo toggle");
  tooltip("a sky disk in the viewport's corner (zenith at the centre, up = where the camera looks): drag the "
          "light's dot to move it; beside it the light's diameter in world units");
  ImGui::SameLine();
  if (ImGui::Button("light = view direction (Space)")) (void)c.align_light_with_camera();
  probe_item(ui.probe, "light = view direction (Space)");
}

// The technique's shipped presets and the user's saved ones: one click loads one. Saving names
// the preset and puts it in user_preset_dir(), where the menu finds it.
void preset_menu(SandboxController& c, UiState& ui) {
  const std::string technique = c.session().technique();
  const std::filesystem::path dir = user_preset_dir();
  if (begin_combo(ui.probe, "preset", "load a preset...")) {
    const std::vector<std::string> shipped = c.shipped_presets(), saved = user_presets(dir, technique);
    for (const std::string& n : shipped)
      if (selectable(ui.probe, "preset", n, false) && c.load_preset(n)) ui.post("loaded preset " + n, ImGui::GetTime());
    if (!shipped.empty() && !saved.empty()) ImGui::Separator();
    for (const std::string& n : saved) {
      const std::string path = (dir / technique / (n + ".json")).string();
      if (selectable(ui.probe, "preset", n + " (saved)", false) && c.load_preset(path)) ui.post("loaded " + path, ImGui::GetTime());
      tooltip(path);
    }
    if (shipped.empty() && saved.empty()) ImGui::TextDisabled("%s ships no presets and none is saved", technique.c_str());
    ImGui::EndCombo();
  }
  tooltip("presets shipped with " + technique + " (\"paper\": the paper's constants) and those saved below");
  const float button_w = ImGui::CalcTextSize("save as").x + 2.0f * ImGui::GetStyle().FramePadding.x;
  ImGui::SetNextItemWidth(std::max(ImGui::GetContentRegionAvail().x * 0.45f, 60.0f));
  ImGui::InputText("##preset name", ui.preset_name, sizeof ui.preset_name);
  probe_item(ui.probe, "preset name");
  ImGui::SameLine();
  if (ImGui::Button("save as", ImVec2(button_w, 0))) {
    Result<std::filesystem::path> path = user_preset_path(dir, technique, ui.preset_name);
    std::error_code ec;
    if (path) std::filesystem::create_directories(path->parent_path(), ec);
    Status st = c.note(!path ? Status(path.error()) : c.save_preset(path->string()));
    if (st) ui.post("saved " + path->string(), ImGui::GetTime());
  }
  probe_item(ui.probe, "save as");
  tooltip("save the current values as a preset named on the left, in " + (dir / technique).string());
}

void technique_panel(SandboxController& c, UiState& ui) {
  const bool open = ImGui::CollapsingHeader("Technique", ImGuiTreeNodeFlags_DefaultOpen);
  probe_item(ui.probe, "Technique");
  if (!open) return;
  technique::TechniqueSession& s = c.session();
  if (begin_combo(ui.probe, "technique", s.technique().c_str())) {
    for (const std::string& n : c.technique_names()) {
      if (selectable(ui.probe, "technique", n, n == s.technique())) (void)c.set_technique(n);
      tooltip(c.technique_description(n));
    }
    ImGui::EndCombo();
  }
  ImGui::TextWrapped("%s", s.graph().description.c_str());
  preset_menu(c, ui);
  for (const graph::ParamDesc& d : s.params().descs()) parameter_widget(c, ui, d);
  if (ImGui::Button("reset all")) (void)c.reset_param("all");
  probe_item(ui.probe, "reset all");
  ImGui::SameLine();
  ImGui::TextDisabled("compiles: %4d", s.compile_count());
}

void graph_panel(SandboxController& c, UiState& ui) {
  // Closed at start: it is taller than the rest together.
  ui.graph_open = ImGui::CollapsingHeader("Graph");
  probe_item(ui.probe, "Graph");
  if (!ui.graph_open) return;
  technique::TechniqueSession& s = c.session();
  const graph::CompiledPlan& plan = s.plan();
  draw_graph_view(c, ui.graph_view, ui.probe);
  ImGui::TextDisabled("times: %s", exec::timing_mode_name(s.executor().timing_mode()));
  probe_item(ui.probe, "times");
  ImGui::Text("memory: naive %s, assigned %s", mib(plan.memory.naive_bytes).c_str(),
              mib(plan.memory.assigned_bytes).c_str());
  ImGui::Text("pool: %zu textures, %s", s.pool().texture_count(), mib(s.pool().bytes()).c_str());
  bool no_reuse = s.compile_options().no_reuse;
  if (ImGui::Checkbox("no reuse", &no_reuse)) (void)c.set_no_reuse(no_reuse);
  bool extended = s.compile_options().extended_lifetimes;
  ImGui::SameLine();
  if (ImGui::Checkbox("extended lifetimes", &extended)) (void)c.set_extended_lifetimes(extended);
  bool immediate = s.executor().options().immediate;
  ImGui::SameLine();
  if (ImGui::Checkbox("immediate", &immediate)) (void)c.set_immediate(immediate);
  tooltip("glFinish and a GL error check after every pass");
}

// The legend of the viewer's colour map: the gradient from min to max, labelled.
void colour_bar(const ViewerSettings& v) {
  if (v.resource.empty() || v.map == ViewerSettings::Map::color) return;
  const ImVec2 at = ImGui::GetCursorScreenPos();
  const float w = ImGui::GetContentRegionAvail().x * 0.9f, h = 12.0f;
  draw_colour_bar(ImGui::GetWindowDrawList(), at, ImVec2(w, h), v.map);
  ImGui::Dummy(ImVec2(w, h));
  ImGui::Text("%.4g", v.min);
  ImGui::SameLine(w * 0.5f - 20.0f);
  ImGui::Text("%.4g", 0.5 * (double(v.min) + double(v.max)));
  ImGui::SameLine(std::max(w - 50.0f, 0.0f));
  ImGui::Text("%.4g", v.max);
}

void viewer_panel(SandboxController& c, UiState& ui) {
  const bool open = ImGui::CollapsingHeader("Resource viewer");
  probe_item(ui.probe, "Resource viewer");
  if (!open) return;
  ViewerSettings& v = c.viewer();
  const char* shown = v.resource.empty() ? "(off)" : v.resource.c_str();
  if (begin_combo(ui.probe, "resource", shown, ImGuiComboFlags_HeightLarge)) {  // graphs hold 20 or more
    if (selectable(ui.probe, "resource", "(off)", v.resource.empty())) (void)c.view_resource("");
    for (const std::string& n : c.session().executor().resource_names())
      if (selectable(ui.probe, "resource", n, n == v.resource)) (void)c.view_resource(n);
    ImGui::EndCombo();
  }
  int map = static_cast<int>(v.map);
  if (combo_index(ui.probe, "colour map", &map, {"colour", "grey", "heat", "signed"})) v.map = static_cast<ViewerSettings::Map>(map);
  int place = static_cast<int>(v.placement);
  if (combo_index(ui.probe, "placement", &place, {"full screen", "inset"}))
    v.placement = static_cast<ViewerSettings::Placement>(place);
  ImGui::DragFloatRange2("range", &v.min, &v.max, 0.005f, 0.0f, 0.0f, "min %.4g", "max %.4g");
  if (ImGui::Button("auto range")) (void)c.note(apply_auto_range(c));
  tooltip("min/max of the viewed channel (view distance for screen depth, background skipped)");
  ImGui::SameLine();
  ImGui::Checkbox("follow", &v.auto_range);
  tooltip("keep the range at the resource's min/max (every 15 frames)");
  colour_bar(v);
  if (v.map == ViewerSettings::Map::color) {
    // Per-channel toggles, as in RenderDoc: alpha alone is shown as grey.
    const char* names[] = {"R", "G", "B", "A"};
    for (unsigned ch = 0; ch < 4; ++ch) {
      bool on = (v.channel_mask >> ch) & 1u;
      if (ch > 0) ImGui::SameLine();
      if (ImGui::Checkbox(names[ch], &on)) v.channel_mask = on ? v.channel_mask | (1u << ch) : v.channel_mask & ~(1u << ch);
      probe_item(ui.probe, std::string("channel ") + names[ch]);
    }
  } else {
    ImGui::SliderInt("channel", &v.channel, 0, 3);
  }
  ImGui::Checkbox("histogram", &v.histogram);
  tooltip("the viewed channel's values over the range above, 64 bins (outside values in the end bins), every 15 frames");
  if (v.histogram && !v.counts.empty()) {
    // Log heights: a mask's lit bin holds most pixels and would flatten the penumbra's.
    std::vector<float> heights(v.counts.size());
    std::transform(v.counts.begin(), v.counts.end(), heights.begin(), [](float n) { return std::log10(1.0f + n); });
    const float top = *std::max_element(v.counts.begin(), v.counts.end());
    char overlay[96];
    std::snprintf(overlay, sizeof overlay, "%.4g .. %.4g, log scale, top bin %.0f", v.min, v.max, top);
    ImGui::PlotHistogram("##histogram", heights.data(), static_cast<int>(heights.size()), 0, overlay, 0.0f,
                         std::max(std::log10(1.0f + top), 1.0f), ImVec2(ImGui::GetContentRegionAvail().x, 60));
    probe_item(ui.probe, "histogram plot");
  }
  ImGui::InputText("save to", ui.save_dir, sizeof ui.save_dir);
  probe_item(ui.probe, "save to");
  tooltip("folder for saved views: RESOURCE_frameN.png (as shown) or .pfm (float values)");
  for (const auto& [label, format] : {std::pair{"save PNG", ViewFormat::png}, std::pair{"save PFM", ViewFormat::pfm}}) {
    if (format == ViewFormat::pfm) ImGui::SameLine();
    if (ImGui::Button(label)) {
      Result<std::string> path = save_viewed_resource(c, ui.save_dir, format);
      if (path) ui.post("saved " + *path, ImGui::GetTime());
      else (void)c.note(path.error());
    }
    probe_item(ui.probe, label);
  }
  float zoom = v.zoom.zoom;
  if (ImGui::SliderFloat("zoom", &zoom, 1.0f, kMaxZoom, "%.2gx", ImGuiSliderFlags_Logarithmic)) {
    v.zoom.zoom = zoom;
    v.zoom = clamped(v.zoom);
  }
  tooltip("mouse wheel over the view zooms about the cursor, middle-drag pans; the compare split's sides zoom together");
  ImGui::SameLine();
  if (ImGui::SmallButton("1:1")) v.zoom = {};
  ImGui::Checkbox("linearise depth", &v.linearize_depth);
  tooltip("screen-size depth shown as view distance (world units), using the camera's near/far");
  SandboxController::DebugViews& dv = c.debug_views();
  ImGui::Checkbox("light frustum", &dv.light_frustum);
  tooltip("the shadow map's frustum (yellow) and the emitter disk with its direction (orange), drawn over the scene");
  ImGui::SameLine();
  ImGui::Checkbox("blocker search", &dv.blocker_region);
  probe_item(ui.probe, "blocker search");
  tooltip("for the pixel under the cursor: its cone to the emitter in the scene, and (viewing a shadow-map-sized "
          "resource) the region of the map where its blockers can be");
  ImGui::SameLine();
  ImGui::Checkbox("texel density", &dv.texel_density);
  tooltip("shadow-map texels per frame pixel on the receivers, log2 heat: blue 1/16 (blocky), green 1, red 16 (aliased)");
}

void compare_panel(SandboxController& c, UiState& ui) {
  const bool open = ImGui::CollapsingHeader("Compare");
  probe_item(ui.probe, "Compare");
  if (!open) return;
  CompareState& cs = c.compare();
  bool on = cs.enabled;
  if (ImGui::Checkbox("compare", &on)) (void)c.set_compare(on);
  probe_item(ui.probe, "compare");
  tooltip("split screen: left = active technique, right = the other one (its reference)");
  if (begin_combo(ui.probe, "against", cs.with.empty() ? "(default)" : cs.with.c_str())) {
    for (const std::string& n : c.technique_names())
      if (selectable(ui.probe, "against", n, n == cs.with)) (void)c.set_compare(true, n);
    ImGui::EndCombo();
  }
  if (!cs.enabled) return;
  bool three = cs.three_way;
  if (ImGui::Checkbox("three-way: A | B | reference", &three)) (void)c.set_three_way(three);
  probe_item(ui.probe, "three-way");
  tooltip("a third column runs the reference; the statistics are A's and B's against it");
  int view = static_cast<int>(cs.view);
  if (combo_index(ui.probe, "view", &view, {"split", "signed error (A - B)"}))
    c.set_compare_view(static_cast<CompareState::View>(view));
  if (cs.view == CompareState::View::split) {
    ImGui::SliderFloat("split", &cs.split, 0.0f, cs.three_way ? cs.split2 : 1.0f);
    if (cs.three_way) ImGui::SliderFloat("split 2", &cs.split2, cs.split, 1.0f);
  }
  else {
    ImGui::SliderFloat("error scale", &cs.error_max, 0.01f, 1.0f, "A - B = +-%.2f is full colour");
    ImGui::Checkbox("pixel classes", &cs.show_classes);
    probe_item(ui.probe, "pixel classes");
    tooltip("what the statistics are split by, from A's G-buffer and B's mask: white lit, black umbra, "
            "orange soft penumbra (penumbra RMSE), blue geometric edge (2 px of a depth or normal "
            "discontinuity or a terminator: its own RMSE), grey background, dark blue-grey outside "
            "the light (a spot's cone: in no statistic)");
  }
  ImGui::SliderInt("stats every", &cs.stats_every, 1, 120, "%d frames");
  const std::string progress = progress_text(c);
  if (!progress.empty()) {
    const bool done = progress_complete(c);
    ImGui::TextColored(done ? ImVec4(0.5f, 0.9f, 0.5f, 1.0f) : ImVec4(1.0f, 0.8f, 0.3f, 1.0f), "%s", progress.c_str());
    if (!done) tooltip("the RMSE means little until the technique has converged");
  }
  if (cs.stats) {
    ImGui::Text("RMSE %.4f   penumbra RMSE %s", cs.stats->rmse, penumbra_rmse_text(*cs.stats).c_str());
    tooltip("penumbra RMSE: over the soft penumbra, pixels where the right-hand side (the reference) is in "
            "0.02..0.98 away from geometric edges; n/a when it has none (e.g. against hard shadows); "
            "unreliable under 1% of the receivers or mostly single pixels (docs/evaluation.md)");
    ImGui::Text("geometric edge RMSE %.4f (%zu px)", cs.stats->rmse_geometric_edge, cs.stats->geometric_edge_pixels);
    ImGui::Text("MAE %.4f   max %.3f   %zu px (%zu soft penumbra)", cs.stats->mae, cs.stats->max_error,
                cs.stats->pixels, cs.stats->penumbra_pixels);
  }
  if (cs.stats_b && c.reference_session())
    ImGui::Text("B: RMSE %.4f   penumbra RMSE %s", cs.stats_b->rmse, penumbra_rmse_text(*cs.stats_b).c_str());
  if (!cs.rmse_history.empty()) {
    float top = 0.0f;
    for (float v : cs.rmse_history) top = std::max(top, v);
    char overlay[64];
    std::snprintf(overlay, sizeof overlay, "RMSE history, max %.4f", top);
    // An explicit width: ImGui 1.86 draws ImVec2(-1, h) as a sliver here.
    ImGui::PlotLines("##rmse", cs.rmse_history.data(), static_cast<int>(cs.rmse_history.size()), 0, overlay, 0.0f,
                     std::max(top, 1e-6f), ImVec2(ImGui::GetContentRegionAvail().x, 40));
    probe_item(ui.probe, "rmse history");
  }
  ImGui::InputText("metrics file", ui.metrics_path, sizeof ui.metrics_path);
  if (ImGui::Button("export metrics")) {
    Status st = c.note(write_metrics(c, ui.metrics_path));
    if (st) ui.post(std::string("wrote ") + ui.metrics_path, ImGui::GetTime());
  }
  tooltip("compare statistics, reference progress and per-pass times; .json or .csv");
  if (!cs.stats_error.empty()) ImGui::TextColored(kRed, "%s", cs.stats_error.c_str());
}

// Frame sequences: N frames along a camera orbit or a turning light, saved as numbered PNGs.
void sequence_panel(SandboxController& c, UiState& ui) {
  const bool open = ImGui::CollapsingHeader("Record frames");
  probe_item(ui.probe, "Record frames");
  if (!open) return;
  if (c.recording()) {
    ImGui::Text("recording frame %4d of %4d", c.sequence_saved() + 1, c.sequence_frames());
    if (ImGui::Button("stop")) c.stop_sequence();
    probe_item(ui.probe, "stop recording");
    return;
  }
  int path = static_cast<int>(ui.sequence.path);
  if (combo_index(ui.probe, "path", &path, {"orbit the camera", "turn the light"}))
    ui.sequence.path = static_cast<SequenceSpec::Path>(path);
  tooltip("about the vertical axis through the scene's centre; the pose comes back after the last frame");
  ImGui::InputInt("frames", &ui.sequence.frames);
  probe_item(ui.probe, "frames");
  ui.sequence.frames = std::clamp(ui.sequence.frames, 1, kMaxSequenceFrames);
  ImGui::DragFloat("degrees", &ui.sequence.degrees, 1.0f, -3600.0f, 3600.0f, "%.0f");
  ImGui::InputText("into", ui.sequence_dir, sizeof ui.sequence_dir);
  probe_item(ui.probe, "into");
  tooltip("an existing folder: frame_0000.png, frame_0001.png, ... (the frame without the panel)");
  if (ImGui::Button("record")) {
    SequenceSpec spec = ui.sequence;
    spec.dir = ui.sequence_dir;
    (void)c.start_sequence(spec);
  }
  probe_item(ui.probe, "record");
  if (!c.sequence_note().empty()) ImGui::TextDisabled("%s", c.sequence_note().c_str());
}

// Messages have a fixed place of fixed height at the top of the panel: they wrap inside it and
// scroll when long, so no widget below moves when one appears. Errors stay until the next
// action succeeds; transient notes fade.
void messages_panel(SandboxController& c, UiState& ui) {
  const bool comparing = c.compare().enabled;
  if (ImGui::Button(comparing ? "stop comparing" : "compare with reference")) (void)c.set_compare(!comparing);
  probe_item(ui.probe, "compare with reference");
  tooltip("split view: this technique left, the reference (or the technique chosen under Compare) right");
  ImGui::SameLine();
  if (ImGui::Button("screenshot (F12)")) ui.screenshot_requested = true;
  ImGui::SetNextItemWidth(-1);
  ImGui::InputText("##shot", ui.screenshot_path, sizeof ui.screenshot_path);
  probe_item(ui.probe, "screenshot path");
  const float lines = 4.0f;
  ImGui::BeginChild("##messages", ImVec2(0, lines * ImGui::GetTextLineHeightWithSpacing() + 8.0f), true);
  ImGui::PushTextWrapPos(0.0f);
  bool any = false;
  if (!c.message().empty()) {
    ImGui::TextColored(kRed, "%s", c.message().c_str());
    any = true;
  }
  if (!c.refused().empty() && c.refused() != c.message()) {
    ImGui::TextColored(kRed, "frame refused: %s", c.refused().c_str());
    any = true;
  }
  for (const Error& e : c.shader_errors()) {
    ImGui::TextColored(kRed, "%s", e.to_string().c_str());
    if (!e.details.empty()) tooltip(e.details);
    any = true;
  }
  const float alpha = ui.note_alpha(ImGui::GetTime());
  if (alpha > 0.0f) {
    ImGui::TextColored(ImVec4(0.8f, 0.9f, 0.8f, alpha), "%s", ui.note.c_str());
    any = true;
  }
  if (!any) ImGui::TextDisabled("no messages");
  ImGui::PopTextWrapPos();
  ImGui::EndChild();
}

// Esc closes the topmost open thing: a combo's list, else the full-screen resource view, else
// the compare split. A text field being edited takes Esc itself (it reverts the edit).
void close_on_escape(SandboxController& c, UiState& ui) {
  if (!ui.escape || ImGui::GetIO().WantTextInput) return;
  ui.probe.keys["escape"]++;
  if (ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId)) ImGui::ClosePopupToLevel(0, true);
  else if (!c.viewer().resource.empty()) (void)c.view_resource("");
  else if (c.compare().enabled) (void)c.set_compare(false);
}

}  // namespace

float UiState::note_alpha(double now) const {
  if (note.empty()) return 0.0f;
  const double age = now - note_time;
  if (age <= kNoteSeconds) return 1.0f;
  return static_cast<float>(std::max(0.0, 1.0 - (age - kNoteSeconds) / kFadeSeconds));
}

void draw_sandbox_ui(SandboxController& c, UiState& ui, const Layout& layout) {
  ui.probe.begin_frame();
  close_on_escape(c, ui);
  ImGui::SetNextWindowPos(ImVec2(float(layout.panel.x), float(layout.panel.y)));
  ImGui::SetNextWindowSize(ImVec2(float(layout.panel.w), float(layout.panel.h)));
  // The scrollbar always shows: content growing past the window (a section opened, a message)
  // must not narrow the widgets and shift them sideways.
  ImGui::Begin("Penumbra", nullptr,
               ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                   ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoSavedSettings |
                   ImGuiWindowFlags_AlwaysVerticalScrollbar);
  // Widgets take 45% of the panel: long parameter names and the reset buttons stay readable.
  ImGui::PushItemWidth(ImGui::GetWindowWidth() * 0.45f);
  // Fixed-width numbers (the font is monospaced): nothing on the line moves as they change.
  ImGui::Text("%6.1f fps  frame %5dx%-5d", ImGui::GetIO().Framerate, c.width(), c.height());
  messages_panel(c, ui);
  scene_panel(c, ui);
  light_panel(c, ui);
  technique_panel(c, ui);
  graph_panel(c, ui);
  viewer_panel(c, ui);
  compare_panel(c, ui);
  sequence_panel(c, ui);
  ImGui::PopItemWidth();
  ImGui::End();
  draw_panel_divider(ui.panel_width, layout);
  draw_viewport_overlay(c, layout, ui.probe);
  probe_tooltip(ui.probe);
}

}  // namespace penumbra::sandbox
