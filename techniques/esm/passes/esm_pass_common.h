#pragma once
// What the esm passes share: the frame's views for a map of a given size, their uniforms
// (shaders/esm_views.glsl), and the slot the silhouette quads blend into.
#include "exec/pass.h"
#include "techniques/esm/passes/esm_views.h"

namespace penumbra::esm {

// The views of this frame's light for an extended map `map_size` texels square.
Result<EsmViews> frame_views(const exec::PassContext& ctx, int map_size);

// Sets every uniform of shaders/esm_views.glsl.
void set_view_uniforms(const gl::Program& program, const EsmViews& views);

// A colour attachment read and written in place (blending): version n in, n + 1 out.
graph::SlotDecl blended_attachment(std::string name, graph::Format format);

}  // namespace penumbra::esm
