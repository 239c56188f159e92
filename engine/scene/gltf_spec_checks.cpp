#include "scene/gltf_spec_checks.h"

#include <cmath>
#include <numbers>
#include <optional>

#include <nlohmann/json.hpp>

namespace penumbra::scene {

namespace {

using Json = nlohmann::json;

class SpecChecker {
 public:
  explicit SpecChecker(const std::string& file) : file_(file) {}

  Error fail(const std::string& where, std::string message) const {
    Error e = make_error(std::move(message) + " (glTF 2.0 specification)");
    e.file = file_;
    e.where = where;
    return e;
  }

  // A number member, when present. Present but not a finite number is an error of its own.
  Result<std::optional<double>> number(const Json& object, const char* key, const std::string& where) const {
    if (!object.is_object() || !object.contains(key)) return std::optional<double>{};
    const Json& v = object[key];
    if (!v.is_number() || !std::isfinite(v.get<double>()))
      return fail(where + "/" + key, std::string(key) + " must be a finite number");
    return std::optional<double>{v.get<double>()};
  }

  Status string_array(const Json& root, const char* key) const {
    if (!root.contains(key)) return {};
    const Json& v = root[key];
    if (!v.is_array()) return fail(std::string("/") + key, std::string(key) + " must be an array of strings");
    for (size_t i = 0; i < v.size(); ++i)
      if (!v[i].is_string())
        return fail("/" + std::string(key) + "/" + std::to_string(i), std::string(key) + " must hold only strings");
    return {};
  }

  Status scene_index(const Json& root) const {
    if (!root.contains("scene")) return {};
    const Json& s = root["scene"];
    const size_t scenes = root.contains("scenes") && root["scenes"].is_array() ? root["scenes"].size() : 0;
    if (!s.is_number_integer() || s.get<long long>() < 0 || static_cast<size_t>(s.get<long long>()) >= scenes)
      return fail("/scene", "scene " + shortened(s.dump(), 24) + " does not exist (" + std::to_string(scenes) +
                                " scenes)");
    return {};
  }

  Status light(const Json& l, const std::string& where) const {
    auto intensity = number(l, "intensity", where);
    if (!intensity) return intensity.error();
    if (*intensity && **intensity < 0.0)
      return fail(where + "/intensity", "light intensity " + value_text(**intensity) + " is negative");
    if (l.contains("color")) {
      const Json& c = l["color"];
      if (!c.is_array() || c.size() != 3) return fail(where + "/color", "light color must be 3 numbers");
      for (size_t i = 0; i < 3; ++i)
        if (!c[i].is_number() || !(c[i].get<double>() >= 0.0 && c[i].get<double>() <= 1.0))
          return fail(where + "/color/" + std::to_string(i), "light color components must lie in [0, 1]");
    }
    auto range = number(l, "range", where);
    if (!range) return range.error();
    if (*range && !(**range > 0.0))
      return fail(where + "/range", "light range " + value_text(**range) + " must be greater than 0");
    if (!l.contains("type") || l["type"] != "spot") return {};
    const std::string spot = where + "/spot";
    const Json& cone = l.contains("spot") ? l["spot"] : Json::object();
    auto inner = number(cone, "innerConeAngle", spot);
    if (!inner) return inner.error();
    auto outer = number(cone, "outerConeAngle", spot);
    if (!outer) return outer.error();
    const double inner_angle = inner->value_or(0.0), outer_angle = outer->value_or(std::numbers::pi / 4.0);
    if (!(outer_angle > 0.0 && outer_angle <= std::numbers::pi / 2.0))
      return fail(spot + "/outerConeAngle", "spot outerConeAngle " + value_text(outer_angle) + " must lie in (0, pi/2]");
    if (!(inner_angle >= 0.0 && inner_angle < outer_angle))
      return fail(spot + "/innerConeAngle", "spot innerConeAngle " + value_text(inner_angle) +
                                                " must lie in [0, outerConeAngle " + value_text(outer_angle) + ")");
    return {};
  }

