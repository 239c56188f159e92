#include "test_passes.h"

#include "gl/framebuffer.h"

namespace penumbra::test {
namespace {

using graph::Access;
using graph::Format;
using graph::ParamDesc;
using graph::ParamType;
using graph::SlotKind;
using graph::Usage;

ParamDesc real_param(const char* name, double def) {
  ParamDesc d{.name = name, .type = ParamType::real, .default_value = def, .min = -100.0, .max = 100.0};
  d.description = "test value";
  return d;
}

class FillPass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    ++execution_counts()[ctx.pass().name];
    gl::ShaderProgram& p = ctx.program({.vertex = "engine/gl/shaders/fullscreen.vert.glsl",
                                        .fragment = "tests/exec/shaders/fill.frag.glsl"});
    if (!p.valid()) return *p.last_error();
    gl::Framebuffer fb;
    fb.attach_color(0, ctx.texture("out"));
    if (Status s = fb.finish(); !s) return s;
    fb.bind();
    p.program().set("u_value", ctx.real("value"));
    glUseProgram(p.id());
    GLuint vao = 0;
    glCreateVertexArrays(1, &vao);
    glBindVertexArray(vao);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glDeleteVertexArrays(1, &vao);
    return {};
  }
};

class AddPass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    ++execution_counts()[ctx.pass().name];
    gl::ShaderProgram& p = ctx.program({.compute = "tests/exec/shaders/add.comp.glsl"});
    if (!p.valid()) return *p.last_error();
    ctx.bind_sampled(p, "u_src", "in");
    ctx.bind_image(0, "out", GL_WRITE_ONLY);
    p.program().set("u_amount", ctx.real("amount"));
    ctx.dispatch_over(p, ctx.texture("out").width(), ctx.texture("out").height());
    return {};
  }
};

class ScalePass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    ++execution_counts()[ctx.pass().name];
    gl::ShaderProgram& p = ctx.program({.compute = "tests/exec/shaders/scale.comp.glsl"});
    if (!p.valid()) return *p.last_error();
    ctx.bind_image(0, "img", GL_READ_WRITE);
    p.program().set("u_factor", ctx.real("factor"));
    ctx.dispatch_over(p, ctx.texture("img").width(), ctx.texture("img").height());
    return {};
  }
};

}  // namespace

std::map<std::string, int>& execution_counts() {
  static std::map<std::string, int> counts;
  return counts;
}

void register_test_passes(exec::PassLibrary& library) {
  graph::PassTypeDecl fill{.name = "fill"};
  fill.slots = {{"out", Access::write, SlotKind::texture, {Format::R32F}, Usage::color_attachment, true}};
  fill.params = {real_param("value", 1.0)};
  library.add({fill, [] { return std::make_unique<FillPass>(); }});

  graph::PassTypeDecl add{.name = "add"};
  add.slots = {{"in", Access::read, SlotKind::texture, {Format::R32F}, Usage::sampled, true},
               {"out", Access::write, SlotKind::texture, {Format::R32F}, Usage::image_store, true}};
  add.params = {real_param("amount", 1.0)};
  add.same_size_groups = {{"in", "out"}};
  library.add({add, [] { return std::make_unique<AddPass>(); }});

  graph::PassTypeDecl scale{.name = "scale"};
  scale.slots = {{"img", Access::read_write, SlotKind::texture, {Format::R32F}, Usage::image_store, true}};
  scale.params = {real_param("factor", 2.0)};
  library.add({scale, [] { return std::make_unique<ScalePass>(); }});
}

}  // namespace penumbra::test
