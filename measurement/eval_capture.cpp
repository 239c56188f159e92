#include "measurement/eval_capture.h"

#include <algorithm>

#include "exec/gbuffer_readback.h"
#include "gl/timer_query.h"
#include "passes/shared_passes.h"
#include "util/row_order.h"

namespace penumbra::measurement {

namespace {

// GL textures hold rows bottom to top; the metrics images rows top to bottom. Calls
// `store(x, top_down_y, texel)` with a pointer to each texel's channels: the one place the
// rows are flipped.
template <class Store>
void for_each_texel_top_down(const gl::Texture& texture, Store&& store) {
  const std::vector<float> texels = texture.read();
  const int w = texture.width(), h = texture.height(), c = texture.info().channels;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) store(x, h - 1 - y, &texels[(static_cast<size_t>(y) * w + x) * c], c);
}

}  // namespace

metrics::MaskImage read_mask_image(const gl::Texture& texture) {
  metrics::MaskImage img(texture.width(), texture.height());
  for_each_texel_top_down(texture, [&](int x, int y, const float* t, int) { img.at(x, y) = t[0]; });
  return img;
}

metrics::CoverageMask read_coverage(const gl::Texture& gbuffer_depth) {
  const int w = gbuffer_depth.width();
  metrics::CoverageMask coverage(static_cast<size_t>(w) * gbuffer_depth.height(), 0);
  for_each_texel_top_down(gbuffer_depth, [&](int x, int y, const float* t, int) {
    coverage[static_cast<size_t>(y) * w + x] = t[0] > 0.0f;
  });
  return coverage;
}

Status keep_alive(technique::TechniqueSession& session, const std::vector<std::string>& resources) {
  auto& keep = session.compile_options().keep_alive;
  bool added = false;
  for (const std::string& r : resources)
    if (std::find(keep.begin(), keep.end(), r) == keep.end()) {
      keep.push_back(r);
      added = true;
    }
  return added ? session.recompile() : Status{};
}

Result<metrics::ReceiverGeometry> read_receiver_geometry(technique::TechniqueSession& session) {
  gl::Texture* depth = session.executor().resource("gbuffer_depth");
  gl::Texture* normal = session.executor().resource("gbuffer_normal");
  if (!depth || !normal) return make_error("the frame lacks gbuffer_depth or gbuffer_normal", ErrorKind::internal);
  const std::vector<glm::vec4> positions = exec::read_positions(*depth, session.camera(), exec::RowOrder::top_down);
  const std::vector<glm::vec3> normals = rows_flipped(exec::read_normals(*normal), depth->width(), depth->height());
  return metrics::receiver_geometry(depth->width(), depth->height(), positions, normals, session.light());
}

Status frame_classes(technique::TechniqueSession& session, const metrics::MaskImage& reference,
                     const metrics::CoverageMask& coverage, metrics::PixelClasses& classes) {
  if (!classes.classes.empty()) return {};
  Result<metrics::ReceiverGeometry> geometry = read_receiver_geometry(session);
  if (!geometry) return geometry.error();
  classes = metrics::classify_pixels(reference, coverage, &*geometry);
  return {};
}

Status render_timed_frames(technique::TechniqueSession& session, int warmup, int frames) {
  for (int i = 0; i < warmup + frames; ++i)
    if (Status s = session.render(); !s) return s;
  // GPU timestamps arrive frames late: wait for the last ones so all `frames` are recorded.
  session.executor().flush_timings();
  return {};
}

std::vector<PassMedian> pass_medians(technique::TechniqueSession& session, int frames) {
  std::vector<PassMedian> out;
  for (const exec::PassTiming& t : session.executor().timings()) {
    std::vector<float> v(t.history.end() - std::min<std::ptrdiff_t>(frames, t.history.size()), t.history.end());
    double median = 0.0;
    if (!v.empty()) {
      std::sort(v.begin(), v.end());
      const size_t m = v.size() / 2;
      median = v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
    }
    out.push_back({t.name, median});
  }
  return out;
}

std::string timing_mode_note(technique::TechniqueSession& session) {
  switch (session.executor().timing_mode()) {
    case exec::TimingMode::gpu_timestamps: return "GPU timestamp queries";
    case exec::TimingMode::cpu_finish:
      return "glFinish + CPU clock (software renderer: GL timer queries do not measure llvmpipe's work)";
    case exec::TimingMode::off: return "off";
  }
  return "unknown";
}

Status check_set_keys(const technique::TechniqueRegistry& registry, const std::vector<std::string>& techniques,
                      const std::vector<std::string>& assignments) {
  std::vector<graph::ParameterSet> sets;
  for (const std::string& t : techniques) {
    const technique::Technique* technique = registry.find(t);
    if (!technique) continue;
    auto g = load_technique_graph(registry, *technique);
    if (!g) return g.error();
    sets.emplace_back(g->parameters);
  }
  for (const std::string& kv : assignments) {
    const size_t eq = kv.find('=');
    if (eq == std::string::npos || eq == 0) {
      Error e = make_error("expected k=v");
      e.where = "--set " + shortened(kv);
      return e;
    }
    const std::string key = kv.substr(0, eq);
    bool known = false;
    for (graph::ParameterSet& p : sets) {
      if (!p.find(key)) continue;
      known = true;
      if (Status s = p.set_from_string(kv); !s) {
        Error e = s.error();
        e.where = "--set " + shortened(kv);
        return e;
      }
    }
    if (!known) {
      std::string list;
      for (const std::string& t : techniques) list += (list.empty() ? "" : ", ") + t;
      Error e = make_error("no technique among " + list + " has a parameter '" + shortened(key) + "'");
      e.where = "--set " + shortened(kv);
      return e;
    }
  }
  return {};
}

Status apply_matching_sets(technique::TechniqueSession& session, const std::vector<std::string>& assignments) {
  for (const std::string& kv : assignments) {
    if (!session.params().find(kv.substr(0, kv.find('=')))) continue;
    if (Status s = session.set_param(kv); !s) {
      Error e = s.error();
      e.where = "--set " + shortened(kv);
      return e;
    }
  }
  return {};
}

Result<std::vector<std::string>> split_list(const std::string& option, const std::string& text) {
  std::vector<std::string> items;
  size_t start = 0;
  while (true) {
    const size_t comma = text.find(',', start);
    std::string item = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    if (item.empty()) return make_error("--" + option + " expects a comma-separated list without empty items, got '" + shortened(text) + "'");
    items.push_back(item);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return items;
}

}  // namespace penumbra::measurement
