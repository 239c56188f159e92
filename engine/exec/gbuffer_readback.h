#pragma once
// The frame contract read back on the CPU (the reference ray tracer, metrics, tests): world
// positions rebuilt from `gbuffer_depth` and normals decoded from `gbuffer_normal`, the same
// arithmetic as passes/gbuffer/gbuffer_read.glsl (tests/gl/gbuffer_contract_test.cpp checks the
// two against each other and against rasterised positions). Rows in GL order (bottom to top),
// like gl::Texture::read().
#include <vector>

#include <glm/glm.hpp>

#include "gl/texture.h"
#include "scene/camera.h"

namespace penumbra::exec {

// World position of pixel (x, y) (GL order, pixel centre) at linear view depth `view_depth`.
glm::vec3 world_from_view_depth(const glm::mat4& inverse_view, const glm::mat4& inverse_projection, int x, int y,
                                int width, int height, float view_depth);

// Octahedral encoding stored as UNORM (gbuffer_read.glsl, encode_normal) -> unit vector.
glm::vec3 decode_octahedral_normal(glm::vec2 stored);
glm::vec2 encode_octahedral_normal(glm::vec3 n);

// xyz world position, w = linear view depth (> 0), or all 0 on background: what a stored
// position texel held before the contract kept only the depth.
std::vector<glm::vec4> read_positions(const gl::Texture& gbuffer_depth, const scene::Camera& camera);
std::vector<glm::vec3> read_normals(const gl::Texture& gbuffer_normal);

}  // namespace penumbra::exec
