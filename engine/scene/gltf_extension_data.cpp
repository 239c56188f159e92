#include "scene/gltf_extension_data.h"

#include <cmath>
#include <cstdint>
#include <cstring>

#include <nlohmann/json.hpp>

#include "scene/glb_container.h"

namespace penumbra::scene::gltf {

namespace {

using Json = nlohmann::json;

// Decoded data of a meshopt fallback buffer is made by the loader; tinygltf gets these 3 bytes.
constexpr const char* kPlaceholderUri = "data:application/octet-stream;base64,AAAA";
constexpr std::size_t kPlaceholderBytes = 3;

class Reader {
 public:
  Reader(const Json& root, const std::string& file) : root_(root), file_(file) {}

  Error fail(const std::string& where, const std::string& message) const { return file_error(file_, message, where); }

  std::size_t count(const char* array) const {
    return root_.contains(array) && root_[array].is_array() ? root_[array].size() : 0;
  }
  // An integer member in [min, limit), present or not.
  Result<std::optional<long long>> integer(const Json& o, const char* key, const std::string& where,
                                           long long min = 0, long long limit = INT32_MAX) const {
    if (!o.contains(key)) return std::optional<long long>{};
    const Json& v = o[key];
    if (!v.is_number_integer() || v.get<long long>() < min || v.get<long long>() >= limit)
      return fail(where + "/" + key, std::string(key) + " must be an integer in [" + std::to_string(min) + ", " +
                                         std::to_string(limit - 1) + "], not " + shortened(v.dump(), 24));
    return std::optional<long long>{v.get<long long>()};
  }
  Result<long long> required_integer(const Json& o, const char* key, const std::string& where, long long min = 0,
                                     long long limit = INT32_MAX) const {
    auto v = integer(o, key, where, min, limit);
    if (!v) return v.error();
    if (!*v) return fail(where, std::string("has no ") + key);
    return **v;
  }
  Result<float> finite(const Json& v, const std::string& where) const {
    if (!v.is_number() || !std::isfinite(v.get<double>()) || std::fabs(v.get<double>()) > 3.0e38)
      return fail(where, "must be a finite number, not " + shortened(v.dump(), 24));
    return static_cast<float>(v.get<double>());
  }
  Result<glm::vec2> finite_pair(const Json& o, const char* key, const std::string& where, glm::vec2 fallback) const {
    if (!o.contains(key)) return fallback;
    const Json& v = o[key];
    if (!v.is_array() || v.size() != 2) return fail(where + "/" + key, std::string(key) + " must be two numbers");
    glm::vec2 out;
    for (int i = 0; i < 2; ++i) {
      auto x = finite(v[static_cast<size_t>(i)], where + "/" + key + "/" + std::to_string(i));
      if (!x) return x.error();
      out[i] = *x;
    }
    return out;
  }

  Result<std::optional<TextureTransform>> texture_transform(const Json& info, const std::string& where) const {
    if (!info.is_object() || !info.contains("extensions") || !info["extensions"].is_object() ||
        !info["extensions"].contains("KHR_texture_transform"))
      return std::optional<TextureTransform>{};
    const std::string at = where + "/extensions/KHR_texture_transform";
    const Json& t = info["extensions"]["KHR_texture_transform"];
    if (!t.is_object()) return fail(at, "must be an object");
    TextureTransform out;
    auto offset = finite_pair(t, "offset", at, out.offset);
    if (!offset) return offset.error();
    out.offset = *offset;
    auto scale = finite_pair(t, "scale", at, out.scale);
    if (!scale) return scale.error();
    out.scale = *scale;
    if (t.contains("rotation")) {
      auto r = finite(t["rotation"], at + "/rotation");
      if (!r) return r.error();
      out.rotation = *r;
    }
    auto tex_coord = integer(t, "texCoord", at, 0, 32);
    if (!tex_coord) return tex_coord.error();
    if (*tex_coord) out.tex_coord = static_cast<int>(**tex_coord);
    return std::optional<TextureTransform>{out};
  }

  Result<MeshoptView> meshopt_view(const Json& m, const std::string& at) const {
    if (!m.is_object()) return fail(at, "must be an object");
    MeshoptView v;
    auto buffer = required_integer(m, "buffer", at, 0, static_cast<long long>(count("buffers")));
    if (!buffer) return buffer.error();
    v.buffer = static_cast<int>(*buffer);
    auto offset = integer(m, "byteOffset", at, 0, INT64_MAX);
    if (!offset) return offset.error();
    v.byte_offset = static_cast<std::size_t>(offset->value_or(0));
    auto length = required_integer(m, "byteLength", at, 1, INT64_MAX);
    if (!length) return length.error();
    v.byte_length = static_cast<std::size_t>(*length);
    auto stride = required_integer(m, "byteStride", at, 1, 257);
    if (!stride) return stride.error();
    v.byte_stride = static_cast<std::size_t>(*stride);
    auto n = required_integer(m, "count", at, 1, INT32_MAX);
    if (!n) return n.error();
    v.count = static_cast<std::size_t>(*n);
    const std::string mode = m.contains("mode") && m["mode"].is_string() ? m["mode"].get<std::string>() : "";
    if (mode == "ATTRIBUTES") v.mode = MeshoptView::Mode::attributes;
    else if (mode == "TRIANGLES") v.mode = MeshoptView::Mode::triangles;
    else if (mode == "INDICES") v.mode = MeshoptView::Mode::indices;
    else return fail(at + "/mode", "mode must be ATTRIBUTES, TRIANGLES or INDICES");
    const std::string filter = !m.contains("filter") ? "NONE" : m["filter"].is_string() ? m["filter"].get<std::string>() : "";
    if (filter == "NONE") v.filter = MeshoptView::Filter::none;
    else if (filter == "OCTAHEDRAL") v.filter = MeshoptView::Filter::octahedral;
    else if (filter == "QUATERNION") v.filter = MeshoptView::Filter::quaternion;
    else if (filter == "EXPONENTIAL") v.filter = MeshoptView::Filter::exponential;
    else return fail(at + "/filter", "filter must be NONE, OCTAHEDRAL, QUATERNION or EXPONENTIAL");
    return v;
  }

