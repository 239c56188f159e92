#include "exec/pass.h"

#include <algorithm>
#include <stdexcept>

#include "exec/shader_cache.h"

namespace penumbra::exec {

const graph::PlannedBinding* PassContext::find(std::string_view slot) const {
  for (const graph::PlannedBinding& b : pass_.bindings)
    if (b.slot == slot) return &b;
  return nullptr;
}

bool PassContext::bound(std::string_view slot) const { return find(slot) != nullptr; }

gl::Texture& PassContext::texture(std::string_view slot) const {
  const graph::PlannedBinding* b = find(slot);
  gl::Texture* t = b && b->physical >= 0 ? textures_(b->physical) : nullptr;
  if (!t)
    throw std::logic_error("pass '" + pass_.name + "': slot '" + std::string(slot) +
                           "' has no texture bound");
  return *t;
}

gl::Buffer& PassContext::buffer(std::string_view slot) const {
  const graph::PlannedBinding* b = find(slot);
  gl::Buffer* buf = b && b->physical >= 0 ? buffers_(b->physical) : nullptr;
  if (!buf)
    throw std::logic_error("pass '" + pass_.name + "': slot '" + std::string(slot) +
                           "' has no buffer bound");
  return *buf;
}

const graph::ParamValue& PassContext::value(std::string_view name) const {
  for (const graph::PlannedParam& p : pass_.params) {
    if (p.name != name) continue;
    if (!p.reference.empty())
      if (const graph::ParamValue* live = params_.get(p.reference)) return *live;
    return p.value;
  }
  throw std::logic_error("pass '" + pass_.name + "' has no parameter '" + std::string(name) + "'");
}

bool PassContext::boolean(std::string_view name) const {
  const auto& v = value(name);
  if (const bool* b = std::get_if<bool>(&v)) return *b;
  if (const int* i = std::get_if<int>(&v)) return *i != 0;
  return false;
}

int PassContext::integer(std::string_view name) const {
  const auto& v = value(name);
  if (const int* i = std::get_if<int>(&v)) return *i;
  if (const double* d = std::get_if<double>(&v)) return static_cast<int>(*d);
  if (const bool* b = std::get_if<bool>(&v)) return *b ? 1 : 0;
  return 0;
}

float PassContext::real(std::string_view name) const {
  const auto& v = value(name);
  if (const double* d = std::get_if<double>(&v)) return static_cast<float>(*d);
  if (const int* i = std::get_if<int>(&v)) return static_cast<float>(*i);
  return 0.0f;
}

std::string PassContext::enumeration(std::string_view name) const {
  const auto& v = value(name);
  if (const std::string* s = std::get_if<std::string>(&v)) return *s;
  return {};
}

gl::ShaderProgram& PassContext::program(const gl::ShaderSources& sources) {
  const bool defined = std::ranges::any_of(sources.defines, [](const auto& d) { return d.first == "SIX_FACES"; });
  const bool six_faces = frame().shadow.six_faces && !defined, cascades = frame().cascades.count > 1;
  if (!six_faces && !cascades) return shaders_.get(sources);
  gl::ShaderSources variant = sources;  // passes/common/shadow_common.glsl's variants
  if (six_faces) variant.defines.push_back({"SIX_FACES", "1"});
  if (cascades) variant.defines.push_back({"CASCADES", std::to_string(frame().cascades.count)});
  return shaders_.get(variant);
}

void PassContext::bind_sampled(const gl::ShaderProgram& p, const char* uniform, std::string_view slot,
                               GLuint sampler) {
  GLuint unit = next_unit_++;
  glBindTextureUnit(unit, texture(slot).id());
  glBindSampler(unit, sampler);
  p.program().set(uniform, static_cast<int>(unit));
}

void PassContext::bind_image(GLuint unit, std::string_view slot, GLenum access, int level) const {
  const gl::Texture& t = texture(slot);
  glBindImageTexture(unit, t.id(), level, GL_FALSE, 0, access, t.info().internal_format);
  std::erase_if(images_, [&](const BoundImage& b) { return b.unit == unit; });
  images_.push_back({unit, std::string(slot), t.format(), graph::image_format_qualifier(t.format())});
}

void PassContext::bind_image_bits(GLuint unit, std::string_view slot, GLenum access) const {
  const gl::Texture& t = texture(slot);
  std::erase_if(images_, [&](const BoundImage& b) { return b.unit == unit; });
  if (t.format() != graph::Format::R32F) {
    binding_error_ = make_error("slot '" + std::string(slot) + "' is bound as r32ui for atomics, which needs an R32F "
                                "texture; it holds a " + graph::format_name(t.format()) + " texture");
    return;
  }
  // Image unit formats need only match the texture's in size (GL 4.5, section 8.26).
  glBindImageTexture(unit, t.id(), 0, GL_FALSE, 0, access, GL_R32UI);
  images_.push_back({unit, std::string(slot), t.format(), "r32ui"});
}

bool PassContext::images_match(const gl::ShaderProgram& p) const {
  const std::vector<gl::ImageDeclaration>& declarations = p.program().images();
  for (const BoundImage& bound : images_) {
    const std::string_view want = bound.qualifier;
    const auto at_unit = [&](const gl::ImageDeclaration& d) { return d.binding == bound.unit; };
    const bool any = std::ranges::any_of(declarations, at_unit);
    if (!any || std::ranges::any_of(declarations, [&](const gl::ImageDeclaration& d) {
          return at_unit(d) && d.qualifier == want;
        }))
      continue;
    std::string declared;  // the message is built only for a mismatch: this runs every dispatch
    for (const gl::ImageDeclaration& d : declarations)
      if (at_unit(d)) declared += (declared.empty() ? "" : " or ") + d.qualifier + " (" + d.name + ")";
    const graph::PlannedBinding* b = find(bound.slot);
    binding_error_ = make_error("image unit " + std::to_string(bound.unit) + " is declared " + declared +
                                " in the shader, but slot '" + bound.slot + "' holds '" +
                                (b ? b->resource : std::string("?")) + "', a " + graph::format_name(bound.format) +
                                " texture (qualifier " + std::string(want) + ")");
    return false;
  }
  return true;
}

void PassContext::dispatch_over(const gl::ShaderProgram& p, int width, int height) const {
  if (!images_match(p)) return;
  glm::ivec3 local = p.program().local_size();
  GLuint gx = static_cast<GLuint>((width + local.x - 1) / std::max(local.x, 1));
  GLuint gy = static_cast<GLuint>((height + local.y - 1) / std::max(local.y, 1));
  glUseProgram(p.id());
  glDispatchCompute(gx, gy, 1);
}

void PassContext::dispatch_tiles(const gl::ShaderProgram& p, int width, int height, int tile) const {
  if (!images_match(p)) return;
  tile = std::max(tile, 1);
  glUseProgram(p.id());
  glDispatchCompute(static_cast<GLuint>((width + tile - 1) / tile), static_cast<GLuint>((height + tile - 1) / tile), 1);
}

void PassContext::reset_tile_list(std::string_view slot) const {
  gl::Buffer& list = buffer(slot);
  glNamedBufferSubData(list.id(), 0, sizeof graph::kEmptyTileListHeader, graph::kEmptyTileListHeader);
}

void PassContext::bind_tile_list(GLuint binding, std::string_view slot) const {
  buffer(slot).bind_base(GL_SHADER_STORAGE_BUFFER, binding);
}

void PassContext::dispatch_over_tiles(const gl::ShaderProgram& p, std::string_view slot) const {
  if (!images_match(p)) return;
  glUseProgram(p.id());
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, buffer(slot).id());
  glDispatchComputeIndirect(0);
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
  dispatched_over_tiles_ = true;
}

void PassContext::dispatch_indirect(const gl::ShaderProgram& p, const gl::Buffer& command, GLintptr offset) const {
  if (binding_error_ || !images_match(p)) return;
  glUseProgram(p.id());
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, command.id());
  glDispatchComputeIndirect(offset);
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
}

void PassLibrary::add(PassType type) {
  declarations_.add(type.decl);
  std::string name = type.decl.name;
  types_[name] = std::move(type);
}

const PassType* PassLibrary::find(std::string_view name) const {
  auto it = types_.find(name);
  return it == types_.end() ? nullptr : &it->second;
}

}  // namespace penumbra::exec
