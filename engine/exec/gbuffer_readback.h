#pragma once
// The frame contract read back on the CPU (the reference ray tracer, metrics, tests): world
// positions rebuilt from `gbuffer_depth` and normals decoded from `gbuffer_normal`, the same
// arithmetic as passes/gbuffer/gbuffer_read.glsl (tests/gl/gbuffer_contract_test.cpp checks the
// two against each other and against rasterised positions).
#include <vector>

#include <glm/glm.hpp>

#include "gl/texture.h"
#include "scene/camera.h"

namespace penumbra::exec {

// The camera rays of a width x height image, linear in the pixel coordinate (a perspective
// camera): the point at linear view depth d seen through pixel coordinate (x, y) (GL order,
// pixel centres at + 0.5) is origin + d * (ray00 + x * ray_dx + y * ray_dy). Computed once per
// frame (exec/frame_uniforms.h uploads it), so a pass rebuilds a position with one multiply-add
// per axis instead of two matrix products.
struct PixelRays {
  glm::vec3 origin;  // the camera position, world units
  glm::vec3 ray00;   // at pixel coordinate (0, 0), the image's bottom-left corner; view depth 1
  glm::vec3 ray_dx;  // change per pixel to the right
  glm::vec3 ray_dy;  // change per pixel up
};
PixelRays pixel_rays(const glm::mat4& view, const glm::mat4& projection, int width, int height);

// World position of pixel (x, y) (GL order, pixel centre) at linear view depth `view_depth`.
glm::vec3 world_from_view_depth(const PixelRays& rays, int x, int y, float view_depth);

// Octahedral encoding stored as UNORM (gbuffer_read.glsl, encode_normal) -> unit vector.
glm::vec3 decode_octahedral_normal(glm::vec2 stored);
glm::vec2 encode_octahedral_normal(glm::vec3 n);

enum class RowOrder { bottom_up, top_down };  // bottom_up: GL's order, like gl::Texture::read()

// xyz world position, w = linear view depth (> 0), or all 0 on background: what a stored
// position texel held before the contract kept only the depth.
std::vector<glm::vec4> read_positions(const gl::Texture& gbuffer_depth, const scene::Camera& camera,
                                      RowOrder rows = RowOrder::bottom_up);
std::vector<glm::vec3> read_normals(const gl::Texture& gbuffer_normal);

}  // namespace penumbra::exec