 private:
  const Json& root_;
  const std::string& file_;
};

const Json* extension(const Json& o, const char* name) {
  if (!o.is_object() || !o.contains("extensions") || !o["extensions"].is_object()) return nullptr;
  const auto it = o["extensions"].find(name);
  return it == o["extensions"].end() ? nullptr : &*it;
}

}  // namespace

glm::vec2 TextureTransform::apply(glm::vec2 uv) const {
  const glm::vec2 s = scale * uv;
  const float c = std::cos(rotation), n = std::sin(rotation);
  return offset + glm::vec2(c * s.x + n * s.y, -n * s.x + c * s.y);
}

Result<PreparedFile> prepare_extensions(std::string bytes, bool binary, const std::string& file) {
  PreparedFile out;
  std::string_view json_text = bytes;
  std::optional<std::string_view> bin;
  if (binary) {
    Result<glb::Chunks> chunks = glb::split(bytes, file);
    if (!chunks) return chunks.error();
    json_text = chunks->json;
    bin = chunks->bin;
  }
  Json root = Json::parse(json_text, nullptr, /*allow_exceptions=*/false);
  if (root.is_discarded() || !root.is_object()) {
    out.bytes = std::move(bytes);
    return out;
  }
  const Reader r(root, file);
  ExtensionData& ext = out.extensions;
  bool rewritten = false;

  if (root.contains("materials") && root["materials"].is_array())
    for (std::size_t m = 0; m < root["materials"].size(); ++m) {
      const Json& mat = root["materials"][m];
      if (!mat.is_object() || !mat.contains("pbrMetallicRoughness")) continue;
      const Json& pbr = mat["pbrMetallicRoughness"];
      if (!pbr.is_object() || !pbr.contains("baseColorTexture")) continue;
      auto t = r.texture_transform(pbr["baseColorTexture"],
                                   "/materials/" + std::to_string(m) + "/pbrMetallicRoughness/baseColorTexture");
      if (!t) return t.error();
      if (*t) ext.base_color_transform[m] = **t;
    }

  if (root.contains("meshes") && root["meshes"].is_array())
    for (std::size_t mi = 0; mi < root["meshes"].size(); ++mi) {
      Json& mesh = root["meshes"][mi];
      if (!mesh.is_object() || !mesh.contains("primitives") || !mesh["primitives"].is_array()) continue;
      for (std::size_t pi = 0; pi < mesh["primitives"].size(); ++pi) {
        Json& prim = mesh["primitives"][pi];
        const Json* d = extension(prim, "KHR_draco_mesh_compression");
        if (!d) continue;
        const std::string at = "/meshes/" + std::to_string(mi) + "/primitives/" + std::to_string(pi) +
                               "/extensions/KHR_draco_mesh_compression";
        if (!d->is_object()) return r.fail(at, "must be an object");
        DracoPrimitive dp;
        auto view = r.required_integer(*d, "bufferView", at, 0, static_cast<long long>(r.count("bufferViews")));
        if (!view) return view.error();
        dp.buffer_view = static_cast<int>(*view);
        if (!d->contains("attributes") || !(*d)["attributes"].is_object())
          return r.fail(at, "has no attributes object");
        for (const auto& [name, id] : (*d)["attributes"].items()) {
          if (!id.is_number_integer() || id.get<long long>() < 0 || id.get<long long>() > INT32_MAX)
            return r.fail(at + "/attributes/" + name, "a Draco attribute id must be a non-negative integer");
          dp.attributes[name] = static_cast<int>(id.get<long long>());
        }
        auto indices = r.integer(prim, "indices", at, 0, static_cast<long long>(r.count("accessors")));
        if (!indices) return indices.error();
        dp.indices = static_cast<int>(indices->value_or(-1));
        if (prim.contains("indices")) {
          prim.erase("indices");
          rewritten = true;
        }
        ext.draco[{mi, pi}] = std::move(dp);
      }
    }

  if (root.contains("bufferViews") && root["bufferViews"].is_array())
    for (std::size_t v = 0; v < root["bufferViews"].size(); ++v)
      if (const Json* m = extension(root["bufferViews"][v], "EXT_meshopt_compression")) {
        auto view = r.meshopt_view(*m, "/bufferViews/" + std::to_string(v) + "/extensions/EXT_meshopt_compression");
        if (!view) return view.error();
        ext.meshopt[v] = *view;
      }

  if (root.contains("buffers") && root["buffers"].is_array())
    for (std::size_t b = 0; b < root["buffers"].size(); ++b) {
      Json& buffer = root["buffers"][b];
      const Json* m = extension(buffer, "EXT_meshopt_compression");
      if (!m || !m->is_object() || !m->value("fallback", false) || buffer.contains("uri")) continue;
      auto length = r.required_integer(buffer, "byteLength", "/buffers/" + std::to_string(b), 1, INT64_MAX);
      if (!length) return length.error();
      ext.fallback_buffers[b] = static_cast<std::size_t>(*length);
      buffer["uri"] = kPlaceholderUri;
      buffer["byteLength"] = kPlaceholderBytes;
      rewritten = true;
    }

  if (!rewritten) out.bytes = std::move(bytes);
  else out.bytes = binary ? glb::join(root.dump(), bin) : root.dump();
  return out;
}

}  // namespace penumbra::scene::gltf
