// Stage: plan memory barriers.
#include "graph/compile_state.h"

namespace penumbra::graph::detail {

namespace {

std::uint32_t barrier_bit(Usage u) {
  switch (u) {
    case Usage::sampled: return barrier_texture_fetch;
    case Usage::image_load:
    case Usage::image_store: return barrier_shader_image_access;
    case Usage::color_attachment:
    case Usage::depth_attachment: return barrier_framebuffer;
    case Usage::storage_buffer: return barrier_storage_buffer;
    case Usage::indirect_dispatch: return barrier_command | barrier_storage_buffer;
    case Usage::imported: return barrier_none;
  }
  return barrier_none;
}

// Image and SSBO writes are not coherent with later reads in GL; attachment writes are.
bool writes_incoherently(Usage u) {
  return u == Usage::image_store || u == Usage::image_load || u == Usage::storage_buffer;
}

}  // namespace

// Before each pass, for every resource it touches whose last writer wrote incoherently
// (image store, SSBO), issue the barrier bit matching THIS pass's usage, once per write.
// Attachment writes followed by sampling need nothing in GL. A persistent resource written
// incoherently starts the frame dirty (last frame's write).
void plan_barriers(CompileState& s) {
  CompiledPlan& plan = s.plan;
  std::vector<char> dirty(plan.physical.size(), 0);
  std::vector<std::uint32_t> issued(plan.physical.size(), 0);
  for (const PlannedPass& p : plan.passes)
    for (const PlannedBinding& b : p.bindings)
      if (b.physical >= 0 && b.write_version >= 0 && writes_incoherently(b.usage) &&
          plan.physical[b.physical].kind == ResourceKind::persistent)
        dirty[b.physical] = 1;
  for (PlannedPass& p : plan.passes) {
    for (const PlannedBinding& b : p.bindings) {
      std::uint32_t bit = barrier_bit(b.usage);
      if (b.physical < 0 || !bit || !dirty[b.physical] || (issued[b.physical] & bit)) continue;
      p.barriers |= bit;
      issued[b.physical] |= bit;
      int v = b.read_version >= 0 ? b.read_version : b.write_version;
      p.barrier_reasons.push_back(b.resource + "@" + std::to_string(v) + ": " +
                                  barrier_bits_to_string(bit));
    }
    for (const PlannedBinding& b : p.bindings) {
      if (b.physical < 0 || b.write_version < 0) continue;
      dirty[b.physical] = writes_incoherently(b.usage);
      issued[b.physical] = 0;
    }
  }
}

}  // namespace penumbra::graph::detail
