// Full-resolution shadow mask of pmchss (Sterna 2018, Listing 6) with the penumbra from an
// in-pass blocker search (regular CHSS, 2.1), the penumbra mask (2.2) or the min map (2.3);
// optionally only the checkerboard half of the pixels, packed (section 3).
#include "exec/pass_decl_builder.h"
#include "gl/texture.h"
#include "passes/common/shadow_receiver_decl.h"
#include "passes/sampling/rotation_noise.h"
#include "techniques/pmchss/passes/pmchss_pass_common.h"
#include "techniques/pmchss/passes/pmchss_pass_types.h"

namespace penumbra::pmchss {
namespace {

using graph::Format;

class ShadowMaskPass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    gl::Texture& shadow = ctx.texture("shadow_map");
    gl::Texture& mask = ctx.texture("mask");
    std::string source = ctx.enumeration("source");
    bool checker = ctx.boolean("checkerboard");
    bool searches = source == "search" && ctx.enumeration("penumbra_mapping") != "fixed";
    if (searches)
      if (Status s = check_search_covers_texel(ctx, shadow.width()); !s) return s;
    if (checker != (mask.format() == gl::Format::RG16F))
      return make_error("slot 'mask' must be RG16F screen/2 with checkerboard=true and R16F "
                        "screen otherwise", ErrorKind::internal);
    // The min map is filtered in its own texels: over a point light's six tiles it takes depths of
    // the tile beside each face in the map, not on the sphere (room at 1080p: penumbra RMSE 2.6x
    // pcss's, bands along every face edge); over cascades, depths of the next cascade's tile.
    if (source == "min_depth" && (ctx.frame().shadow.six_faces || ctx.frame().cascades.count > 1))
      return make_error(std::string("variant=min_filter filters the shadow map in its own texels, which mixes ") +
                            (ctx.frame().shadow.six_faces ? "a point light's six faces" : "cascades") +
                            "; use variant=penumbra_mask (the default) or regular");
    const char* source_define = source == "mask" ? "1" : source == "min_depth" ? "2" : "0";
    std::vector<std::pair<std::string, std::string>> defines = {
        {"BLOCKER_SAMPLES", std::to_string(ctx.integer("blocker_samples"))},
        {"FILTER_SAMPLES", std::to_string(ctx.integer("filter_samples"))},
        {"PENUMBRA_SOURCE", source_define},
        mapping_define(ctx)};
    if (checker) defines.push_back({"CHECKER", "1"});
    gl::ShaderProgram& p = ctx.program(
        {.compute = "techniques/pmchss/shaders/shadow_mask.comp.glsl", .defines = defines});
    if (!p.valid()) return *p.last_error();
    if (nearest_.id() == 0) {
      nearest_ = gl::Sampler(gl::Sampler::Filter::nearest, gl::Sampler::Wrap::clamp);
      linear_ = gl::Sampler(gl::Sampler::Filter::linear, gl::Sampler::Wrap::clamp);
      compare_ = gl::Sampler(gl::Sampler::Filter::linear, gl::Sampler::Wrap::clamp, true);
    }
    ctx.bind_sampled(p, "u_depth", "depth");
    ctx.bind_sampled(p, "u_normal", "normal");
    ctx.bind_sampled(p, "u_shadow_map", "shadow_map", nearest_.id());
    ctx.bind_sampled(p, "u_shadow_cmp", "shadow_map", compare_.id());
    if (source == "mask") ctx.bind_sampled(p, "u_penumbra_mask", "penumbra_mask", linear_.id());
    if (source == "min_depth") ctx.bind_sampled(p, "u_min_depth", "min_depth", linear_.id());
    ctx.bind_image(0, "mask", GL_WRITE_ONLY);
    if (Status s = set_pmchss_uniforms(p.program(), ctx); !s) return s;
    passes::set_rotation_noise(p.program(), ctx);
    ctx.dispatch_over(p, mask.width(), mask.height());
    return {};
  }

 private:
  gl::Sampler nearest_, linear_, compare_;
};

}  // namespace

exec::PassType shadow_mask_pass_type() {
  exec::PassDeclBuilder b = passes::shadow_receiver_pass(
      "pmchss_shadow_mask",
      "pmchss shadow mask: 16 Vogel taps of hardware PCF scaled by the penumbra (Sterna 2018, Listing 6)");
  b.sampled("penumbra_mask", {Format::R16F}, false)
      .sampled("min_depth", {Format::R32F}, false)
      .image_out("mask", {Format::R16F, Format::RG16F});
  for (graph::ParamDesc& d : penumbra_params()) b.param(std::move(d));
  return b.param(enum_param("source", "search", {"search", "mask", "min_depth"}, "Where the penumbra comes from"))
      .param(passes::rotation_noise_param())
      .param(int_param("blocker_samples", 16, 4, 64, "", "Blocker search taps (source=search)"))
      .param(int_param("filter_samples", 16, 4, 64, "", "PCF taps of the shadow mask, each a 2x2 hardware comparison (Listing 6: 16)"))
      .param(bool_param("checkerboard", false, "Compute (x + y) even pixels only, packed RG16F"))
      .build<ShadowMaskPass>();
}

}  // namespace penumbra::pmchss
