#include "technique/frame_graph.h"

#include <algorithm>
#include <optional>
#include <string>

#include "graph/builder.h"

namespace penumbra::technique {
namespace {

bool same_decl(const graph::ResourceDecl& a, const graph::ResourceDecl& b) {
  if (a.kind != b.kind) return false;
  if (a.kind == graph::ResourceKind::imported) return true;
  if (a.kind == graph::ResourceKind::buffer) return a.bytes == b.bytes;
  return a.format == b.format && a.size.to_string() == b.size.to_string();
}

constexpr const char* kFrameResources[] = {"scene",          "camera",         "light",          "gbuffer_depth",
                                           "gbuffer_normal", "gbuffer_albedo", "gbuffer_zbuffer"};

// A technique pass binding a resource the frame used to provide: an error naming it, where it
// is bound, and its replacement.
std::optional<Error> removed_frame_resource(const graph::GraphDesc& technique) {
  for (size_t p = 0; p < technique.passes.size(); ++p)
    for (const graph::SlotBinding& b : technique.passes[p].slots)
      for (const RemovedFrameResource& removed : kRemovedFrameResources)
        if (b.resource == removed.name) {
          Error e = make_error("pass '" + technique.passes[p].name + "', slot '" + b.slot + "': resource '" +
                               removed.name + "' is no longer part of the frame: " + removed.replacement);
          e.file = technique.source_file;
          e.where = b.location.empty() ? "/passes/" + std::to_string(p) : b.location;
          return e;
        }
  return std::nullopt;
}

}  // namespace

bool reads_frame_resources(const graph::GraphDesc& graph) {
  for (const graph::PassDecl& p : graph.passes)
    for (const graph::SlotBinding& b : p.slots) {
      bool frame = std::find(std::begin(kFrameResources), std::end(kFrameResources), b.resource) !=
                       std::end(kFrameResources) ||
                   std::any_of(std::begin(kRemovedFrameResources), std::end(kRemovedFrameResources),
                               [&](const RemovedFrameResource& r) { return b.resource == r.name; });
      bool declared = std::any_of(graph.resources.begin(), graph.resources.end(),
                                  [&](const graph::ResourceDecl& r) { return r.name == b.resource; });
      if (frame && !declared) return true;
    }
  return false;
}

Result<graph::GraphDesc> compose_frame_graph(const graph::GraphDesc& technique) {
  using namespace graph;
  if (std::optional<Error> e = removed_frame_resource(technique)) return *e;
  GraphBuilder b(technique.name);
  ImportedHandle scene = b.import("scene");
  ImportedHandle camera = b.import("camera");
  b.import("light");
  TextureHandle depth = b.texture("gbuffer_depth", Format::R32F, SizeExpr::screen());
  TextureHandle normal = b.texture("gbuffer_normal", Format::RG16, SizeExpr::screen());
  TextureHandle albedo = b.texture("gbuffer_albedo", Format::RGBA8, SizeExpr::screen());
  TextureHandle zbuffer = b.texture("gbuffer_zbuffer", Format::DEPTH32F, SizeExpr::screen());
  TextureHandle color = b.texture(kColor, Format::RGBA8, SizeExpr::screen());
  b.pass("gbuffer", "gbuffer")
      .read("scene", scene)
      .read("camera", camera)
      .write("zbuffer", zbuffer)
      .write("depth", depth)
      .write("normal", normal)
      .write("albedo", albedo);
  GraphDesc frame = b.build();
  for (PassDecl& p : frame.passes) p.frame = true;

  // Technique resources: identical re-declarations of frame resources are dropped.
  for (const ResourceDecl& r : technique.resources) {
    auto it = std::find_if(frame.resources.begin(), frame.resources.end(),
                           [&](const ResourceDecl& f) { return f.name == r.name; });
    if (it == frame.resources.end()) {
      frame.resources.push_back(r);
    } else if (!same_decl(*it, r)) {
      Error e = make_error("resource '" + r.name +
                           "' is provided by the frame (see docs/writing-a-technique.md) and "
                           "must not be redeclared differently");
      e.file = technique.source_file;
      e.where = r.location;
      return e;
    }
  }
  bool writes_mask = std::any_of(technique.resources.begin(), technique.resources.end(),
                                 [](const ResourceDecl& r) { return r.name == kShadowMask; });
  if (!writes_mask) {
    Error e = make_error("a technique graph must declare and write a screen-size 'shadow_mask' "
                         "texture (R8, R16F or R32F)");
    e.file = technique.source_file;
    return e;
  }
  frame.parameters = technique.parameters;
  frame.exposures = technique.exposures;
  frame.description = technique.description;
  frame.source_file = technique.source_file;
  frame.passes.insert(frame.passes.end(), technique.passes.begin(), technique.passes.end());

  PassDecl lighting;
  lighting.type = "lighting";
  lighting.name = "lighting";
  lighting.frame = true;
  lighting.slots = {{"albedo", "gbuffer_albedo", -1, ""},
                    {"normal", "gbuffer_normal", -1, ""},
                    {"depth", "gbuffer_depth", -1, ""},
                    {"shadow_mask", kShadowMask, -1, ""},
                    {"light", "light", -1, ""},
                    {"color", kColor, -1, ""}};
  frame.passes.push_back(lighting);

  frame.outputs = {kColor, kShadowMask};
  for (const std::string& o : technique.outputs)
    if (std::find(frame.outputs.begin(), frame.outputs.end(), o) == frame.outputs.end())
      frame.outputs.push_back(o);
  (void)color;
  return frame;
}

}  // namespace penumbra::technique
