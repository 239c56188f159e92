// Penumbra mask pass (Sterna 2018, section 2.2): the blocker search at screen/4 or screen/2 and,
// in the same dispatch, the optional max filter and the 7x7 Gaussian blur of the mask.
#include "exec/pass_decl_builder.h"
#include "gl/texture.h"
#include "techniques/pmchss/passes/pmchss_pass_common.h"
#include "techniques/pmchss/passes/pmchss_pass_types.h"

namespace penumbra::pmchss {
namespace {

using graph::Format;

// TILE of penumbra_mask.comp.glsl (defined only here): mask texels a 32x32 workgroup writes,
// each way, once the 3-texel halo of every filter stage is taken off.
int tile_size(bool blur, bool max_filter) { return 32 - 6 * ((blur ? 1 : 0) + (max_filter ? 1 : 0)); }

class PenumbraMaskPass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    gl::Texture& shadow = ctx.texture("shadow_map");
    if (Status s = check_search_covers_texel(ctx, shadow.width()); !s) return s;
    gl::Texture& mask = ctx.texture("mask");
    bool blocker_depth = ctx.enumeration("output") == "blocker_depth";
    bool blur = ctx.boolean("blur"), max_filter = ctx.boolean("max_filter");
    int tile = tile_size(blur, max_filter);
    gl::ShaderProgram& p = ctx.program(
        {.compute = "techniques/pmchss/shaders/penumbra_mask.comp.glsl",
         .defines = {{"BLOCKER_SAMPLES", std::to_string(ctx.integer("blocker_samples"))},
                     {"FILTER_SAMPLES", "16"},
                     mapping_define(ctx),
                     {"BLUR", blur ? "1" : "0"},
                     {"MAX_FILTER", max_filter ? "1" : "0"},
                     {"TILE", std::to_string(tile)},
                     {blocker_depth ? "OUTPUT_BLOCKER_DEPTH" : "OUTPUT_PENUMBRA", "1"}}});
    if (!p.valid()) return *p.last_error();
    if (nearest_.id() == 0) nearest_ = gl::Sampler(gl::Sampler::Filter::nearest, gl::Sampler::Wrap::clamp);
    ctx.bind_sampled(p, "u_depth", "depth");
    ctx.bind_sampled(p, "u_normal", "normal");
    ctx.bind_sampled(p, "u_shadow_map", "shadow_map", nearest_.id());
    ctx.bind_image(0, "mask", GL_WRITE_ONLY);
    if (Status s = set_pmchss_uniforms(p.program(), ctx); !s) return s;
    p.program().set("u_default_one", ctx.boolean("default_one") ? 1 : 0);
    p.program().set("u_blur_sigma", ctx.real("blur_sigma"));
    ctx.dispatch_tiles(p, mask.width(), mask.height(), tile);
    return {};
  }

 private:
  gl::Sampler nearest_;
};

}  // namespace

exec::PassType penumbra_mask_pass_type() {
  exec::PassDeclBuilder b("pmchss_penumbra_mask");
  b.describe("pmchss penumbra mask: reduced-resolution blocker search, then max filter and "
             "Gaussian blur in the same dispatch (Sterna 2018, 2.2)")
      .sampled("depth", {Format::R32F})
      .sampled("normal", {Format::RG16})
      .sampled("shadow_map", {Format::DEPTH32F})
      .imported("light", false)
      .image_out("mask", {Format::R16F});
  for (graph::ParamDesc& d : penumbra_params()) b.param(std::move(d));
  return b.param(int_param("blocker_samples", 32, 4, 64, "",
                           "Blocker search taps (the paper uses 32, 16 shows small artifacts in the mask)"))
      .param(bool_param("default_one", false,
                        "Write 1 instead of 0 where no blocker is found (section 2.2; then kernel scaling is unnecessary)"))
      .param(bool_param("blur", false, "Separable 7x7 Gaussian blur of the penumbra mask against swimming bubbles (section 2.2)"))
      .param(real_param("blur_sigma", 3.0, 0.5, 8.0, "mask texels", "Penumbra mask blur sigma (section 2.2: 3)"))
      .param(bool_param("max_filter", false,
                        "7x7 max filter before the blur; the paper recommends against it (loses penumbra information, "
                        "subtle artifacts)"))
      .param(enum_param("output", "penumbra", {"penumbra", "blocker_depth"},
                        "What to write: penumbra, or mean blocker window depth (debug)"))
      .build<PenumbraMaskPass>();
}

}  // namespace penumbra::pmchss
