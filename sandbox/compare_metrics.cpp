#include "sandbox/compare_metrics.h"

#include <cstdio>

#include <nlohmann/json.hpp>

#include "measurement/progressive_render.h"
#include "util/file_write.h"

namespace penumbra::sandbox {

namespace {

using nlohmann::json;


json progress_json(const technique::TechniqueSession& s) {
  const std::optional<exec::PassProgress>& p = s.progress();
  if (!p) return nullptr;
  return {{"label", p->label}, {"unit", p->unit}, {"done", p->done}, {"total", p->total}, {"complete", p->complete()}};
}

json parameters_json(const technique::TechniqueSession& s) { return json::parse(s.params().to_json()); }

json passes_json(technique::TechniqueSession& s) {
  json passes = json::array();
  const graph::CompiledPlan& plan = s.plan();
  const auto& timings = s.executor().timings();
  for (size_t i = 0; i < plan.passes.size(); ++i) {
    const exec::PassTiming* t = i < timings.size() ? &timings[i] : nullptr;
    passes.push_back({{"name", plan.passes[i].name},
                      {"type", plan.passes[i].type},
                      {"last_ms", t ? t->last_ms : 0.0},
                      {"median_ms", t ? t->median_ms() : 0.0}});
  }
  return passes;
}

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

}  // namespace

std::string penumbra_rmse_text(const metrics::MaskErrors& e) {
  if (e.penumbra_pixels == 0) return "n/a (no soft penumbra)";
  char buf[200];
  std::snprintf(buf, sizeof buf, "%.4f%s%s%s", e.rmse_penumbra, e.reliability.reliable ? "" : " (unreliable: ",
                e.reliability.reason.c_str(), e.reliability.reliable ? "" : ")");
  return buf;
}

bool progress_complete(SandboxController& c) {
  for (technique::TechniqueSession* s : c.shown_sessions())
    if (s->progress() && !s->progress()->complete()) return false;
  return true;
}

std::string progress_text(SandboxController& c) {
  std::string text;
  for (technique::TechniqueSession* s : c.shown_sessions())
    if (const std::optional<exec::PassProgress>& p = s->progress())
      text += (text.empty() ? "" : "; ") + s->technique() + " (" + measurement::progress_text(*p) + ")";
  return text;
}

std::string metrics_json(SandboxController& c) {
  c.refresh_compare_stats();
  json j;
  j["frame"] = c.frames();
  j["size"] = {c.width(), c.height()};
  j["scene"] = c.scene_name();
  j["technique"] = {{"name", c.session().technique()},
                    {"parameters", parameters_json(c.session())},
                    {"progress", progress_json(c.session())}};
  j["passes"] = passes_json(c.session());
  const ViewerSettings& v = c.viewer();
  j["viewer"] = {{"resource", v.resource}, {"min", v.min}, {"max", v.max}, {"channel", v.channel},
                 {"zoom", v.zoom.zoom}, {"center", {v.zoom.center.x, v.zoom.center.y}}};
  j["refused"] = c.refused().empty() ? json(nullptr) : json(c.refused());
  const CompareState& cs = c.compare();
  if (!cs.enabled || !c.secondary()) {
    j["compare"] = nullptr;
  } else {
    json k;
    k["with"] = {{"name", c.secondary()->technique()},
                 {"parameters", parameters_json(*c.secondary())},
                 {"progress", progress_json(*c.secondary())}};
    k["view"] = cs.view == CompareState::View::split ? "split" : "error";
    k["passes"] = passes_json(*c.secondary());
    auto errors = [](json& out, const metrics::MaskErrors& e) {
      out["rmse"] = e.rmse;
      out["rmse_penumbra"] = e.penumbra_pixels ? json(e.rmse_penumbra) : json(nullptr);
      out["mae"] = e.mae;
      out["max_error"] = e.max_error;
      out["pixels"] = e.pixels;
      out["penumbra_pixels"] = e.penumbra_pixels;
      out["penumbra_reliable"] = e.reliability.reliable;
      out["penumbra_unreliable_because"] = e.reliability.reason;
      out["rmse_geometric_edge"] = e.geometric_edge_pixels ? json(e.rmse_geometric_edge) : json(nullptr);
      out["geometric_edge_pixels"] = e.geometric_edge_pixels;
    };
    // Three-way: the statistics above are A against the reference; B's are under "b".
    k["three_way"] = c.reference_session() != nullptr;
    if (cs.stats_b && c.reference_session()) {
      json b;
      errors(b, *cs.stats_b);
      k["b"] = b;
    }
    if (cs.stats) {
      errors(k, *cs.stats);
    } else {
      k["stats_error"] = cs.stats_error.empty() ? "no statistics yet" : cs.stats_error;
    }
    k["rmse_history"] = cs.rmse_history;
    j["compare"] = k;
  }
  return j.dump(2) + "\n";
}

std::string metrics_csv(SandboxController& c) {
  const json j = json::parse(metrics_json(c));
  std::string out = "side,pass,type,last_ms,median_ms\n";
  auto rows = [&](const char* side, const json& passes) {
    for (const json& p : passes)
      out += std::string(side) + "," + p["name"].get<std::string>() + "," + p["type"].get<std::string>() + "," +
             number(p["last_ms"].get<double>()) + "," + number(p["median_ms"].get<double>()) + "\n";
  };
  rows("A", j["passes"]);
  if (!j["compare"].is_null()) {
    rows("B", j["compare"]["passes"]);
    out += "stat,name,value\n";
    for (const char* key : {"rmse", "rmse_penumbra", "mae", "max_error", "pixels", "penumbra_pixels"})
      if (j["compare"].contains(key))
        out += std::string("stat,") + key + "," +
               (j["compare"][key].is_null() ? std::string("n/a") : number(j["compare"][key].get<double>())) + "\n";
  }
  return out;
}

Status write_metrics(SandboxController& c, const std::string& path) {
  const bool csv = path.size() >= 4 && path.compare(path.size() - 4, 4, ".csv") == 0;
  return write_file_whole(path, csv ? metrics_csv(c) : metrics_json(c));
}

}  // namespace penumbra::sandbox
