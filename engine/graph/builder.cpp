#include "graph/builder.h"

namespace penumbra::graph {

PassBuilder& PassBuilder::bind(const std::string& slot, int resource, int version) {
  GraphDesc& g = owner_->desc_;
  SlotBinding b;
  b.slot = slot;
  // An invalid handle binds a name no resource has: the compiler reports it as unknown.
  b.resource = resource >= 0 && resource < static_cast<int>(g.resources.size())
                   ? g.resources[resource].name
                   : "<invalid handle>";
  b.version = version;
  g.passes[pass_].slots.push_back(std::move(b));
  last_ = Last::slot;
  return *this;
}

PassBuilder& PassBuilder::when(const std::string& condition) {
  PassDecl& p = owner_->desc_.passes[pass_];
  if (last_ == Last::slot && !p.slots.empty()) p.slots.back().when = condition;
  if (last_ == Last::param && !p.params.empty()) p.params.back().when = condition;
  return *this;
}

PassBuilder& PassBuilder::read(const std::string& s, TextureHandle h) { return bind(s, h.index, h.version); }
PassBuilder& PassBuilder::read(const std::string& s, BufferHandle h) { return bind(s, h.index, h.version); }
PassBuilder& PassBuilder::read(const std::string& s, ImportedHandle h) { return bind(s, h.index, -1); }
PassBuilder& PassBuilder::write(const std::string& s, TextureHandle h) { return bind(s, h.index, h.version); }
PassBuilder& PassBuilder::write(const std::string& s, BufferHandle h) { return bind(s, h.index, h.version); }
PassBuilder& PassBuilder::write(const std::string& s, ImportedHandle h) { return bind(s, h.index, -1); }
PassBuilder& PassBuilder::read_write(const std::string& s, TextureHandle h) { return bind(s, h.index, h.version); }
PassBuilder& PassBuilder::read_write(const std::string& s, BufferHandle h) { return bind(s, h.index, h.version); }

PassBuilder& PassBuilder::param(const std::string& name, ParamValue value) {
  ParamBinding p;
  p.name = name;
  if (auto* s = std::get_if<std::string>(&value); s && s->size() > 1 && (*s)[0] == '$')
    p.reference = s->substr(1);
  else
    p.constant = std::move(value);
  owner_->desc_.passes[pass_].params.push_back(std::move(p));
  last_ = Last::param;
  return *this;
}

PassBuilder& PassBuilder::param(const std::string& name, const char* value_or_reference) {
  return param(name, ParamValue{std::string(value_or_reference)});
}

PassBuilder& PassBuilder::repeat(int count) {
  owner_->desc_.passes[pass_].repeat = count;
  owner_->desc_.passes[pass_].repeat_reference.clear();
  return *this;
}

PassBuilder& PassBuilder::repeat(const std::string& reference) {
  owner_->desc_.passes[pass_].repeat_reference =
      !reference.empty() && reference[0] == '$' ? reference.substr(1) : reference;
  return *this;
}

PassBuilder& PassBuilder::enabled(const std::string& condition) {
  owner_->desc_.passes[pass_].enabled = condition;
  return *this;
}

PassBuilder& PassBuilder::side_effect(bool on) {
  owner_->desc_.passes[pass_].side_effect = on;
  return *this;
}

GraphBuilder::GraphBuilder(std::string name) { desc_.name = std::move(name); }

void GraphBuilder::parameter(ParamDesc desc) { desc_.parameters.push_back(std::move(desc)); }

int GraphBuilder::add_resource(ResourceDecl decl) {
  desc_.resources.push_back(std::move(decl));
  return static_cast<int>(desc_.resources.size()) - 1;
}

TextureHandle GraphBuilder::texture(const std::string& name, Format format, SizeExpr size) {
  return {add_resource({name, ResourceKind::texture, format, std::move(size), 0, ""}), -1};
}

TextureHandle GraphBuilder::persistent(const std::string& name, Format format, SizeExpr size) {
  return {add_resource({name, ResourceKind::persistent, format, std::move(size), 0, ""}), -1};
}

BufferHandle GraphBuilder::buffer(const std::string& name, std::uint64_t bytes) {
  return {add_resource({name, ResourceKind::buffer, Format::R8, {}, bytes, ""}), -1};
}

BufferHandle GraphBuilder::tile_list(const std::string& name, SizeExpr tiles) {
  ResourceDecl r{name, ResourceKind::buffer, Format::R8, std::move(tiles), 0, ""};
  r.tile_list = true;
  return {add_resource(std::move(r)), -1};
}

TextureHandle GraphBuilder::tile_texture(const std::string& name, Format format, SizeExpr tiles) {
  ResourceDecl r{name, ResourceKind::texture, format, std::move(tiles), 0, ""};
  r.per_tile = true;
  return {add_resource(std::move(r)), -1};
}

ImportedHandle GraphBuilder::import(const std::string& name) {
  return {add_resource({name, ResourceKind::imported, Format::R8, {}, 0, ""})};
}

PassBuilder GraphBuilder::pass(const std::string& type, const std::string& name) {
  PassDecl p;
  p.type = type;
  p.name = name;
  desc_.passes.push_back(std::move(p));
  return PassBuilder(*this, static_cast<int>(desc_.passes.size()) - 1);
}

void GraphBuilder::output(TextureHandle h) {
  if (h.index >= 0 && h.index < static_cast<int>(desc_.resources.size()))
    desc_.outputs.push_back(desc_.resources[h.index].name);
}
void GraphBuilder::output(BufferHandle h) { output(TextureHandle{h.index, -1}); }
void GraphBuilder::output(const std::string& name) { desc_.outputs.push_back(name); }

}  // namespace penumbra::graph
