#pragma once
// The GL-free pass type registry: what slots and parameters a pass type has. The executor
// registers a GL implementation under the same type name; the compiler only needs this.
//
//   PassTypeRegistry registry;
//   registry.add({.name = "blur",
//                 .slots = {{.name = "input", .access = Access::read, .kind = SlotKind::texture,
//                            .formats = {Format::R16F, Format::RGBA16F}, .usage = Usage::sampled},
//                           {.name = "output", .access = Access::write,
//                            .kind = SlotKind::texture, .usage = Usage::image_store}},
//                 .params = {{.name = "radius", .type = ParamType::integer,
//                             .default_value = 4, .min = 1, .max = 16, .unit = "texels"}},
//                 .same_size_groups = {{"input", "output"}}});
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "graph/parameters.h"
#include "graph/resources.h"

namespace penumbra::graph {

// read_write reads version n and produces n+1 in the same physical resource (in place).
enum class Access { read, write, read_write };
// How the pass touches the resource; drives barrier planning. image_store / storage_buffer
// writes are incoherent in GL and need a barrier before the next use.
// indirect_dispatch: a tile list the pass dispatches over (its header as the indirect
// arguments, its entries read as a storage buffer).
enum class Usage {
  sampled, image_load, image_store, color_attachment, depth_attachment, storage_buffer,
  indirect_dispatch, imported
};
// texture slots accept texture and persistent resources.
enum class SlotKind { texture, buffer, imported };

const char* access_name(Access a);
const char* usage_name(Usage u);
const char* slot_kind_name(SlotKind k);

struct SlotDecl {
  std::string name;
  Access access = Access::read;
  SlotKind kind = SlotKind::texture;
  std::vector<Format> formats;  // accepted formats; empty = any
  Usage usage = Usage::sampled;
  bool required = true;
  bool tile_list = false;  // a buffer slot that takes only a tile list (graph/resources.h)
  // A write whose new version n+1 lives in the physical texture of version n-1 of the same
  // resource, the one two writes back, and finds its contents there. A repeated pass reading n
  // and writing n+1 then alternates between two textures for certain (without it the pool may
  // hand any free texture of the descriptor), so a pass that writes only part of the image (a
  // tile list) leaves the rest as its iteration before last wrote it. Readers of n-1 run first.
  bool ping_pong = false;
};

struct PassTypeDecl {
  std::string name;
  std::vector<SlotDecl> slots;
  std::vector<ParamDesc> params;
  // Slots whose bound textures must resolve to the same size (e.g. a blur's in and out).
  std::vector<std::vector<std::string>> same_size_groups;
  bool side_effect = false;  // every instance is a culling root (e.g. presents)
  std::string description;

  const SlotDecl* find_slot(std::string_view slot) const;
  const ParamDesc* find_param(std::string_view param) const;
};

class PassTypeRegistry {
 public:
  // Replaces a declaration of the same name (a plugin may refine a generic type).
  void add(PassTypeDecl decl);
  const PassTypeDecl* find(std::string_view name) const;
  std::vector<std::string> names() const;  // sorted

 private:
  std::unordered_map<std::string, PassTypeDecl> types_;
};

}  // namespace penumbra::graph
