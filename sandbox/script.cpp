#include "sandbox/script.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>

#include <nlohmann/json.hpp>

#include "sandbox/view_mapping.h"
#include "scene/light.h"
#include "util/file_read.h"
#include "util/json_text.h"

namespace penumbra::sandbox {

// ordered: a "set" step applies its assignments in the order written.
using json = nlohmann::ordered_json;

namespace {

struct StepName {
  const char* key;
  StepKind kind;
};
constexpr StepName kSteps[] = {
    {"scene", StepKind::scene},       {"technique", StepKind::technique},
    {"set", StepKind::set},           {"reset", StepKind::reset},
    {"camera", StepKind::camera},     {"light", StepKind::light},
    {"shadow_size", StepKind::shadow_size}, {"wait", StepKind::wait},
    {"screenshot", StepKind::screenshot}, {"compare", StepKind::compare},
    {"view", StepKind::view},         {"resize", StepKind::resize},
    {"expect_no_gl_error", StepKind::expect_no_gl_error}, {"ground", StepKind::ground},
    {"metrics", StepKind::metrics},   {"inspect", StepKind::inspect},
    {"graph", StepKind::graph},       {"debug", StepKind::debug},
    {"save_view", StepKind::save_view}, {"record", StepKind::record},
};

std::string valid_step_names() {
  std::string s;
  for (const StepName& n : kSteps) s += (s.empty() ? "" : ", ") + std::string(n.key);
  return s;
}

// Thrown inside parse_step only, turned into an Error naming the step by parse_script.
struct StepProblem {
  std::string message;
};

[[noreturn]] void problem(std::string message) { throw StepProblem{std::move(message)}; }

// A value echoed in a message: one short line whatever the input is.
std::string echo(const json& v) { return shortened(v.dump(), 60); }

// Positions and directions are world units; beyond this a float has no precision left for a
// camera or light to be meaningful (1e300 becomes inf in a float).
constexpr float kMaxCoordinate = 1e6f;

std::string need_string(const json& v, const std::string& what) {
  if (!v.is_string()) problem(what + " must be a string, got " + echo(v));
  return v.get<std::string>();
}

float need_number(const json& v, const std::string& what) {
  if (!v.is_number()) problem(what + " must be a number, got " + echo(v));
  const double d = v.get<double>();
  if (!std::isfinite(d) || std::fabs(d) > kMaxCoordinate)
    problem(what + " must be a finite number within +-1e6, got " + echo(v));
  return static_cast<float>(d);
}

bool need_bool(const json& v, const std::string& what) {
  if (!v.is_boolean()) problem(what + " must be true or false, got " + echo(v));
  return v.get<bool>();
}

int need_int(const json& v, const std::string& what, int lo, int hi) {
  if (!v.is_number_integer()) problem(what + " must be an integer, got " + echo(v));
  auto i = v.get<long long>();
  if (i < lo || i > hi)
    problem(what + " must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got " +
            std::to_string(i));
  return static_cast<int>(i);
}

glm::vec3 need_vec3(const json& v, const std::string& what) {
  if (!v.is_array() || v.size() != 3 || !v[0].is_number() || !v[1].is_number() || !v[2].is_number())
    problem(what + " must be an array of 3 numbers [x, y, z], got " + echo(v));
  return {need_number(v[0], what + "[0]"), need_number(v[1], what + "[1]"), need_number(v[2], what + "[2]")};
}

void only_keys(const json& obj, std::initializer_list<const char*> keys, const std::string& what) {
  if (!obj.is_object()) problem(what + " must be an object, got " + echo(obj));
  for (auto it = obj.begin(); it != obj.end(); ++it) {
    const std::string& k = it.key();
    if (std::none_of(keys.begin(), keys.end(), [&](const char* a) { return k == a; })) {
      std::string list;
      for (const char* a : keys) list += (list.empty() ? "" : ", ") + std::string(a);
      problem(what + ": unknown key '" + shortened(k) + "' (expected " + list + ")");
    }
  }
}

// A JSON scalar as the text ParameterSet::set_from_string parses ("true", "3", "0.25", "vogel").
std::string value_text(const json& v, const std::string& key) {
  if (v.is_boolean()) return v.get<bool>() ? "true" : "false";
  if (v.is_number_integer()) return std::to_string(v.get<long long>());
  if (v.is_number()) return v.dump();
  if (v.is_string()) return v.get<std::string>();
  problem("set: value of '" + shortened(key) + "' must be a boolean, number or string, got " + echo(v));
}

void parse_body(ScriptStep& s, const json& v) {
  switch (s.kind) {
    case StepKind::scene: s.text = need_string(v, "scene"); break;
    case StepKind::technique: s.text = need_string(v, "technique"); break;
    case StepKind::screenshot:
    case StepKind::metrics:
    case StepKind::graph: {
      const std::string key = step_kind_name(s.kind);
      s.text = need_string(v, key);
      if (s.text.empty()) problem(key + ": the path is empty");
      // Checked before any frame runs: a long script must not fail at its last step.
      const std::filesystem::path dir = std::filesystem::path(s.text).parent_path();
      std::error_code ec;
      if (Status d = dir.empty() ? Status() : check_directory(dir.string()); !d)
        problem(key + ": '" + shortened(dir.string()) + "' " + d.error().message);
      if (std::filesystem::is_directory(s.text, ec)) problem(key + ": '" + shortened(s.text) + "' is a directory");
      break;
    }
    case StepKind::reset:
      s.text = v.is_boolean() && v.get<bool>() ? "all" : need_string(v, "reset (\"all\" or a parameter)");
      break;
    case StepKind::set:
      if (!v.is_object() || v.empty()) problem("set must be a non-empty object {\"name\": value}, got " + echo(v));
      for (const auto& [k, val] : v.items()) s.assignments.emplace_back(k, value_text(val, k));
      break;
    case StepKind::wait: s.number = need_int(v, "wait (frames)", 1, 100000); break;
    case StepKind::shadow_size: s.number = need_int(v, "shadow_size (texels)", 16, 16384); break;
    case StepKind::resize:
      if (!v.is_array() || v.size() != 2) problem("resize must be [width, height], got " + echo(v));
      s.width = need_int(v[0], "resize width (pixels)", 16, 8192);
      s.height = need_int(v[1], "resize height (pixels)", 16, 8192);
      break;
    case StepKind::expect_no_gl_error:
      if (!v.is_boolean() || !v.get<bool>()) problem("expect_no_gl_error must be true, got " + echo(v));
      break;
    case StepKind::inspect: {
      only_keys(v, {"at", "out"}, "inspect");
      if (!v.contains("at") || !v["at"].is_array() || v["at"].size() != 2)
        problem("inspect.at must be [x, y] (frame pixel, origin top-left), got " + echo(v.value("at", json())));
      s.inspect.x = need_int(v["at"][0], "inspect.at x (pixels)", 0, 16383);
      s.inspect.y = need_int(v["at"][1], "inspect.at y (pixels)", 0, 16383);
      s.inspect.out = v.contains("out") ? need_string(v["out"], "inspect.out") : "";
      if (s.inspect.out.empty()) problem("inspect.out must name the JSON file to write");
      break;
    }
    case StepKind::save_view: {
      // {"save_view": {"format": "png"|"pfm", "dir": "out"}}: the viewed resource, named
      // RESOURCE_frameN.png/.pfm (viewed_resource.h).
      only_keys(v, {"format", "dir"}, "save_view");
      s.format = v.contains("format") ? need_string(v["format"], "save_view.format") : "";
      if (s.format != "png" && s.format != "pfm") problem("save_view.format must be \"png\" or \"pfm\", got \"" + shortened(s.format) + "\"");
      s.text = v.contains("dir") ? need_string(v["dir"], "save_view.dir") : ".";
      if (Status d = check_directory(s.text); !d) problem("save_view: '" + shortened(s.text) + "' " + d.error().message);
      break;
    }
    case StepKind::record: {
      // {"record": {"frames": 24, "path": "orbit"|"light", "degrees": 360, "dir": "seq"}}
      only_keys(v, {"frames", "path", "degrees", "dir"}, "record");
      if (v.contains("frames")) s.sequence.frames = need_int(v["frames"], "record.frames", 1, kMaxSequenceFrames);
      if (v.contains("path")) {
        Result<SequenceSpec::Path> path = parse_sequence_path(need_string(v["path"], "record.path"));
        if (!path) problem("record: " + path.error().message);
        else s.sequence.path = *path;
      }
      if (v.contains("degrees")) s.sequence.degrees = need_number(v["degrees"], "record.degrees");  // range: check_sequence
      s.sequence.dir = v.contains("dir") ? need_string(v["dir"], "record.dir") : "";
      if (Status st = check_sequence(s.sequence); !st) problem("record: " + st.error().message);
      break;
    }
    case StepKind::debug:
      only_keys(v, {"light_frustum", "blocker_region", "texel_density", "light_gizmo"}, "debug");
      for (const auto& [key, field] : {std::pair{"light_frustum", &s.light_frustum}, std::pair{"blocker_region", &s.blocker_region},
                                       std::pair{"texel_density", &s.texel_density}, std::pair{"light_gizmo", &s.light_gizmo}})
        if (v.contains(key)) *field = need_bool(v[key], std::string("debug.") + key);
      if (v.empty()) problem("debug: give at least one of light_frustum, blocker_region, texel_density, light_gizmo");
      break;
    case StepKind::ground:
      s.flag = need_bool(v, "ground");
      break;
    case StepKind::camera:
      if (v.is_string()) {
        const std::string c = v.get<std::string>();
        if (c != "fit" && c != "file" && c.rfind("file:", 0) != 0)
          problem("camera must be \"fit\", \"file\", \"file:NAME\" or an object, got " + echo(v));
        s.camera.choice = c;
        break;
      }
      only_keys(v, {"position", "look_at", "yaw", "pitch"}, "camera");
      if (v.empty()) problem("camera: give at least one of position, look_at, yaw, pitch");
      if (v.contains("position")) s.camera.position = need_vec3(v["position"], "camera.position");
      if (v.contains("look_at")) s.camera.look_at = need_vec3(v["look_at"], "camera.look_at");
      if (v.contains("yaw")) s.camera.yaw_deg = need_number(v["yaw"], "camera.yaw (degrees)");
      if (v.contains("pitch")) s.camera.pitch_deg = need_number(v["pitch"], "camera.pitch (degrees)");
      break;
    case StepKind::light:
      only_keys(v, {"type", "direction", "position", "size", "spot_angle", "frozen"}, "light");
      if (v.contains("frozen")) s.light.frozen = need_bool(v["frozen"], "light.frozen");
      if (v.empty()) problem("light: give at least one of type, direction, position, size, spot_angle");
      if (v.contains("type")) {
        s.light.type = need_string(v["type"], "light.type");
        if (*s.light.type != "directional" && *s.light.type != "spot" && *s.light.type != "point")
          problem("light.type must be \"directional\", \"spot\" or \"point\", got \"" + *s.light.type + "\"");
      }
      if (v.contains("direction")) {
        s.light.direction = need_vec3(v["direction"], "light.direction");
        if (glm::length(*s.light.direction) < 1e-6f) problem("light.direction must not be zero");
      }
      if (v.contains("position")) s.light.position = need_vec3(v["position"], "light.position");
      if (v.contains("size")) {
        s.light.size = need_number(v["size"], "light.size (world units)");
        if (*s.light.size < 0.0f) problem("light.size must be >= 0 (emitter diameter, world units)");
      }
      if (v.contains("spot_angle")) {
        s.light.spot_angle_deg = need_number(v["spot_angle"], "light.spot_angle (degrees)");
        if (Status a = scene::check_spot_angle_degrees(*s.light.spot_angle_deg); !a) problem("light." + a.error().message);
      }
      break;
    case StepKind::compare:
      if (v.is_boolean()) {
        s.compare.enabled = v.get<bool>();
      } else if (v.is_string()) {
        s.compare.enabled = true;
        s.compare.with = v.get<std::string>();
      } else {
        only_keys(v, {"enabled", "with", "view", "three_way", "classes"}, "compare");
        if (v.contains("three_way")) s.compare.three_way = need_bool(v["three_way"], "compare.three_way");
        if (v.contains("classes")) s.compare.classes = need_bool(v["classes"], "compare.classes");
        s.compare.enabled = !v.contains("enabled") || need_bool(v["enabled"], "compare.enabled");
        if (v.contains("with")) s.compare.with = need_string(v["with"], "compare.with");
        if (v.contains("view")) {
          s.compare.view = need_string(v["view"], "compare.view");
          if (s.compare.view != "split" && s.compare.view != "error")
            problem("compare.view must be \"split\" or \"error\", got \"" + s.compare.view + "\"");
        }
      }
      break;
    case StepKind::view:
      if (v.is_string()) {
        s.view.resource = v.get<std::string>();
        break;
      }
      only_keys(v, {"resource", "map", "placement", "min", "max", "channel", "channels", "zoom", "center", "auto_range"}, "view");
      if (v.contains("zoom")) {
        s.view.zoom = need_number(v["zoom"], "view.zoom");
        if (!(*s.view.zoom >= 1.0f && *s.view.zoom <= 64.0f)) problem("view.zoom must be in [1, 64], got " + echo(v["zoom"]));
      }
      if (v.contains("center")) {
        const auto& a = v["center"];
        if (!a.is_array() || a.size() != 2 || !a[0].is_number() || !a[1].is_number())
          problem("view.center must be [u, v] (uv at the frame's middle), got " + echo(a));
        s.view.center = glm::vec2(a[0].get<float>(), a[1].get<float>());
      }
      if (v.contains("auto_range")) s.view.auto_range = need_bool(v["auto_range"], "view.auto_range");
      if (v.contains("resource")) s.view.resource = need_string(v["resource"], "view.resource");
      if (v.contains("map")) {
        s.view.map = need_string(v["map"], "view.map");
        if (!colour_map_index(s.view.map))
          problem("view.map must be \"color\", \"grey\", \"heat\" or \"signed\", got \"" + s.view.map + "\"");
      }
      if (v.contains("placement")) {
        s.view.placement = need_string(v["placement"], "view.placement");
        if (s.view.placement != "full" && s.view.placement != "inset")
          problem("view.placement must be \"full\" or \"inset\", got \"" + s.view.placement + "\"");
      }
      if (v.contains("min")) s.view.min = need_number(v["min"], "view.min");
      if (v.contains("max")) s.view.max = need_number(v["max"], "view.max");
      if (s.view.min && s.view.max && !(*s.view.min < *s.view.max))
        problem("view.min must be below view.max, got min " + echo(v["min"]) + " and max " + echo(v["max"]));
      if (v.contains("channel")) s.view.channel = need_int(v["channel"], "view.channel", 0, 3);
      if (v.contains("channels")) {
        const std::string letters = need_string(v["channels"], "view.channels");
        unsigned mask = 0;
        for (char ch : letters) {
          const size_t bit = std::string("rgba").find(ch);
          if (bit == std::string::npos) problem("view.channels must be letters of \"rgba\", got \"" + shortened(letters) + "\"");
          else mask |= 1u << bit;
        }
        if (mask == 0) problem("view.channels must name at least one of r, g, b, a");
        s.view.channel_mask = mask;
      }
      break;
  }
}

}  // namespace

const char* step_kind_name(StepKind kind) {
  for (const StepName& n : kSteps)
    if (n.kind == kind) return n.key;
  return "?";
}

Error step_error(const ScriptStep& step, const std::string& message) {
  Error e = make_error("script step " + std::to_string(step.index) + " (" + step_kind_name(step.kind) +
                       "): " + message);
  e.where = "/" + std::to_string(step.index);
  e.file = step.source;
  return e;
}

Result<std::vector<ScriptStep>> parse_script(const std::string& text, const std::string& source) {
  auto fail = [&](std::string message, int line = 0, int column = 0) {
    Error e = make_error(std::move(message));
    e.file = source;
    e.line = line;
    e.column = column;
    return e;
  };
  // Nesting, numbers that overflow, duplicate keys: refused with their position before parsing.
  if (std::optional<JsonTextProblem> p = scan_json_text(text))
    return fail("script: " + p->message, p->line, p->column);
  json j;
  try {
    j = json::parse(text);
  } catch (const json::parse_error& ex) {
    int line = 0, column = 0;
    byte_offset_to_line_col(text, ex.byte > 0 ? ex.byte - 1 : 0, line, column);
    return fail("script is not valid JSON: " + shortened(ex.what(), 200), line, column);
  } catch (const std::exception& ex) {
    return fail("script is not valid JSON: " + shortened(ex.what(), 200));
  }
  if (!j.is_array())
    return fail("a script must be a JSON array of steps, e.g. [{\"technique\": \"pcss\"}, {\"wait\": 2}]");
  if (j.size() > kMaxScriptSteps)
    return fail("script has " + std::to_string(j.size()) + " steps; at most " + std::to_string(kMaxScriptSteps));
  std::vector<ScriptStep> steps;
  for (size_t i = 0; i < j.size(); ++i) {
    const json& item = j[i];
    ScriptStep s;
    s.index = static_cast<int>(i);
    s.source = source;
    try {
      if (!item.is_object() || item.size() != 1)
        problem("each step must be an object with exactly one key (one of " + valid_step_names() +
                "), got " + echo(item));
      const std::string key = item.begin().key();
      auto it = std::find_if(std::begin(kSteps), std::end(kSteps),
                             [&](const StepName& n) { return key == n.key; });
      if (it == std::end(kSteps))
        problem("unknown step '" + shortened(key) + "' (expected one of " + valid_step_names() + ")");
      s.kind = it->kind;
      parse_body(s, item.begin().value());
    } catch (const StepProblem& p) {
      Error e = fail("script step " + std::to_string(i) + ": " + p.message);
      e.where = "/" + std::to_string(i);
      return e;
    } catch (const std::exception& ex) {  // a JSON type/range error the checks above missed
      Error e = fail("script step " + std::to_string(i) + ": " + shortened(ex.what(), 200));
      e.where = "/" + std::to_string(i);
      return e;
    }
    steps.push_back(std::move(s));
  }
  return steps;
}

namespace {

std::string number_text(double v, graph::ParamType type) {
  if (type == graph::ParamType::integer) return std::to_string(static_cast<long long>(std::llround(v)));
  return json(v).dump();
}

// The values a test should visit for one parameter: min, max, default (or every option).
std::vector<std::string> interesting_values(const graph::ParamDesc& d) {
  std::vector<std::string> out;
  switch (d.type) {
    case graph::ParamType::boolean: out = {"false", "true"}; break;
    case graph::ParamType::enumeration: out = d.options; break;
    case graph::ParamType::integer:
    case graph::ParamType::real:
      if (d.has_range()) {
        out = {number_text(d.min, d.type), number_text(d.max, d.type)};
      } else {
        double def = d.type == graph::ParamType::integer ? std::get<int>(d.default_value)
                                                           : std::get<double>(d.default_value);
        out = {number_text(def * 2.0 + 1.0, d.type)};
      }
      break;
  }
  std::string def = graph::param_value_to_string(d.default_value);
  if (d.type == graph::ParamType::enumeration && def.size() >= 2) def = def.substr(1, def.size() - 2);
  out.push_back(def);
  return out;
}

json set_step(const std::string& name, const std::string& text) {
  return json{{"set", json{{name, text}}}};  // set accepts text for every type
}

}  // namespace

std::string exhaustive_script(const std::vector<TechniqueInfo>& techniques,
                              const std::string& screenshot_dir, int width, int height,
                              int shadow_size) {
  json steps = json::array();
  steps.push_back({{"resize", {width, height}}});
  steps.push_back({{"shadow_size", shadow_size}});
  for (const TechniqueInfo& t : techniques) {
    steps.push_back({{"technique", t.name}});
    steps.push_back({{"wait", 1}});
    for (const graph::ParamDesc& d : t.params)
      for (const std::string& v : interesting_values(d)) {
        steps.push_back(set_step(d.name, v));
        steps.push_back({{"wait", 1}});
      }
    steps.push_back({{"expect_no_gl_error", true}});
    steps.push_back({{"wait", 2}});
    steps.push_back({{"screenshot", screenshot_dir + "/" + t.name + ".png"}});
    steps.push_back({{"compare", true}});
    steps.push_back({{"wait", 2}});
    steps.push_back({{"screenshot", screenshot_dir + "/" + t.name + "_compare.png"}});
    steps.push_back({{"compare", {{"view", "error"}}}});
    steps.push_back({{"wait", 1}});
    steps.push_back({{"compare", false}});
    steps.push_back({{"view", {{"resource", "shadow_mask"}, {"map", "heat"}, {"placement", "inset"}}}});
    steps.push_back({{"wait", 1}});
    steps.push_back({{"view", ""}});
    steps.push_back({{"expect_no_gl_error", true}});
  }
  return steps.dump(1) + "\n";
}

std::string soak_script(const std::vector<TechniqueInfo>& techniques, std::uint32_t seed, int steps,
                        int max_size) {
  std::mt19937 rng(seed);
  auto pick = [&](int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng); };
  auto uniform = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
  json out = json::array();
  int current = 0;
  if (!techniques.empty()) out.push_back({{"technique", techniques[0].name}});
  while (static_cast<int>(out.size()) < steps - 1) {
    int r = pick(100);
    if (techniques.empty() || r < 10) {
      if (!techniques.empty()) {
        current = pick(static_cast<int>(techniques.size()));
        out.push_back({{"technique", techniques[current].name}});
      }
    } else if (r < 55) {
      const auto& params = techniques[current].params;
      if (params.empty()) continue;
      const graph::ParamDesc& d = params[pick(static_cast<int>(params.size()))];
      std::vector<std::string> values = interesting_values(d);
      if (d.type == graph::ParamType::real && d.has_range()) values.push_back(number_text(uniform(d.min, d.max), d.type));
      if (d.type == graph::ParamType::integer && d.has_range()) {  // a value on the parameter's grid
        int v = graph::nearest_step_value(d, static_cast<int>(uniform(d.min, d.max)));
        if (d.has_step() && v > d.max) v -= d.step;
        values.push_back(std::to_string(v));
      }
      out.push_back(set_step(d.name, values[pick(static_cast<int>(values.size()))]));
    } else if (r < 63) {
      out.push_back({{"resize", {16 + pick(max_size - 15), 16 + pick(max_size - 15)}}});
    } else if (r < 70) {
      // Compare against a technique of the list (never an implicit partner outside it).
      if (pick(2) == 0) out.push_back({{"compare", false}});
      else out.push_back({{"compare", techniques[pick(static_cast<int>(techniques.size()))].name}});
    } else if (r < 73) {
      out.push_back({{"reset", "all"}});
    } else {
      out.push_back({{"wait", 1}});
    }
  }
  out.push_back({{"expect_no_gl_error", true}});
  return out.dump() + "\n";
}

}  // namespace penumbra::sandbox
