// Property test over ~500 seeded random graphs: physical assignment never lets two versions
// with overlapping lifetimes share a texture, shares only identical descriptors, never shares
// persistent resources, and assigned memory <= naive. With no_reuse, one texture per group.
#include <gtest/gtest.h>

#include <random>

#include "test_registry.h"

namespace penumbra::graph {
namespace {

using namespace testing;

// Random graphs from blur / blur_in_place / penumbra_filter / accumulate passes over a pool
// of textures of a few formats and sizes; reads only what exists, so they always compile.
GraphDesc random_graph(std::mt19937& rng) {
  GraphBuilder b("random");
  auto pick = [&](int n) { return static_cast<int>(rng() % static_cast<unsigned>(n)); };
  auto scene = b.import("scene"), camera = b.import("camera");
  auto depth = b.texture("depth", Format::DEPTH32F, SizeExpr::screen());
  b.pass("depth_prepass", "camera_depth").read("scene", scene).read("camera", camera).write("depth", depth);
  const Format formats[] = {Format::R8, Format::R16F, Format::RGBA16F};
  const SizeExpr sizes[] = {SizeExpr::screen(), SizeExpr::screen(2)};
  struct Tex { TextureHandle h; Format f; int size; bool written; };
  std::vector<Tex> pool;
  int textures = 3 + pick(10);
  for (int i = 0; i < textures; ++i) {
    Format f = formats[pick(3)];
    int s = pick(2);
    pool.push_back({b.texture("t" + std::to_string(i), f, sizes[s]), f, s, false});
  }
  auto history = b.persistent("history", Format::RGBA16F, SizeExpr::screen());
  int passes = 2 + pick(30);
  for (int i = 0; i < passes; ++i) {
    std::string name = "p" + std::to_string(i);
    int kind = pick(4);
    Tex& out = pool[pick(textures)];
    if (kind == 0 && out.size == 0) {  // filter: writes a screen-size mask
      b.pass("penumbra_filter", name).read("shadow_map", depth).read("depth", depth).write("mask", out.h);
      out.written = true;
    } else if (kind == 1 && out.written) {
      b.pass("blur_in_place", name).read_write("image", out.h);
    } else if (kind == 2 && out.written && out.f == Format::RGBA16F && out.size == 0) {
      b.pass("accumulate", name).read("sample", out.h).read_write("history", history);
    } else {
      std::vector<int> sources;
      for (int t = 0; t < textures; ++t)
        if (pool[t].written && pool[t].size == out.size && &pool[t] != &out) sources.push_back(t);
      if (sources.empty()) continue;
      b.pass("blur", name).read("input", pool[sources[pick(static_cast<int>(sources.size()))]].h)
          .write("output", out.h);
      out.written = true;
    }
  }
  for (auto& t : pool)
    if (t.written && pick(3) == 0) b.output(t.h);
  return b.build();
}

struct DescKey {
  ResourceKind kind;
  Format format;
  int w, h;
  bool operator==(const DescKey&) const = default;
};

// True when b is produced in place (read_write) from a: the one legal way to share while alive.
bool in_place_link(const CompiledPlan& plan, const ResourceVersion& a, const ResourceVersion& b) {
  if (b.producer < 0) return false;
  for (const auto& bind : plan.passes[b.producer].bindings)
    if (bind.resource == a.name && bind.read_version == a.version && bind.write_version == b.version)
      return true;
  return false;
}

void check_assignment(const CompiledPlan& plan, const GraphDesc& g) {
  std::uint64_t sum = 0;
  for (const auto& p : plan.physical) sum += p.bytes;
  EXPECT_EQ(sum, plan.memory.assigned_bytes);
  EXPECT_LE(plan.memory.assigned_bytes, plan.memory.naive_bytes);
  auto decl_of = [&](const std::string& name) -> const ResourceDecl& {
    for (const auto& r : g.resources)
      if (r.name == name) return r;
    throw std::runtime_error("no resource " + name);
  };
  for (size_t i = 0; i < plan.versions.size(); ++i) {
    const auto& a = plan.versions[i];
    if (a.physical < 0) {
      EXPECT_EQ(a.kind, ResourceKind::imported);
      continue;
    }
    const PhysicalResource& p = plan.physical.at(a.physical);
    const ResourceDecl& da = decl_of(a.name);
    int w, h;
    da.size.resolve(plan.settings, da.size.divisor, w, h);
    EXPECT_EQ((DescKey{p.kind, p.format, p.width, p.height}), (DescKey{da.kind, da.format, w, h}))
        << a.label() << " on a texture of another descriptor";
    for (size_t j = i + 1; j < plan.versions.size(); ++j) {
      const auto& b = plan.versions[j];
      if (b.physical != a.physical) continue;
      if (a.name == b.name && (da.kind == ResourceKind::persistent)) continue;
      EXPECT_NE(da.kind, ResourceKind::persistent) << a.label() << " shares with " << b.label();
      // An in-place chain lives in one texture; with extended lifetimes all of it overlaps.
      bool same_chain = a.name == b.name &&
                        (plan.options.extended_lifetimes || in_place_link(plan, a, b));
      bool overlap = a.first_use <= b.last_use && b.first_use <= a.last_use;
      if (overlap && !same_chain)
        ADD_FAILURE() << a.label() << " [" << a.first_use << "," << a.last_use << "] and "
                      << b.label() << " [" << b.first_use << "," << b.last_use << "] share #" << a.physical;
    }
  }
}

TEST(GraphAssignmentProperty, RandomGraphsNeverShareOverlappingOrDifferentTextures) {
  std::mt19937 rng(20240611);
  int compiled = 0, reused = 0;
  for (int i = 0; i < 500; ++i) {
    GraphDesc g = random_graph(rng);
    auto plan = compile_graph(g);
    ASSERT_TRUE(plan) << "graph " << i << "\n" << all_messages(plan.errors());
    check_assignment(*plan, g);
    ++compiled;
    if (plan->memory.assigned_bytes < plan->memory.naive_bytes) ++reused;

    CompileOptions no_reuse;
    no_reuse.no_reuse = true;
    auto naive = compile_graph(g, no_reuse);
    ASSERT_TRUE(naive);
    check_assignment(*naive, g);
    EXPECT_EQ(naive->memory.assigned_bytes, naive->memory.naive_bytes);
    // One physical texture per resource version group: a texture holds one resource only.
    for (const auto& p : naive->physical) {
      std::string name = p.holds.at(0).substr(0, p.holds[0].find('@'));
      for (const auto& h : p.holds) EXPECT_EQ(h.substr(0, h.find('@')), name);
    }
    CompileOptions extended;
    extended.extended_lifetimes = true;
    auto wide = compile_graph(g, extended);
    ASSERT_TRUE(wide);
    check_assignment(*wide, g);
  }
  EXPECT_EQ(compiled, 500);
  EXPECT_GT(reused, 50) << "the generator should produce graphs where reuse happens";
}

}  // namespace
}  // namespace penumbra::graph
