// Text and Graphviz views of a CompiledPlan. The text dump is the golden-file format: keep
// it deterministic (no addresses, no hash-map order) and stable across refactors.
#include <cstdio>
#include <sstream>

#include "graph/plan.h"

namespace penumbra::graph {

std::string barrier_bits_to_string(std::uint32_t bits) {
  static const std::pair<std::uint32_t, const char*> kNames[] = {
      {barrier_texture_fetch, "texture_fetch"},
      {barrier_shader_image_access, "shader_image_access"},
      {barrier_framebuffer, "framebuffer"},
      {barrier_storage_buffer, "storage_buffer"},
      {barrier_texture_update, "texture_update"},
      {barrier_command, "command"}};
  std::string out;
  for (auto [bit, name] : kNames)
    if (bits & bit) out += (out.empty() ? "" : "|") + std::string(name);
  return out.empty() ? "none" : out;
}

int CompiledPlan::physical_for(const std::string& name, int version) const {
  if (version < 0) {
    auto it = physical_of.find(name);
    return it == physical_of.end() ? -1 : it->second;
  }
  for (const auto& v : versions)
    if (v.name == name && v.version == version) return v.physical;
  return -1;
}

static std::string physical_label(const PhysicalResource& p) {
  std::ostringstream s;
  s << "#" << p.id << " ";
  if (p.kind == ResourceKind::buffer) s << "buffer " << p.bytes << " B";
  else s << format_name(p.format) << " " << p.width << "x" << p.height;
  if (p.kind == ResourceKind::persistent) s << " persistent";
  return s.str();
}

static std::string binding_text(const PlannedBinding& b) {
  std::string s = b.slot + " " + access_name(b.access) + " ";
  if (b.read_version >= 0 && b.write_version >= 0)
    s += b.resource + "@" + std::to_string(b.read_version) + "->@" + std::to_string(b.write_version);
  else
    s += b.resource + "@" + std::to_string(b.read_version >= 0 ? b.read_version : b.write_version);
  s += " (" + std::string(usage_name(b.usage)) + ") ";
  s += b.physical >= 0 ? "#" + std::to_string(b.physical) : "imported";
  return s;
}

std::string to_text(const CompiledPlan& plan) {
  std::ostringstream o;
  o << "graph " << plan.graph_name << "\n";
  o << "settings screen " << plan.settings.screen_w << "x" << plan.settings.screen_h
    << " shadow " << plan.settings.shadow_size << "\n";
  o << "options no_reuse=" << plan.options.no_reuse
    << " extended_lifetimes=" << plan.options.extended_lifetimes << "\n";
  o << "\norder\n";
  for (size_t i = 0; i < plan.passes.size(); ++i) {
    const PlannedPass& p = plan.passes[i];
    o << "  " << i << " " << p.name << " : " << p.type << "\n";
    if (p.barriers) {
      o << "      barrier " << barrier_bits_to_string(p.barriers) << " [";
      for (size_t k = 0; k < p.barrier_reasons.size(); ++k)
        o << (k ? ", " : "") << p.barrier_reasons[k];
      o << "]\n";
    }
    for (const PlannedBinding& b : p.bindings) o << "      " << binding_text(b) << "\n";
    for (const PlannedParam& pp : p.params) {
      o << "      param " << pp.name << " = ";
      if (!pp.reference.empty()) o << "$" << pp.reference << " (now " << param_value_to_string(pp.value) << ")";
      else o << param_value_to_string(pp.value);
      o << "\n";
    }
  }
  o << "\nculled";
  for (const auto& c : plan.culled) o << " " << c;
  o << "\ndisabled";
  for (const auto& d : plan.disabled) o << " " << d;
  o << "\n\nresources (version: physical [first, last])\n";
  for (const ResourceVersion& v : plan.versions) {
    o << "  " << v.label() << " " << resource_kind_name(v.kind) << ": ";
    o << (v.physical >= 0 ? "#" + std::to_string(v.physical) : std::string("imported"));
    o << " [" << v.first_use << ", " << v.last_use << "]\n";
  }
  o << "\nphysical\n";
  for (const PhysicalResource& p : plan.physical) {
    o << "  " << physical_label(p) << " (" << p.bytes << " B):";
    for (const auto& h : p.holds) o << " " << h;
    o << "\n";
  }
  o << "\noutputs";
  for (const auto& name : plan.outputs) {
    int id = plan.physical_for(name);
    o << " " << name << "=" << (id >= 0 ? "#" + std::to_string(id) : std::string("none"));
  }
  o << "\nmemory naive " << plan.memory.naive_bytes << " B, assigned "
    << plan.memory.assigned_bytes << " B\n";
  return o.str();
}

// "read 24.9 MB, wrote 4.1 MB"
static std::string traffic_label(const PassTraffic& t) {
  char text[96];
  std::snprintf(text, sizeof text, "read %.1f MB, wrote %.1f MB", static_cast<double>(t.read_bytes) / 1e6,
                static_cast<double>(t.written_bytes) / 1e6);
  return text;
}

std::string to_dot(const CompiledPlan& plan) {
  std::ostringstream o;
  o << "digraph \"" << plan.graph_name << "\" {\n  rankdir=LR;\n";
  o << "  node [fontname=\"Helvetica\"];\n";
  for (size_t i = 0; i < plan.passes.size(); ++i)
    o << "  p" << i << " [shape=box, style=filled, fillcolor=\"#ffd8a8\", label=\""
      << plan.passes[i].name << "\\n" << plan.passes[i].type << "\\n" << traffic_label(plan.passes[i].traffic)
      << "\"];\n";
  for (size_t i = 0; i < plan.versions.size(); ++i) {
    const auto& v = plan.versions[i];
    o << "  r" << i << " [shape=ellipse, label=\"" << v.label() << "\\n"
      << (v.physical >= 0 ? "#" + std::to_string(v.physical) : std::string("imported")) << "\"];\n";
  }
  auto version_node = [&](const std::string& name, int version) {
    for (size_t i = 0; i < plan.versions.size(); ++i)
      if (plan.versions[i].name == name && plan.versions[i].version == version) return static_cast<int>(i);
    return -1;
  };
  for (size_t i = 0; i < plan.passes.size(); ++i) {
    for (const PlannedBinding& b : plan.passes[i].bindings) {
      if (b.read_version >= 0)
        if (int r = version_node(b.resource, b.read_version); r >= 0)
          o << "  r" << r << " -> p" << i << " [label=\"" << b.slot << "\"];\n";
      if (b.write_version >= 0)
        if (int r = version_node(b.resource, b.write_version); r >= 0)
          o << "  p" << i << " -> r" << r << " [label=\"" << b.slot << "\"];\n";
    }
  }
  o << "}\n";
  return o.str();
}

}  // namespace penumbra::graph
