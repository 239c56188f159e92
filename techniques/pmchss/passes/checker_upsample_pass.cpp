// Checkerboard upsample (Sterna 2018, section 3): unpack the computed half of the pixels and
// fill the others from their four neighbours weighted by 1 / (eps + |delta linear depth|).
#include "gl/texture.h"
#include "techniques/pmchss/passes/pmchss_pass_common.h"
#include "techniques/pmchss/passes/pmchss_pass_types.h"

namespace penumbra::pmchss {
namespace {

using graph::Access;
using graph::Format;
using graph::SlotKind;
using graph::Usage;

class CheckerUpsamplePass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    gl::ShaderProgram& p = ctx.program({.compute = "techniques/pmchss/shaders/checker_upsample.comp.glsl"});
    if (!p.valid()) return *p.last_error();
    ctx.bind_sampled(p, "u_checker", "checker");
    ctx.bind_sampled(p, "u_position", "position");
    ctx.bind_image(0, "mask", GL_WRITE_ONLY);
    p.program().set("u_depth_epsilon", ctx.real("depth_epsilon"));
    gl::Texture& mask = ctx.texture("mask");
    ctx.dispatch_over(p, mask.width(), mask.height());
    return {};
  }
};

}  // namespace

exec::PassType checker_upsample_pass_type() {
  graph::PassTypeDecl d;
  d.name = "pmchss_checker_upsample";
  d.description = "Checkerboard shadow mask -> full resolution, depth-aware (Sterna 2018, 3)";
  d.slots = {
      {"checker", Access::read, SlotKind::texture, {Format::RG16F}, Usage::sampled, true},
      {"position", Access::read, SlotKind::texture, {Format::RGBA32F}, Usage::sampled, true},
      {"mask", Access::write, SlotKind::texture, {Format::R16F}, Usage::image_store, true},
  };
  d.same_size_groups = {{"position", "mask"}};
  d.params = {real_param("depth_epsilon", 0.001, 1e-6, 10.0, "world units",
                         "eps of the neighbour weight 1 / (eps + |delta depth|)")};
  return {d, [] { return std::make_unique<CheckerUpsamplePass>(); }};
}

}  // namespace penumbra::pmchss
