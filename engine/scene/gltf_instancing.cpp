#include "scene/gltf_instancing.h"

#include <algorithm>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <tiny_gltf.h>

#include "scene/gltf_accessors.h"
#include "scene/gltf_loader.h"

namespace penumbra::scene::gltf {

namespace {

constexpr const char* kExtension = "EXT_mesh_gpu_instancing";

// The accessor index an attribute names, -1 when absent; -2 when present but not an index.
int attribute(const tinygltf::Value& attributes, const char* name) {
  if (!attributes.Has(name)) return -1;
  const tinygltf::Value& v = attributes.Get(name);
  return v.IsInt() || v.IsNumber() ? v.GetNumberAsInt() : -2;
}

}  // namespace

Result<std::optional<std::vector<glm::mat4>>> node_instances(const tinygltf::Model& model, const tinygltf::Node& node,
                                                            const std::string& file, const std::string& where) {
  const auto ext = node.extensions.find(kExtension);
  if (ext == node.extensions.end()) return std::optional<std::vector<glm::mat4>>{};
  auto fail = [&](const std::string& message) { return file_error(file, message + " (" + kExtension + ")", where); };
  if (!ext->second.IsObject() || !ext->second.Has("attributes") || !ext->second.Get("attributes").IsObject())
    return fail("has no attributes object");
  const tinygltf::Value& attributes = ext->second.Get("attributes");
  const int t = attribute(attributes, "TRANSLATION"), r = attribute(attributes, "ROTATION"),
            s = attribute(attributes, "SCALE");
  if (t == -2 || r == -2 || s == -2) return fail("an attribute is not an accessor index");
  if (t < 0 && r < 0 && s < 0) return fail("names none of TRANSLATION, ROTATION and SCALE");

  std::vector<glm::vec3> translations, scales;
  std::vector<glm::vec4> rotations;
  if (t >= 0) {
    auto v = read_vec3(model, t, AttributeKind::position, file, where + " TRANSLATION");
    if (!v) return v.error();
    translations = std::move(*v);
  }
  if (r >= 0) {
    auto v = read_vec4(model, r, AttributeKind::rotation, file, where + " ROTATION");
    if (!v) return v.error();
    rotations = std::move(*v);
  }
  if (s >= 0) {
    auto v = read_vec3(model, s, AttributeKind::position, file, where + " SCALE");
    if (!v) return v.error();
    scales = std::move(*v);
  }
  const size_t n = std::max({translations.size(), rotations.size(), scales.size()});
  for (const size_t count : {translations.size(), rotations.size(), scales.size()})
    if (count != 0 && count != n)
      return fail("its attributes have different counts (" + std::to_string(translations.size()) + ", " +
                  std::to_string(rotations.size()) + ", " + std::to_string(scales.size()) + ")");
  if (n > kMaxInstances) return fail(std::to_string(n) + " instances, more than " + std::to_string(kMaxInstances));
  std::vector<glm::mat4> out(n, glm::mat4(1.0f));
  for (size_t i = 0; i < n; ++i) {
    glm::mat4 m(1.0f);
    if (!translations.empty()) m = glm::translate(m, translations[i]);
    if (!rotations.empty()) {
      const glm::vec4 q = rotations[i];  // (x, y, z, w), as node rotations
      if (glm::length(q) < 1e-6f) return fail("instance " + std::to_string(i) + " has a rotation of zero length");
      m = m * glm::mat4_cast(glm::normalize(glm::quat(q.w, q.x, q.y, q.z)));
    }
    if (!scales.empty()) m = glm::scale(m, scales[i]);
    out[i] = m;
  }
  return std::optional<std::vector<glm::mat4>>{std::move(out)};
}

}  // namespace penumbra::scene::gltf
