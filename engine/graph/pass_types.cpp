#include "graph/pass_types.h"

#include <algorithm>

namespace penumbra::graph {

const char* access_name(Access a) {
  switch (a) {
    case Access::read: return "read";
    case Access::write: return "write";
    case Access::read_write: return "read_write";
  }
  return "?";
}

const char* usage_name(Usage u) {
  switch (u) {
    case Usage::sampled: return "sampled";
    case Usage::image_load: return "image_load";
    case Usage::image_store: return "image_store";
    case Usage::color_attachment: return "color_attachment";
    case Usage::depth_attachment: return "depth_attachment";
    case Usage::storage_buffer: return "storage_buffer";
    case Usage::indirect_dispatch: return "indirect_dispatch";
    case Usage::imported: return "imported";
  }
  return "?";
}

const char* slot_kind_name(SlotKind k) {
  switch (k) {
    case SlotKind::texture: return "texture";
    case SlotKind::buffer: return "buffer";
    case SlotKind::imported: return "imported";
  }
  return "?";
}

const SlotDecl* PassTypeDecl::find_slot(std::string_view slot) const {
  for (const auto& s : slots)
    if (s.name == slot) return &s;
  return nullptr;
}

const ParamDesc* PassTypeDecl::find_param(std::string_view param) const {
  for (const auto& p : params)
    if (p.name == param) return &p;
  return nullptr;
}

void PassTypeRegistry::add(PassTypeDecl decl) {
  std::string key = decl.name;
  types_[key] = std::move(decl);
}

const PassTypeDecl* PassTypeRegistry::find(std::string_view name) const {
  auto it = types_.find(std::string(name));
  return it == types_.end() ? nullptr : &it->second;
}

std::vector<std::string> PassTypeRegistry::names() const {
  std::vector<std::string> out;
  for (const auto& [k, v] : types_) out.push_back(k);
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace penumbra::graph
