#include "sandbox/display.h"

#include "util/row_order.h"

#include <algorithm>

#include "exec/frame_uniforms.h"

namespace penumbra::sandbox {

namespace {
const gl::ShaderSources kPresent{.vertex = "sandbox/shaders/display.vert.glsl",
                                 .fragment = "sandbox/shaders/display.frag.glsl"};
const gl::ShaderSources kDensity{.vertex = "sandbox/shaders/display.vert.glsl",
                                 .fragment = "sandbox/shaders/texel_density.frag.glsl"};
const gl::ShaderSources kDifference{.compute = "sandbox/shaders/mask_difference.comp.glsl"};

Status program_status(const gl::ShaderProgram& p) {
  if (p.valid()) return {};
  if (p.last_error()) return *p.last_error();
  return make_error("display program failed to build", ErrorKind::internal);
}
}  // namespace

const char* map_name(ViewerSettings::Map map) { return kColourMapNames[static_cast<int>(map)]; }

Status DisplayPass::resize(int width, int height) {
  if (target_ && target_.width() == width && target_.height() == height) return {};
  if (!vao_) {
    GLuint vao = 0;
    glCreateVertexArrays(1, &vao);
    vao_ = gl::GlHandle<gl::delete_vertex_array>(vao);
    nearest_ = gl::Sampler(gl::Sampler::Filter::nearest, gl::Sampler::Wrap::clamp);
  }
  target_ = gl::Texture(gl::Format::RGBA8, width, height);
  target_.set_label("sandbox_presentation");
  difference_ = gl::Texture(gl::Format::RG16F, width, height);
  difference_.set_label("sandbox_mask_difference");
  framebuffer_ = std::make_unique<gl::Framebuffer>();
  framebuffer_->attach_color(0, target_);
  return framebuffer_->finish();
}

void DisplayPass::show_refused() const {
  if (!framebuffer_) return;
  glClearNamedFramebufferfv(framebuffer_->id(), GL_COLOR, 0, kRefusedColor);
}

void DisplayPass::begin() const {
  framebuffer_->bind();
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_CULL_FACE);
  glClearColor(0.12f, 0.12f, 0.13f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
}

Status DisplayPass::draw(const Layer& layer) {
  if (!layer.texture) return make_error("display: no texture to draw", ErrorKind::internal);
  gl::ShaderProgram& p = shaders_.get(kPresent);
  if (Status s = program_status(p); !s) return s;
  const gl::Program& prog = p.program();
  framebuffer_->bind();
  glViewport(layer.viewport.x, layer.viewport.y, layer.viewport.z, layer.viewport.w);
  glUseProgram(p.id());
  glBindTextureUnit(0, layer.texture->id());
  glBindSampler(0, nearest_.id());
  prog.set("src", 0);
  prog.set("uv_rect", layer.uv_rect);
  prog.set("map_mode", static_cast<int>(layer.map));
  prog.set("channel", std::min(layer.channel, layer.texture->info().channels - 1));
  prog.set("value_range", layer.range);
  prog.set("channel_mask", glm::vec4(layer.channel_mask & 1u, (layer.channel_mask >> 1) & 1u, (layer.channel_mask >> 2) & 1u,
                                     (layer.channel_mask >> 3) & 1u));
  prog.set("linearize_depth", layer.linearize_depth ? 1 : 0);
  prog.set("near_far", layer.near_far);
  prog.set("coverage_in_g", layer.coverage_in_g ? 1 : 0);
  glBindVertexArray(vao_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  glBindSampler(0, 0);
  return {};
}

Status DisplayPass::texel_density(const gl::Texture& depth, const scene::Camera& camera,
                                  const glm::mat4& light_view_proj, int shadow_size, const glm::vec4& uv_rect,
                                  float zoom) {
  gl::ShaderProgram& p = shaders_.get(kDensity);
  if (Status s = program_status(p); !s) return s;
  const gl::Program& prog = p.program();
  framebuffer_->bind();
  glViewport(0, 0, target_.width(), target_.height());
  glUseProgram(p.id());
  exec::FrameInputs frame;
  frame.camera = camera;
  frame.screen_w = depth.width();
  frame.screen_h = depth.height();
  exec::bind_frame_uniforms(frame_uniforms_, frame);
  glBindTextureUnit(0, depth.id());
  glBindSampler(0, nearest_.id());
  prog.set("depth", 0);
  prog.set("uv_rect", uv_rect);
  prog.set("light_view_proj", light_view_proj);
  prog.set("shadow_size", static_cast<float>(shadow_size));
  prog.set("zoom", zoom);
  glBindVertexArray(vao_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  glBindSampler(0, 0);
  return {};
}

Status DisplayPass::difference(const gl::Texture& a, const gl::Texture& b, const gl::Texture& depth) {
  gl::ShaderProgram& p = shaders_.get(kDifference);
  if (Status s = program_status(p); !s) return s;
  const gl::Program& prog = p.program();
  glUseProgram(p.id());
  const gl::Texture* inputs[3] = {&a, &b, &depth};
  const char* names[3] = {"mask_a", "mask_b", "depth"};
  for (int i = 0; i < 3; ++i) {
    glBindTextureUnit(i, inputs[i]->id());
    glBindSampler(i, nearest_.id());
    prog.set(names[i], i);
  }
  glBindImageTexture(0, difference_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RG16F);
  glm::ivec3 local = prog.local_size();
  glDispatchCompute((difference_.width() + local.x - 1) / local.x,
                    (difference_.height() + local.y - 1) / local.y, 1);
  // The display samples the result next.
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
  for (int i = 0; i < 3; ++i) glBindSampler(i, 0);
  return {};
}

Status DisplayPass::upload_picture(const metrics::RgbaImage& image, unsigned version) {
  if (image.width != target_.width() || image.height != target_.height())
    return make_error("a picture of " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                          " for a frame of " + std::to_string(target_.width()) + "x" + std::to_string(target_.height()),
                      ErrorKind::internal);
  if (!picture_ || picture_.width() != image.width || picture_.height() != image.height) {
    picture_ = gl::Texture(gl::Format::RGBA8, image.width, image.height);
    picture_.set_label("sandbox_picture");
  }
  picture_.upload_bytes(rows_flipped(image.pixels, static_cast<size_t>(image.width) * 4, image.height).data());
  picture_version_ = version;
  return {};
}

}  // namespace penumbra::sandbox
