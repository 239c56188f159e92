#pragma once
// C++ way into the render graph: typed handles and chained pass builders, producing the same
// GraphDesc the JSON parser produces (so everything downstream is shared).
//
//   GraphBuilder b("pcss");
//   b.parameter({.name = "blur_passes", .type = ParamType::integer, .default_value = 2,
//                .min = 1, .max = 8, .description = "Blur repetitions", .structural = true});
//   ImportedHandle scene = b.import("scene"), light = b.import("light");
//   TextureHandle depth = b.texture("shadow_map", Format::DEPTH32F, SizeExpr::shadow());
//   TextureHandle mask = b.texture("shadow_mask", Format::R16F, SizeExpr::screen());
//   b.pass("shadow_map", "light_depth").read("scene", scene).read("light", light)
//       .write("depth", depth);
//   b.pass("pcf", "filter").read("shadow_map", depth).write("mask", mask)
//       .param("samples", 16);
//   b.pass("blur_in_place", "soften").read_write("image", mask)
//       .param("radius", "$blur_radius").repeat("$blur_passes").enabled("$use_blur");
//   b.output(mask);
//   GraphDesc graph = b.build();
//
// A pass parameter left unbound takes the graph parameter of the same name when there is one
// (implicit binding, graph_desc.h), so `.param("samples", "$samples")` is never needed.
//
// Rules: handles are only valid for the builder that made them; a handle names a logical
// resource, and each write makes a new version (graph_desc.h). `h.at(n)` pins version n.
// Names passed to the builder must be unique; the compiler reports duplicates.
#include <cstdint>
#include <string>

#include "graph/graph_desc.h"

namespace penumbra::graph {

struct TextureHandle {
  int index = -1;
  int version = -1;  // -1: implicit (latest / next)
  TextureHandle at(int v) const { return {index, v}; }
};
struct BufferHandle {
  int index = -1;
  int version = -1;
  BufferHandle at(int v) const { return {index, v}; }
};
struct ImportedHandle {
  int index = -1;
};

class GraphBuilder;

class PassBuilder {
 public:
  PassBuilder& read(const std::string& slot, TextureHandle h);
  PassBuilder& read(const std::string& slot, BufferHandle h);
  PassBuilder& read(const std::string& slot, ImportedHandle h);
  PassBuilder& write(const std::string& slot, TextureHandle h);
  PassBuilder& write(const std::string& slot, BufferHandle h);
  PassBuilder& write(const std::string& slot, ImportedHandle h);
  PassBuilder& read_write(const std::string& slot, TextureHandle h);
  PassBuilder& read_write(const std::string& slot, BufferHandle h);
  // A constant, or "$name" to reference a technique parameter.
  PassBuilder& param(const std::string& name, ParamValue value);
  PassBuilder& param(const std::string& name, const char* value_or_reference);
  PassBuilder& repeat(int count);
  PassBuilder& repeat(const std::string& reference);  // "$param"
  PassBuilder& enabled(const std::string& condition);  // condition.h grammar
  // Makes the binding just added (slot or parameter) apply only when `condition` holds; the
  // first applying binding of a slot or parameter wins (graph_desc.h):
  //   .write("mask", checker).when("$checkerboard").write("mask", mask)
  PassBuilder& when(const std::string& condition);
  PassBuilder& side_effect(bool on = true);

 private:
  friend class GraphBuilder;
  PassBuilder(GraphBuilder& owner, int pass) : owner_(&owner), pass_(pass) {}
  PassBuilder& bind(const std::string& slot, int resource, int version);
  enum class Last { none, slot, param };
  GraphBuilder* owner_;
  int pass_;
  Last last_ = Last::none;
};

class GraphBuilder {
 public:
  explicit GraphBuilder(std::string name);
  void parameter(ParamDesc desc);
  TextureHandle texture(const std::string& name, Format format, SizeExpr size);  // SizeExpr::screen_by("p") for screen/$p
  TextureHandle persistent(const std::string& name, Format format, SizeExpr size);
  BufferHandle buffer(const std::string& name, std::uint64_t bytes);
  // A tile list over `tiles` (SizeExpr::screen(8): the screen in 8 x 8-pixel tiles).
  BufferHandle tile_list(const std::string& name, SizeExpr tiles);
  // A texture of one texel per tile of `tiles` (SizeExpr::screen(16): ceil(w / 16) x ceil(h / 16)).
  TextureHandle tile_texture(const std::string& name, Format format, SizeExpr tiles);
  ImportedHandle import(const std::string& name);
  PassBuilder pass(const std::string& type, const std::string& name);
  void output(TextureHandle h);
  void output(BufferHandle h);
  void output(const std::string& resource_name);
  const GraphDesc& desc() const { return desc_; }
  GraphDesc build() const { return desc_; }

 private:
  friend class PassBuilder;
  int add_resource(ResourceDecl decl);
  GraphDesc desc_;
};

}  // namespace penumbra::graph
