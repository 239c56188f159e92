#include "sandbox/graph_view.h"

#include <algorithm>
#include <cstdio>

#include <imgui.h>


namespace penumbra::sandbox {

namespace {

std::string plan_key(SandboxController& c) {
  std::string key = c.session().technique() + "#" + std::to_string(c.session().compile_count());
  for (const graph::PlannedPass& p : c.session().plan().passes) key += "|" + p.name;
  return key;
}

ImU32 node_colour(const GraphViewModel::Pass& p) {
  if (p.state == GraphViewModel::State::io) return IM_COL32(45, 60, 45, 255);
  if (p.state != GraphViewModel::State::runs) return IM_COL32(55, 55, 55, 255);
  return p.slowest ? IM_COL32(150, 70, 30, 255) : IM_COL32(40, 65, 110, 255);
}

void draw_nodes_and_edges(SandboxController& c, const GraphViewCache& cache) {
  const GraphLayout& l = cache.layout;
  const GraphViewModel& m = cache.model;
  constexpr float kMargin = 12.0f;
  ImGui::BeginChild("##graph_canvas", ImVec2(0, std::min(l.size.y + 2 * kMargin + 16, 320.0f)), true,
                    ImGuiWindowFlags_HorizontalScrollbar);
  const ImVec2 o = ImGui::GetCursorScreenPos();
  auto at = [&](glm::vec2 p) { return ImVec2(o.x + kMargin + p.x, o.y + kMargin + p.y); };
  ImDrawList* dl = ImGui::GetWindowDrawList();
  for (size_t i = 0; i < l.edges.size() && i < m.input.edges.size(); ++i) {
    const GraphLayout::Edge& e = l.edges[i];
    const ImU32 col = IM_COL32(170, 170, 180, 200);
    for (size_t k = 0; k + 3 < e.points.size(); k += 3)
      dl->AddBezierCubic(at(e.points[k]), at(e.points[k + 1]), at(e.points[k + 2]), at(e.points[k + 3]), col, 1.4f);
    if (!e.points.empty()) {
      const glm::vec2 tail = e.points.back(), tip = e.head;
      const glm::vec2 d = glm::length(tip - tail) > 0.1f ? glm::normalize(tip - tail) : glm::vec2(1, 0);
      const glm::vec2 n(-d.y, d.x);
      dl->AddTriangleFilled(at(tip), at(tip - d * 7.0f + n * 3.5f), at(tip - d * 7.0f - n * 3.5f), col);
    }
    dl->AddText(at(e.label_at + glm::vec2(-3.5f * m.input.edges[i].label.size(), -7.0f)), IM_COL32(150, 190, 150, 255),
                m.input.edges[i].label.c_str());
  }
  for (size_t i = 0; i < l.nodes.size() && i < m.nodes.size(); ++i) {
    const GraphViewModel::Pass& p = m.nodes[i];
    const glm::vec2 half = l.nodes[i].size * 0.5f;
    const ImVec2 a = at(l.nodes[i].center - half), b = at(l.nodes[i].center + half);
    dl->AddRectFilled(a, b, node_colour(p), 4.0f);
    if (p.slowest) dl->AddRect(a, b, IM_COL32(255, 150, 60, 255), 4.0f, 0, 2.0f);
    const bool dim = p.state == GraphViewModel::State::culled || p.state == GraphViewModel::State::disabled;
    const ImU32 text = dim ? IM_COL32(140, 140, 140, 255) : IM_COL32(235, 235, 235, 255);
    dl->AddText(ImVec2(a.x + 6, a.y + 3), text, p.name.c_str());
    char sub[48];
    if (p.state == GraphViewModel::State::runs) std::snprintf(sub, sizeof sub, "%.3f ms", p.ms);
    else std::snprintf(sub, sizeof sub, "%s", dim ? (p.state == GraphViewModel::State::culled ? "culled" : "disabled") : "");
    dl->AddText(ImVec2(a.x + 6, a.y + 17), text, sub);
    ImGui::SetCursorScreenPos(a);
    ImGui::PushID(static_cast<int>(i));
    if (ImGui::InvisibleButton("##node", ImVec2(std::max(b.x - a.x, 1.0f), std::max(b.y - a.y, 1.0f))) &&
        !p.outputs.empty())
      (void)c.view_resource(p.outputs.front());
    if (ImGui::IsItemHovered()) {
      std::string tip = p.name + (p.type.empty() ? "" : "  (" + p.type + ")");
      if (!p.why.empty()) tip += "\n" + p.why;
      if (!p.outputs.empty()) {
        tip += "\nwrites:";
        for (const std::string& r : p.outputs) tip += " " + r;
        tip += "\nclick: view " + p.outputs.front();
      }
      wrapped_tooltip(tip);
    }
    ImGui::PopID();
  }
  ImGui::SetCursorScreenPos(o);
  ImGui::Dummy(ImVec2(l.size.x + 2 * kMargin, l.size.y + 2 * kMargin));
  ImGui::EndChild();
}

// Each pass's time as a bar; the frame budget as a vertical line.
void draw_times(GraphViewCache& cache, UiProbe& probe) {
  const GraphViewModel& m = cache.model;
  ImGui::SetNextItemWidth(120);
  ImGui::DragFloat("frame budget", &cache.budget_ms, 0.1f, 0.1f, 1000.0f, "%.2f ms");
  probe_item(probe, "frame budget");
  // Its own line, numbers of fixed width: at the narrowest panel nothing is cut off.
  if (m.total_ms > cache.budget_ms) ImGui::TextColored(ImVec4(1.0f, 0.35f, 0.3f, 1.0f), "total %8.3f ms  OVER BUDGET", m.total_ms);
  else ImGui::Text("total %8.3f ms", m.total_ms);
  probe_item(probe, "total");
  const float width = ImGui::GetContentRegionAvail().x;
  const double scale_ms = std::max<double>(cache.budget_ms * 1.1, m.total_ms);
  ImDrawList* dl = ImGui::GetWindowDrawList();
  const ImVec2 o = ImGui::GetCursorScreenPos();
  float x = o.x;
  const float h = 14.0f;
  for (const GraphViewModel::Pass& p : m.nodes) {
    if (p.state != GraphViewModel::State::runs) continue;
    const float w = static_cast<float>(p.ms / scale_ms) * width;
    dl->AddRectFilled(ImVec2(x, o.y), ImVec2(x + std::max(w, 1.0f), o.y + h), node_colour(p));
    dl->AddRect(ImVec2(x, o.y), ImVec2(x + std::max(w, 1.0f), o.y + h), IM_COL32(20, 20, 20, 255));
    if (ImGui::IsMouseHoveringRect(ImVec2(x, o.y), ImVec2(x + std::max(w, 1.0f), o.y + h)))
      ImGui::SetTooltip("%s: %.3f ms (%.0f%% of the budget)", p.name.c_str(), p.ms, 100.0 * p.ms / cache.budget_ms);
    x += w;
  }
  const float bx = o.x + static_cast<float>(cache.budget_ms / scale_ms) * width;
  dl->AddLine(ImVec2(bx, o.y - 3), ImVec2(bx, o.y + h + 3), IM_COL32(255, 80, 80, 255), 2.0f);
  ImGui::Dummy(ImVec2(width, h + 4));
}

// The frame's total pass time over the executor's history, with its scale and the budget.
void draw_history(SandboxController& c, const GraphViewCache& cache, UiProbe& probe) {
  const auto& timings = c.session().executor().timings();
  size_t n = 0;
  for (const exec::PassTiming& t : timings) n = std::max(n, t.history.size());
  if (n < 2) return;
  std::vector<float> total(n, 0.0f);
  for (const exec::PassTiming& t : timings)
    for (size_t i = 0; i < t.history.size(); ++i) total[n - t.history.size() + i] += t.history[i];
  const float top = std::max(*std::max_element(total.begin(), total.end()), cache.budget_ms);
  char overlay[96];
  std::snprintf(overlay, sizeof overlay, "frame passes, last %zu frames: 0 .. %.2f ms (budget %.2f)", n, top, cache.budget_ms);
  // An explicit width: ImGui 1.86 draws ImVec2(-1, h) as a sliver here.
  ImGui::PlotLines("##total_history", total.data(), static_cast<int>(n), 0, overlay, 0.0f, top,
                   ImVec2(ImGui::GetContentRegionAvail().x, 48));
  probe_item(probe, "frame history");
  const ImVec2 a = ImGui::GetItemRectMin(), b = ImGui::GetItemRectMax();
  const float y = b.y - (b.y - a.y) * (cache.budget_ms / top);
  ImGui::GetWindowDrawList()->AddLine(ImVec2(a.x, y), ImVec2(b.x, y), IM_COL32(255, 80, 80, 160), 1.0f);
}

// Physical textures as rows, each version's lifetime (first..last pass) as a bar on it.
void draw_timeline(const GraphViewCache& cache, int passes) {
  const GraphViewModel& m = cache.model;
  if (m.lifetimes.empty() || passes <= 0) return;
  ImGui::TextDisabled("texture lifetimes (%d physical textures; a row holding several versions is shared)", m.physical_count);
  const float width = ImGui::GetContentRegionAvail().x, row = 13.0f;
  const ImVec2 o = ImGui::GetCursorScreenPos();
  ImDrawList* dl = ImGui::GetWindowDrawList();
  int rows = 0;
  std::vector<int> row_of(static_cast<size_t>(std::max(m.physical_count, 1)), -1);
  for (const auto& l : m.lifetimes) {
    if (l.physical < 0 || static_cast<size_t>(l.physical) >= row_of.size()) continue;
    int& r = row_of[static_cast<size_t>(l.physical)];
    if (r < 0) r = rows++;
    const float x0 = o.x + width * float(l.first) / float(passes + 1);
    const float x1 = o.x + width * float(std::min(l.last, passes) + 1) / float(passes + 1);
    const float y = o.y + r * row;
    const ImU32 col = IM_COL32(60 + (l.physical * 53) % 150, 90 + (l.physical * 31) % 120, 160, 255);
    dl->AddRectFilled(ImVec2(x0, y), ImVec2(x1 - 1, y + row - 2), col, 2.0f);
    dl->AddText(ImVec2(x0 + 2, y - 1), IM_COL32(240, 240, 240, 255), l.label.c_str());
    if (ImGui::IsMouseHoveringRect(ImVec2(x0, y), ImVec2(x1, y + row)))
      ImGui::SetTooltip("%s on physical texture %d, passes %d..%d", l.label.c_str(), l.physical, l.first, l.last);
  }
  ImGui::Dummy(ImVec2(width, rows * row + 4));
}

}  // namespace

void draw_graph_view(SandboxController& c, GraphViewCache& cache, UiProbe& probe) {
  const std::string key = plan_key(c);
  GraphViewModel fresh = current_graph_view(c);
  if (key != cache.key) {
    cache.key = key;
    Result<GraphLayout> l = layout_with_dot(fresh.input);
    cache.error = l ? "" : l.error().to_string();
    cache.layout = l ? *l : GraphLayout{};
  }
  cache.model = std::move(fresh);  // times change every frame, the layout only with the plan
  if (!cache.error.empty()) ImGui::TextColored(ImVec4(1, 0.35f, 0.3f, 1), "%s", cache.error.c_str());
  else draw_nodes_and_edges(c, cache);
  draw_times(cache, probe);
  draw_history(c, cache, probe);
  draw_timeline(cache, static_cast<int>(c.session().plan().passes.size()));
}

}  // namespace penumbra::sandbox
