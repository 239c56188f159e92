#include "exec/executor.h"

#include <glad/gl.h>

#include <stdexcept>

#include "exec/frame_uniforms.h"
#include "gl/context.h"

namespace penumbra::exec {

GLbitfield gl_barrier_bits(std::uint32_t bits) {
  GLbitfield gl = 0;
  if (bits & graph::barrier_texture_fetch) gl |= GL_TEXTURE_FETCH_BARRIER_BIT;
  if (bits & graph::barrier_shader_image_access) gl |= GL_SHADER_IMAGE_ACCESS_BARRIER_BIT;
  if (bits & graph::barrier_framebuffer) gl |= GL_FRAMEBUFFER_BARRIER_BIT;
  if (bits & graph::barrier_storage_buffer) gl |= GL_SHADER_STORAGE_BARRIER_BIT;
  if (bits & graph::barrier_command) gl |= GL_COMMAND_BARRIER_BIT;
  if (bits & graph::barrier_texture_update) gl |= GL_TEXTURE_UPDATE_BARRIER_BIT;
  return gl;
}

Status Executor::set_plan(graph::CompiledPlan plan) {
  std::vector<std::unique_ptr<PassImpl>> impls;
  for (const graph::PlannedPass& p : plan.passes) {
    const PassType* type = library_.find(p.type);
    if (!type || !type->create) {
      Error e = make_error("no GL implementation registered for pass type '" + p.type + "'",
                           ErrorKind::internal);
      e.where = "pass '" + p.name + "'";
      return e;
    }
    impls.push_back(type->create());
  }
  pool_.begin_generation();
  std::vector<gl::Texture*> textures(plan.physical.size(), nullptr);
  std::vector<gl::Buffer*> buffers(plan.physical.size(), nullptr);
  for (const graph::PhysicalResource& r : plan.physical) {
    if (r.kind == graph::ResourceKind::buffer) {
      buffers[r.id] = pool_.acquire_buffer(r.bytes);
    } else if (r.kind == graph::ResourceKind::persistent) {
      std::string name = r.holds.empty() ? "persistent#" + std::to_string(r.id) : r.holds.front();
      name = name.substr(0, name.find('@'));
      textures[r.id] = pool_.persistent(name, r.format, r.width, r.height);
    } else {
      textures[r.id] = pool_.acquire(r.format, r.width, r.height);
    }
  }
  pool_.end_generation();
  plan_ = std::move(plan);
  impls_ = std::move(impls);
  textures_ = std::move(textures);
  buffers_ = std::move(buffers);
  std::vector<std::string> names;
  for (const graph::PlannedPass& p : plan_.passes) names.push_back(p.name);
  // The mode stays what the last frame used (a fresh executor decides on its first execute, when
  // GL info is known): a label drawn between a recompile and the next frame must not change.
  timer_.reset(names, timer_.mode());
  has_plan_ = true;
  progress_.reset();  // the new plan's passes start their work afresh
  return {};
}

Status Executor::execute(const graph::ParameterSet& params, const FrameInputs& frame) {
  if (!has_plan_) return make_error("executor has no plan", ErrorKind::internal);
  if (frames_ == 0 || timer_.timings().size() != plan_.passes.size() ||
      (timer_.mode() == TimingMode::off) == options_.timing_enabled) {
    std::vector<std::string> names;
    for (const graph::PlannedPass& p : plan_.passes) names.push_back(p.name);
    const bool software = gl::current_context_is_software();
    TimingMode mode = !options_.timing_enabled ? TimingMode::off
                      : options_.force_timing_mode ? *options_.force_timing_mode
                      : software                   ? TimingMode::cpu_finish
                                                   : TimingMode::gpu_timestamps;
    if (mode != timer_.mode() || timer_.timings().size() != names.size()) timer_.reset(names, mode);
  }
  timer_.begin_frame(frames_);
  auto texture_of = [this](int id) -> gl::Texture* {
    return id >= 0 && id < static_cast<int>(textures_.size()) ? textures_[id] : nullptr;
  };
  auto buffer_of = [this](int id) -> gl::Buffer* {
    return id >= 0 && id < static_cast<int>(buffers_.size()) ? buffers_[id] : nullptr;
  };
  bind_frame_uniforms(frame_uniforms_, frame);
  Status result;
  for (size_t i = 0; i < plan_.passes.size(); ++i) {
    const graph::PlannedPass& pass = plan_.passes[i];
    if (pass.barriers) glMemoryBarrier(gl_barrier_bits(pass.barriers));
    PassContext ctx(pass, params, frame, shaders_, texture_of, buffer_of, &progress_);
    timer_.begin_pass(i);
    Status s;
    glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, pass.name.c_str());
    try {
      s = impls_[i]->execute(ctx);
    } catch (const std::exception& ex) {
      s = make_error(ex.what(), ErrorKind::internal);
    }
    if (s && ctx.binding_error()) s = *ctx.binding_error();
    over_tiles_.resize(plan_.passes.size());
    over_tiles_[i] = ctx.dispatched_over_tiles();
    glPopDebugGroup();
    timer_.end_pass(i);
    // Leave no state behind that the next pass would inherit by accident.
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glUseProgram(0);
    if (options_.immediate) {
      glFinish();
      if (GLenum err = glGetError(); err != GL_NO_ERROR && s) {
        char code[16];
        std::snprintf(code, sizeof code, "0x%04X", err);
        s = make_error(std::string("GL error ") + code + " after the pass (immediate mode)", ErrorKind::internal);
      }
    }
    if (!s) {
      Error e = s.error();
      e.where = "pass '" + pass.name + "' (" + pass.type + ")" + (e.where.empty() ? "" : ": " + e.where);
      result = e;
      timer_.abort_frame();
      break;
    }
  }
  timer_.end_frame();
  ++frames_;
  pool_.end_frame();
  return result;
}

gl::Texture* Executor::physical_texture(int id) const {
  return id >= 0 && id < static_cast<int>(textures_.size()) ? textures_[id] : nullptr;
}

gl::Buffer* Executor::physical_buffer(int id) const {
  return id >= 0 && id < static_cast<int>(buffers_.size()) ? buffers_[id] : nullptr;
}

gl::Texture* Executor::resource(const std::string& name) const {
  return physical_texture(plan_.physical_for(name));
}

std::vector<std::string> Executor::resource_names() const {
  std::vector<std::string> names;
  for (const auto& [name, id] : plan_.physical_of)
    if (physical_texture(id)) names.push_back(name);
  return names;
}

}  // namespace penumbra::exec
