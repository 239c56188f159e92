#include "measurement/reference_frame.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <spdlog/spdlog.h>

#include "measurement/eval_capture.h"
#include "measurement/progressive_render.h"
#include "technique/frame_graph.h"
#include "metrics/reference_cache_file.h"
#include "util/file_read.h"
#include "util/file_write.h"

namespace penumbra::measurement {

namespace {

namespace fs = std::filesystem;

// Bump when the reference's algorithm or this file format changes: old entries stop matching.
constexpr const char* kCacheFormat = "penumbra-reference-cache 1";

fs::path cache_dir() {
  if (const char* d = std::getenv("PENUMBRA_CACHE_DIR"); d && *d)
    return std::string(d) == "off" ? fs::path() : fs::path(d) / "reference";
  if (const char* d = std::getenv("XDG_CACHE_HOME"); d && *d) return fs::path(d) / "penumbra" / "reference";
  if (const char* h = std::getenv("HOME"); h && *h) return fs::path(h) / ".cache" / "penumbra" / "reference";
  return {};
}

std::string vec_text(const glm::vec3& v) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "%.9g %.9g %.9g", v.x, v.y, v.z);
  return buf;
}

// Everything that decides the reference image, as text (hashed into the file name).
std::string cache_key(technique::TechniqueSession& session) {
  std::ostringstream k;
  const scene::Scene& scene = session.scene();
  k << kCacheFormat << "\nscene " << scene.name << " " << scene.source_file;
  if (!scene.source_file.empty()) {
    std::error_code ec;
    k << " " << fs::file_size(scene.source_file, ec) << " "
      << fs::last_write_time(scene.source_file, ec).time_since_epoch().count();
  }
  // A fingerprint of the geometry too: a built-in scene may change between versions.
  k << " triangles " << scene.triangle_count() << " bounds " << vec_text(scene.bounds.min) << " "
    << vec_text(scene.bounds.max);
  const scene::Camera& c = session.camera();
  k << "\ncamera " << vec_text(c.position) << " " << c.yaw << " " << c.pitch << " " << c.fov_y << " "
    << c.near_plane << " " << c.far_plane;
  const scene::Light& l = session.light();
  k << "\nlight " << static_cast<int>(l.type) << " " << vec_text(l.direction) << " " << vec_text(l.position) << " "
    << l.size << " " << l.spot_angle;
  k << "\nsize " << session.settings().screen_w << "x" << session.settings().screen_h;
  k << "\nparameters " << session.params().to_json();
  return k.str();
}

std::string fnv1a_hex(const std::string& text) {
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char c : text) {
    h ^= c;
    h *= 1099511628211ull;
  }
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

// The cached reference for `key`, if a sound one is there. A damaged file (truncated, NaN or
// out-of-range pixels, another size) is reported and rendered again: the new one replaces it.
bool read_cache(const fs::path& file, const std::string& key, const technique::TechniqueSession& session,
                ReferenceFrame& out) {
  std::error_code ec;
  if (!fs::exists(file, ec)) return false;
  const int w = session.settings().screen_w, h = session.settings().screen_h;
  Result<std::string> bytes = read_file_whole(file.string(), metrics::reference_cache_size(key, w, h));
  bool other_frame = false;
  Result<metrics::CachedReference> cached =
      bytes ? metrics::parse_reference_cache(*bytes, key, w, h, &other_frame) : Result<metrics::CachedReference>(bytes.error());
  if (!cached) {
    if (!other_frame)
      spdlog::warn("{}: reference cache entry not used ({}); rendering the reference again and replacing it",
                   file.string(), cached.error().message);
    return false;
  }
  out.mask = std::move(cached->mask);
  out.coverage = std::move(cached->coverage);
  return true;
}

void write_cache(const fs::path& file, const std::string& key, const ReferenceFrame& frame) {
  std::error_code ec;
  fs::create_directories(file.parent_path(), ec);
  // A cache that cannot be written is not an error: the reference was computed.
  if (Status s = write_file_whole(file.string(), metrics::format_reference_cache(key, frame.mask, frame.coverage)); !s)
    spdlog::warn("reference cache not written: {}", s.error().to_string());
}

// Renders the reference to completion: raster accumulates until all samples are in (progress
// every ~10%), raytraced traces once (the pass logs its own progress).
Status render_to_completion(technique::TechniqueSession& session, const ReferenceSettings& settings) {
  const int per_frame = std::max(1, session.params().get_int("maps_per_frame"));
  const int max_frames = settings.method == "raster" ? (settings.samples + per_frame - 1) / per_frame + 2 : 1;
  return render_until_complete(session, max_frames, [](const exec::PassProgress& p) {
    std::fprintf(stderr, "reference (%s)\n", progress_text(p).c_str());
  });
}

}  // namespace

Result<ReferenceFrame> reference_frame(technique::TechniqueSession& session, const ReferenceSettings& settings) {
  if (Status s = session.set_technique(kReferenceTechnique); !s) return s.error();
  if (Status s = apply_matching_sets(session, settings.sets); !s) return s.error();
  for (const std::string& kv : {"method=" + settings.method, "rays=" + std::to_string(settings.rays),
                                "samples=" + std::to_string(settings.samples)})
    if (Status s = session.set_param(kv); !s) return s.error();

  ReferenceFrame frame;
  const std::string key = cache_key(session);
  const fs::path dir = cache_dir();
  const fs::path file = dir.empty() ? fs::path() : dir / (fnv1a_hex(key) + ".bin");
  if (settings.use_cache && !file.empty() && read_cache(file, key, session, frame)) {
    frame.from_cache = true;
    frame.cache_file = file.string();
    return frame;
  }
  if (Status s = keep_alive(session, {"gbuffer_depth"}); !s) return s.error();  // coverage
  if (Status s = render_to_completion(session, settings); !s) return s.error();
  gl::Texture* mask = session.executor().resource(technique::kShadowMask);
  gl::Texture* depth = session.executor().resource("gbuffer_depth");
  if (!mask || !depth)
    return make_error("the reference frame lacks shadow_mask or gbuffer_depth", ErrorKind::internal);
  frame.mask = read_mask_image(*mask);
  frame.coverage = read_coverage(*depth);
  if (settings.use_cache && !file.empty()) {
    write_cache(file, key, frame);
    frame.cache_file = file.string();
  }
  return frame;
}

}  // namespace penumbra::measurement
