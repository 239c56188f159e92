#pragma once
// A palm tree for the built-in `palms` scene (Cherry & Kooima's Pool scene: "The palm tree leaves
// are simply quads with a texture using the alpha channel to denote the areas between the
// leaves"): a gently bent trunk of cylinders and a crown of fronds, each frond two textured quads
// (an arch: rising, then drooping) whose alpha texture cuts out the gaps between the leaflets.
// World units are metres, Y up.
//
//   Mesh trunk, fronds;
//   build::add_palm(trunk, fronds, {.base = {1, 0, -2}, .height = 3.5f, .fronds = 9});
//   scene.images.push_back(palm_frond_image());  // the fronds' material samples it (alpha mask)
#include <glm/glm.hpp>

#include "scene/scene.h"

namespace penumbra::scene {

struct PalmTree {
  glm::vec3 base{0.0f};      // foot of the trunk on the ground, world units
  float height = 3.5f;       // top of the trunk above the base, metres
  float lean_degrees = 8.0f; // trunk lean from vertical, towards lean_azimuth
  float lean_azimuth = 0.0f; // degrees around Y (0 = towards +X)
  int fronds = 9;            // fronds around the crown
  float frond_length = 1.8f; // metres, base to tip
  float frond_width = 0.7f;  // metres, leaflet tip to leaflet tip
  float crown_phase = 0.0f;  // degrees: rotation of the first frond around Y
};

// The RGBA8 frond texture: u along the frond (0 = base, 1 = tip; image x), v across (image y, the
// midrib at v = 0.5). Alpha 255 on the midrib and on slanted leaflets inside a tapering outline,
// 0 in the gaps and outside; green colour. Gaps and leaflets are at least 6 texels wide so the
// mip levels the G-buffer and shadow-map passes sample keep them.
Image palm_frond_image();

namespace build {
// Appends the trunk (cylinders, to `trunk`) and the fronds (double-sided quads with uv for
// palm_frond_image(), to `fronds`).
void add_palm(Mesh& trunk, Mesh& fronds, const PalmTree& palm);
}  // namespace build

}  // namespace penumbra::scene