  Status camera(const Json& c, const std::string& where) const {
    if (c.contains("perspective")) {
      const std::string p = where + "/perspective";
      const Json& cam = c["perspective"];
      auto yfov = number(cam, "yfov", p), znear = number(cam, "znear", p), zfar = number(cam, "zfar", p),
           aspect = number(cam, "aspectRatio", p);
      for (auto* r : {&yfov, &znear, &zfar, &aspect})
        if (!*r) return r->error();
      if (*yfov && !(**yfov > 0.0 && **yfov < std::numbers::pi))
        return fail(p + "/yfov", "camera yfov " + value_text(**yfov) + " must lie in (0, pi)");
      if (*znear && !(**znear > 0.0))
        return fail(p + "/znear", "camera znear " + value_text(**znear) + " must be greater than 0");
      if (*zfar && !(**zfar > znear->value_or(0.0)))
        return fail(p + "/zfar", "camera zfar " + value_text(**zfar) + " must be greater than znear");
      if (*aspect && !(**aspect > 0.0))
        return fail(p + "/aspectRatio", "camera aspectRatio " + value_text(**aspect) + " must be greater than 0");
    }
    if (c.contains("orthographic")) {
      const std::string o = where + "/orthographic";
      const Json& cam = c["orthographic"];
      auto xmag = number(cam, "xmag", o), ymag = number(cam, "ymag", o), znear = number(cam, "znear", o),
           zfar = number(cam, "zfar", o);
      for (auto* r : {&xmag, &ymag, &znear, &zfar})
        if (!*r) return r->error();
      if ((*xmag && **xmag == 0.0) || (*ymag && **ymag == 0.0))
        return fail(o, "orthographic camera xmag and ymag must not be 0");
      if (*znear && !(**znear >= 0.0)) return fail(o + "/znear", "camera znear must not be negative");
      if (*zfar && !(**zfar > znear->value_or(0.0)))
        return fail(o + "/zfar", "camera zfar " + value_text(**zfar) + " must be greater than znear");
    }
    return {};
  }

  Status node(const Json& n, const std::string& where) const {
    if (!n.is_object() || !n.contains("rotation")) return {};
    const Json& q = n["rotation"];
    double length2 = 0.0;
    if (q.is_array() && q.size() == 4)
      for (const Json& v : q) length2 += v.is_number() ? v.get<double>() * v.get<double>() : 0.0;
    if (!(length2 > 1e-12))  // the renderer normalizes: any direction but none
      return fail(where + "/rotation", "node rotation must be a quaternion of non-zero length");
    return {};
  }

 private:
  static std::string value_text(double v) { return shortened(Json(v).dump(), 24); }

  const std::string& file_;
};

}  // namespace

Status check_gltf_spec_values(std::string_view json_text, const std::string& file) {
  const Json root = Json::parse(json_text.begin(), json_text.end(), nullptr, /*allow_exceptions=*/false);
  if (root.is_discarded() || !root.is_object()) return {};
  const SpecChecker check(file);
  for (const char* key : {"extensionsUsed", "extensionsRequired"})
    if (Status s = check.string_array(root, key); !s) return s;
  if (Status s = check.scene_index(root); !s) return s;
  if (root.contains("extensions") && root["extensions"].is_object() &&
      root["extensions"].contains("KHR_lights_punctual")) {
    const Json& ext = root["extensions"]["KHR_lights_punctual"];
    if (ext.is_object() && ext.contains("lights") && ext["lights"].is_array())
      for (size_t i = 0; i < ext["lights"].size(); ++i)
        if (Status s = check.light(ext["lights"][i], "/extensions/KHR_lights_punctual/lights/" + std::to_string(i)); !s)
          return s;
  }
  auto each = [&](const char* array, auto&& check_item) -> Status {
    if (!root.contains(array) || !root[array].is_array()) return {};
    for (size_t i = 0; i < root[array].size(); ++i)
      if (Status s = check_item(root[array][i], "/" + std::string(array) + "/" + std::to_string(i)); !s) return s;
    return {};
  };
  if (Status s = each("cameras", [&](const Json& c, const std::string& w) { return check.camera(c, w); }); !s) return s;
  if (Status s = each("nodes", [&](const Json& n, const std::string& w) { return check.node(n, w); }); !s) return s;
  return {};
}

}  // namespace penumbra::scene
