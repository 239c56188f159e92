#include "test_support/upload_pass.h"

#include <memory>

#include "exec/pass_decl_builder.h"

namespace penumbra::test {
namespace {

class UploadPass final : public exec::PassImpl {
 public:
  explicit UploadPass(std::shared_ptr<const TextureImage> texels) : texels_(*texels), keep_(std::move(texels)) {}

  Status execute(exec::PassContext& ctx) override {
    gl::Texture& out = ctx.texture("out");
    if (out.width() != texels_.width || out.height() != texels_.height || out.info().channels != texels_.channels) {
      Error e = make_error("the texels are " + std::to_string(texels_.width) + "x" + std::to_string(texels_.height) +
                           " with " + std::to_string(texels_.channels) + " channels, the texture " +
                           std::to_string(out.width()) + "x" + std::to_string(out.height()) + " with " +
                           std::to_string(out.info().channels));
      e.where = "pass '" + ctx.pass().name + "', slot out";
      return e;
    }
    if (gl_rows_.empty()) gl_rows_ = flip_rows(texels_.texels, texels_.width, texels_.height, texels_.channels);
    out.upload(gl_rows_.data());
    return {};
  }

 private:
  const TextureImage& texels_;
  std::shared_ptr<const TextureImage> keep_;  // the one copy the pass type owns
  std::vector<float> gl_rows_;  // bottom to top, as glTextureSubImage2D takes them
};

}  // namespace

exec::PassType upload_pass_type(const std::string& type_name, graph::Format format, TextureImage texels) {
  exec::PassDeclBuilder builder(type_name);
  builder.describe("Test: writes texels chosen by the test into `out`");
  if (format == graph::Format::DEPTH32F)
    builder.depth_out("out");
  else
    builder.color_out("out", {format});
  auto shared = std::make_shared<const TextureImage>(std::move(texels));
  return {builder.decl(), [shared] { return std::make_unique<UploadPass>(shared); }};
}

}  // namespace penumbra::test
