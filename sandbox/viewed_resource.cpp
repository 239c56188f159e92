#include "sandbox/viewed_resource.h"

#include "util/file_read.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>

#include "sandbox/view_mapping.h"
#include "util/file_write.h"
#include "util/png.h"
#include "util/row_order.h"

namespace penumbra::sandbox {

float linear_depth(float d, float n, float f) {
  const float z = d * 2.0f - 1.0f;
  return 2.0f * n * f / (f + n - z * (f - n));
}

bool screen_depth(const gl::Texture& t, const SandboxController& c) {
  return t.info().is_depth && t.width() == c.width() && t.height() == c.height();
}

Result<ViewedImage> read_viewed(SandboxController& c, const std::string& what) {
  const ViewerSettings& v = c.viewer();
  if (v.resource.empty()) return make_error(what + ": no resource is viewed");
  gl::Texture* t = c.session().executor().resource(v.resource);
  if (!t) return make_error(what + ": '" + shortened(v.resource) + "' is not produced by the current graph");
  ViewedImage img;
  img.width = t->width();
  img.height = t->height();
  img.channels = t->info().channels;
  img.texels = t->read();
  const int ch = std::clamp(v.channel, 0, img.channels - 1);
  const bool depth = v.linearize_depth && screen_depth(*t, c);
  img.values.reserve(img.texels.size() / static_cast<size_t>(img.channels));
  for (size_t i = static_cast<size_t>(ch); i < img.texels.size(); i += static_cast<size_t>(img.channels)) {
    float x = img.texels[i];
    if (depth) x = x >= 1.0f ? std::numeric_limits<float>::quiet_NaN() : linear_depth(x, c.camera().near_plane, c.camera().far_plane);
    img.values.push_back(x);
  }
  return img;
}

namespace {

Result<glm::vec2> range_of(const ViewedImage& img, const std::string& resource) {
  float lo = std::numeric_limits<float>::infinity(), hi = -lo;
  for (float x : img.values)
    if (std::isfinite(x)) {
      lo = std::min(lo, x);
      hi = std::max(hi, x);
    }
  if (!(lo <= hi)) return make_error("auto range: '" + resource + "' holds no finite value");
  return glm::vec2(lo, hi);
}

Status apply_range(ViewerSettings& v, const ViewedImage& img) {
  Result<glm::vec2> r = range_of(img, v.resource);
  if (!r) return r.error();
  const float pad = r->y > r->x ? 0.0f : 1e-6f * std::max(1.0f, std::abs(r->x));
  v.min = r->x - pad;
  v.max = r->y + pad;
  return {};
}

}  // namespace

Result<glm::vec2> resource_range(SandboxController& c) {
  Result<ViewedImage> img = read_viewed(c, "auto range");
  if (!img) return img.error();
  return range_of(*img, c.viewer().resource);
}

Status apply_auto_range(SandboxController& c) {
  Result<ViewedImage> img = read_viewed(c, "auto range");
  return img ? apply_range(c.viewer(), *img) : Status(img.error());
}

Status update_histogram(SandboxController& c) {
  Result<ViewedImage> img = read_viewed(c, "histogram");
  if (!img) {
    c.viewer().counts.clear();
    return img.error();
  }
  c.viewer().counts = histogram(img->values, c.viewer().min, c.viewer().max, kHistogramBins);
  return {};
}

void refresh_viewed(SandboxController& c) {
  ViewerSettings& v = c.viewer();
  if (v.resource.empty() || (!v.auto_range && !v.histogram)) return;
  Result<ViewedImage> img = read_viewed(c, "viewer");  // one read-back for both
  if (!img) return;
  if (v.auto_range) (void)apply_range(v, *img);
  if (v.histogram) v.counts = histogram(img->values, v.min, v.max, kHistogramBins);
}

std::optional<ViewFormat> parse_view_format(const std::string& name) {
  if (name == "png") return ViewFormat::png;
  if (name == "pfm") return ViewFormat::pfm;
  return std::nullopt;
}

namespace {

// Portable float map: "PF" (RGB) or "Pf" (grey), width height, -1 (little-endian), rows bottom
// to top, as GL reads them.
Status write_pfm(const std::string& path, int w, int h, int channels, const std::vector<float>& data) {
  std::string text = std::string(channels == 3 ? "PF" : "Pf") + "\n" + std::to_string(w) + " " + std::to_string(h) + "\n-1\n";
  const size_t header = text.size();
  text.resize(header + data.size() * sizeof(float));
  std::copy_n(reinterpret_cast<const char*>(data.data()), data.size() * sizeof(float), text.data() + header);
  return write_file_whole(path, text);
}

}  // namespace

Result<std::string> save_viewed_resource(SandboxController& c, const std::string& dir, ViewFormat format) {
  Result<ViewedImage> img = read_viewed(c, "save");
  if (!img) return img.error();
  const ViewerSettings& v = c.viewer();
  if (Status d = dir.empty() ? Status() : check_directory(dir); !d)
    return make_error("save: '" + shortened(dir) + "' " + d.error().message);
  const std::string name = v.resource + "_frame" + std::to_string(c.frames()) + (format == ViewFormat::png ? ".png" : ".pfm");
  const std::string path = (std::filesystem::path(dir.empty() ? "." : dir) / name).string();
  const size_t n = img->values.size(), k = static_cast<size_t>(img->channels);
  auto texel = [&](size_t i) {
    glm::vec4 t(0.0f, 0.0f, 0.0f, 1.0f);
    for (size_t ch = 0; ch < std::min<size_t>(k, 4); ++ch) t[int(ch)] = img->texels[i * k + ch];
    return t;
  };
  Status s;
  if (format == ViewFormat::png) {
    std::vector<unsigned char> rgba(n * 4);
    for (size_t i = 0; i < n; ++i) {
      const float value = img->values[i];
      glm::vec3 rgb = std::isfinite(value) || v.map == ViewerSettings::Map::color
                          ? displayed_colour(static_cast<int>(v.map), texel(i), value, v.channel_mask, v.min, v.max)
                          : glm::vec3(40.0f / 255.0f);  // background, as the display greys it
      for (int ch = 0; ch < 3; ++ch) rgba[i * 4 + size_t(ch)] = static_cast<unsigned char>(std::lround(rgb[ch] * 255.0f));
      rgba[i * 4 + 3] = 255;
    }
    s = write_png_rgba8(path, img->width, img->height, rows_flipped(rgba, static_cast<size_t>(img->width) * 4, img->height));
  } else if (v.map == ViewerSettings::Map::color) {
    std::vector<float> rgb(n * 3);
    for (size_t i = 0; i < n; ++i)
      for (int ch = 0; ch < 3; ++ch) rgb[i * 3 + size_t(ch)] = ((v.channel_mask >> ch) & 1u) ? texel(i)[ch] : 0.0f;
    s = write_pfm(path, img->width, img->height, 3, rgb);
  } else {
    s = write_pfm(path, img->width, img->height, 1, img->values);
  }
  if (!s) return s.error();
  return path;
}

}  // namespace penumbra::sandbox
