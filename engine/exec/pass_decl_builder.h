#pragma once
// Declares a pass type with a chained builder (Falcor's RenderPassReflection style), so a pass
// file states its slots and parameters in a few readable lines:
//
//   return exec::PassDeclBuilder("hard_mask")
//       .describe("Binary shadow mask: one nearest shadow-map comparison per pixel (compute)")
//       .sampled("position", {Format::RGBA32F})
//       .sampled("shadow_map", {Format::DEPTH32F})
//       .image_out("mask", {Format::R16F})
//       .same_size({"position", "mask"})
//       .real("depth_bias", 0.0005, 0.0, 0.05, "window depth", "Subtracted from the receiver depth")
//       .build<HardMaskPass>();
#include <memory>
#include <string>
#include <vector>

#include "exec/pass.h"

namespace penumbra::exec {

class PassDeclBuilder {
 public:
  using Format = graph::Format;
  explicit PassDeclBuilder(std::string name) { decl_.name = std::move(name); }

  PassDeclBuilder& describe(std::string text) {
    decl_.description = std::move(text);
    return *this;
  }
  // Read through a sampler (texelFetch / texture).
  PassDeclBuilder& sampled(std::string slot, std::vector<Format> formats = {}, bool required = true) {
    return add(std::move(slot), graph::Access::read, graph::Usage::sampled, std::move(formats), required);
  }
  // Read with imageLoad.
  PassDeclBuilder& image_in(std::string slot, std::vector<Format> formats = {}) {
    return add(std::move(slot), graph::Access::read, graph::Usage::image_load, std::move(formats), true);
  }
  // Written with imageStore (incoherent: the compiler plans the barrier before the next use).
  PassDeclBuilder& image_out(std::string slot, std::vector<Format> formats = {}, bool required = true) {
    return add(std::move(slot), graph::Access::write, graph::Usage::image_store, std::move(formats), required);
  }
  // Written with imageStore into the texture of the version two writes back (graph::SlotDecl::
  // ping_pong): the pass may write part of the image and keep the rest.
  PassDeclBuilder& image_out_ping_pong(std::string slot, std::vector<Format> formats = {}) {
    image_out(std::move(slot), std::move(formats));
    decl_.slots.back().ping_pong = true;
    return *this;
  }
  // Read and written in place with imageLoad/imageStore (version n in, n+1 out).
  PassDeclBuilder& image_inout(std::string slot, std::vector<Format> formats = {}) {
    return add(std::move(slot), graph::Access::read_write, graph::Usage::image_store, std::move(formats), true);
  }
  PassDeclBuilder& color_out(std::string slot, std::vector<Format> formats = {}) {
    return add(std::move(slot), graph::Access::write, graph::Usage::color_attachment, std::move(formats), true);
  }
  PassDeclBuilder& depth_out(std::string slot) {
    return add(std::move(slot), graph::Access::write, graph::Usage::depth_attachment, {Format::DEPTH32F}, true);
  }
  // A tile list (graph/resources.h) this pass fills; a later pass dispatches over it.
  PassDeclBuilder& tile_list_out(std::string slot, bool required = true) {
    decl_.slots.push_back({std::move(slot), graph::Access::write, graph::SlotKind::buffer, {},
                           graph::Usage::storage_buffer, required, true});
    return *this;
  }
  // A tile list an earlier pass filled: this pass runs one work group per tile in it.
  PassDeclBuilder& tile_list_in(std::string slot, bool required = true) {
    decl_.slots.push_back({std::move(slot), graph::Access::read, graph::SlotKind::buffer, {},
                           graph::Usage::indirect_dispatch, required, true});
    return *this;
  }
  // scene, camera, light: provided by the executor through FrameInputs.
  PassDeclBuilder& imported(std::string slot, bool required = true) {
    decl_.slots.push_back({std::move(slot), graph::Access::read, graph::SlotKind::imported, {},
                           graph::Usage::imported, required});
    return *this;
  }

  PassDeclBuilder& real(std::string name, double def, double min, double max, std::string unit,
                        std::string description) {
    return param(graph::real_param(std::move(name), def, min, max, std::move(unit), std::move(description)));
  }
  PassDeclBuilder& integer(std::string name, int def, int min, int max, std::string unit, std::string description) {
    return param(graph::int_param(std::move(name), def, min, max, std::move(unit), std::move(description)));
  }
  PassDeclBuilder& boolean(std::string name, bool def, std::string description) {
    return param(graph::bool_param(std::move(name), def, std::move(description)));
  }
  PassDeclBuilder& enumeration(std::string name, std::string def, std::vector<std::string> options,
                               std::string description) {
    return param(graph::enum_param(std::move(name), std::move(def), std::move(options), std::move(description)));
  }
  // Valid values of the integer parameter added last: its min + k * n (2 from an odd min: odd).
  PassDeclBuilder& step(int n) {
    if (!decl_.params.empty()) decl_.params.back().step = n;
    return *this;
  }
  // The parameter added last has no default: every pass of this type must bind it (its
  // declared default is then only what a UI starts from).
  PassDeclBuilder& required() {
    if (!decl_.params.empty()) decl_.params.back().required = true;
    return *this;
  }
  PassDeclBuilder& param(graph::ParamDesc desc) {
    decl_.params.push_back(std::move(desc));
    return *this;
  }

  PassDeclBuilder& same_size(std::vector<std::string> slots) {
    decl_.same_size_groups.push_back(std::move(slots));
    return *this;
  }
  PassDeclBuilder& side_effect() {
    decl_.side_effect = true;
    return *this;
  }

  const graph::PassTypeDecl& decl() const { return decl_; }
  template <class Impl>
  PassType build() const {
    return {decl_, [] { return std::make_unique<Impl>(); }};
  }

 private:
  PassDeclBuilder& add(std::string slot, graph::Access access, graph::Usage usage, std::vector<Format> formats,
                       bool required) {
    decl_.slots.push_back({std::move(slot), access, graph::SlotKind::texture, std::move(formats), usage, required});
    return *this;
  }
  graph::PassTypeDecl decl_;
};

}  // namespace penumbra::exec
