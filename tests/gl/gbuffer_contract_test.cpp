// The slim frame contract: positions rebuilt from the R32F view depth (gbuffer_read.glsl on the
// GPU, exec/gbuffer_readback.h on the CPU) against the exact geometry, and the octahedral normal
// against the surface's. Two planes, one facing the camera's side and one the ground, on a
// 1e-3-unit and a 1e3-unit copy of the same scene: near and far depths at both scales.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include <glm/gtc/matrix_transform.hpp>

#include "exec/gbuffer_readback.h"
#include "exec/pass_decl_builder.h"
#include "scene/mesh_builder.h"
#include "test_support/technique_rig.h"

namespace penumbra::test {
namespace {

class ContractProbePass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    gl::ShaderProgram& p = ctx.program({.compute = "tests/gl/shaders/contract_probe.comp.glsl"});
    if (!p.valid()) return *p.last_error();
    ctx.bind_sampled(p, "u_depth", "depth");
    ctx.bind_sampled(p, "u_normal", "normal");
    ctx.bind_image(0, "position_out", GL_WRITE_ONLY);
    ctx.bind_image(1, "normal_out", GL_WRITE_ONLY);
    ctx.bind_image(2, "mask", GL_WRITE_ONLY);
    ctx.dispatch_over(p, ctx.texture("mask").width(), ctx.texture("mask").height());
    return {};
  }
};

void register_probe(technique::TechniqueRegistry& registry) {
  registry.add({.name = "contract_probe",
                .graph_file = "tests/gl/contract_probe.json",
                .register_passes = [](exec::PassLibrary& library) {
                  library.add(exec::PassDeclBuilder("contract_probe")
                                  .describe("Test: the frame contract as passes read it")
                                  .sampled("depth", {graph::Format::R32F})
                                  .sampled("normal", {graph::Format::RG16})
                                  .image_out("position_out", {graph::Format::RGBA32F})
                                  .image_out("normal_out", {graph::Format::RGBA32F})
                                  .image_out("mask", {graph::Format::R16F})
                                  .build<ContractProbePass>());
                }});
}

// A ground (y = 0) 40 x 40 scale units and a wall (z = -10 scale, facing +z), seen from
// (0, 1.5, 12) scale units looking at (0, 0.5, 0): depths from about 2 to 25 scale units on the
// ground, grazing at the horizon.
scene::Scene two_planes(float scale) {
  scene::Scene s;
  s.name = "two_planes";
  s.materials.push_back({.base_color_factor = glm::vec4(0.8f, 0.8f, 0.8f, 1.0f)});
  scene::Mesh m;
  m.name = "planes";
  scene::build::add_ground(m, glm::vec3(0.0f), 40.0f * scale, 40.0f * scale);
  scene::Mesh wall;
  scene::build::add_ground(wall, glm::vec3(0.0f), 40.0f * scale, 20.0f * scale);
  for (scene::Vertex& v : wall.vertices) {
    v.position = glm::vec3(v.position.x, 10.0f * scale - v.position.z, -10.0f * scale);  // +y turned to +z
    v.normal = glm::vec3(0, 0, 1);
  }
  const uint32_t base = static_cast<uint32_t>(m.vertices.size());
  m.vertices.insert(m.vertices.end(), wall.vertices.begin(), wall.vertices.end());
  for (uint32_t i : wall.indices) m.indices.push_back(base + i);
  m.material = 0;
  s.meshes.push_back(std::move(m));
  s.instances.push_back({0, glm::mat4(1.0f)});
  s.bounds = scene::compute_bounds(s);
  s.camera = scene::Camera::look_at(glm::vec3(0.0f, 1.5f, 12.0f) * scale, glm::vec3(0.0f, 0.5f, 0.0f) * scale,
                                    glm::radians(50.0f), 0.05f * scale, 200.0f * scale);
  s.light.direction = glm::normalize(glm::vec3(-1.0f, -2.0f, -1.0f));
  return s;
}

// Where the ray through pixel (x, y)'s centre (rows top to bottom) meets the planes, exactly
// (double precision), and that plane's normal; false where it meets neither.
bool exact_hit(const scene::Camera& camera, int x, int y, int w, int h, float scale, glm::dvec3& hit, glm::dvec3& n) {
  const glm::dmat4 inverse_view_proj = glm::inverse(glm::dmat4(camera.projection(float(w) / float(h))) *
                                                    glm::dmat4(camera.view()));
  const glm::dvec2 ndc((x + 0.5) / w * 2.0 - 1.0, 1.0 - (y + 0.5) / h * 2.0);
  glm::dvec4 a = inverse_view_proj * glm::dvec4(ndc, -1.0, 1.0), b = inverse_view_proj * glm::dvec4(ndc, 1.0, 1.0);
  const glm::dvec3 origin = glm::dvec3(a) / a.w, dir = glm::normalize(glm::dvec3(b) / b.w - origin);
  double best = 1e300;
  const double s = scale;
  if (dir.y < 0.0) {  // ground, |x|, |z| <= 20 s
    const double t = -origin.y / dir.y;
    const glm::dvec3 p = origin + t * dir;
    if (std::abs(p.x) <= 20.0 * s && std::abs(p.z) <= 20.0 * s && p.z > -10.0 * s) best = t, hit = p, n = {0, 1, 0};
  }
  if (dir.z < 0.0) {  // wall z = -10 s, y in [0, 20 s]
    const double t = (-10.0 * s - origin.z) / dir.z;
    const glm::dvec3 p = origin + t * dir;
    if (t < best && std::abs(p.x) <= 20.0 * s && p.y >= 0.0 && p.y <= 20.0 * s) best = t, hit = p, n = {0, 0, 1};
  }
  return best < 1e300;
}

// The angle between two directions, exact for nearly equal ones (acos of a dot product is not:
// a float32 unit vector's length alone moves the dot by 1e-7, 0.02 degrees).
double degrees_between(const glm::dvec3& a, const glm::dvec3& b) {
  return glm::degrees(std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)));
}

struct Errors {
  double worst_relative = 0.0;       // |rebuilt - exact| / view depth
  double worst_normal_degrees = 0.0;
  double nearest = 1e300, farthest = 0.0;  // view depths of the receivers compared
  int compared = 0;
};

class GBufferContract : public ::testing::TestWithParam<float> {};

TEST_P(GBufferContract, RebuiltPositionsAndNormalsMatchTheGeometry) {
  const float scale = GetParam();
  constexpr int kW = 160, kH = 96;
  TechniqueRig rig({.width = kW, .height = kH, .shadow_size = 256, .technique = "contract_probe",
                    .techniques = register_probe});
  const scene::Scene s = two_planes(scale);
  rig.set_scene(s);
  rig.render();
  const TextureImage gpu = rig.read_all("probe_position"), gpu_normal = rig.read_all("probe_normal");
  const std::vector<glm::vec4> cpu = rig.positions();
  ASSERT_EQ(gpu.width, kW);
  ASSERT_EQ(cpu.size(), static_cast<size_t>(kW) * kH);
  Errors e;
  for (int y = 1; y < kH - 1; ++y)
    for (int x = 1; x < kW - 1; ++x) {
      glm::dvec3 exact, n;
      if (!exact_hit(rig.session().camera(), x, y, kW, kH, scale, exact, n)) continue;
      const double depth = gpu.at(x, y, 3);
      if (!(depth > 0.0)) continue;  // an edge pixel the raster missed
      const glm::dvec3 rebuilt(gpu.at(x, y, 0), gpu.at(x, y, 1), gpu.at(x, y, 2));
      // Pixels beside the wall-ground crease may sample the other plane.
      if (std::abs(exact.y) < 0.05 * scale && std::abs(exact.z + 10.0 * scale) < 0.5 * scale) continue;
      const double relative = glm::length(rebuilt - exact) / depth;
      e.worst_relative = std::max(e.worst_relative, relative);
      const glm::dvec3 cpu_rebuilt(cpu[static_cast<size_t>(y) * kW + x]);
      EXPECT_LT(glm::length(cpu_rebuilt - rebuilt) / depth, 1e-5) << "CPU and GPU disagree at " << x << "," << y;
      const glm::dvec3 decoded(gpu_normal.at(x, y, 0), gpu_normal.at(x, y, 1), gpu_normal.at(x, y, 2));
      e.worst_normal_degrees = std::max(e.worst_normal_degrees, degrees_between(decoded, n));
      e.nearest = std::min(e.nearest, depth);
      e.farthest = std::max(e.farthest, depth);
      ++e.compared;
    }
  ASSERT_GT(e.compared, kW * kH / 2);
  // Near and far: the ground from a few units in front of the camera to the wall beyond it.
  EXPECT_LT(e.nearest, 6.0 * scale);
  EXPECT_GT(e.farthest, 20.0 * scale);
  // The bound documented in docs/writing-a-technique.md: float32 interpolation of the view depth
  // and the per-frame camera rays (exec::PixelRays), a few parts in a million at any scale.
  EXPECT_LT(e.worst_relative, 1e-5) << "scale " << scale;
  std::printf("scale %g: %d receivers, view depth %.3g..%.3g, worst position error %.3g of the depth, normal %.4f deg\n", scale, e.compared, e.nearest, e.farthest, e.worst_relative, e.worst_normal_degrees);
  // RG16 octahedral: 16 bits a component, a few thousandths of a degree (Cigolle et al. 2014,
  // Table 1).
  EXPECT_LT(e.worst_normal_degrees, 0.01) << "scale " << scale;
}

INSTANTIATE_TEST_SUITE_P(Scales, GBufferContract, ::testing::Values(1e-3f, 1.0f, 1e3f));

// The per-frame ray basis the passes use against the two inverse matrices it replaces, on a
// centred and an off-centre (shifted) perspective frustum, at the corners and the middle.
TEST(PixelRays, RebuildTheSamePointsAsTheInverseMatrices) {
  const glm::mat4 view = glm::lookAt(glm::vec3(3.0f, 2.0f, 7.0f), glm::vec3(0.0f, 0.5f, 0.0f), glm::vec3(0, 1, 0));
  constexpr int kW = 1920, kH = 1080;
  for (const glm::mat4& projection : {glm::perspective(0.9f, 16.0f / 9.0f, 0.05f, 500.0f),
                                      glm::frustum(-0.02f, 0.07f, -0.03f, 0.02f, 0.05f, 500.0f)}) {
    const exec::PixelRays rays = exec::pixel_rays(view, projection, kW, kH);
    const glm::dmat4 inverse_view = glm::inverse(glm::dmat4(view)), inverse_projection = glm::inverse(glm::dmat4(projection));
    double worst = 0.0;
    for (const glm::ivec2 px : {glm::ivec2(0, 0), glm::ivec2(kW - 1, 0), glm::ivec2(0, kH - 1), glm::ivec2(kW - 1, kH - 1),
                                glm::ivec2(kW / 2, kH / 3)})
      for (const double depth : {0.1, 3.0, 250.0}) {
        const glm::dvec2 ndc = (glm::dvec2(px) + 0.5) / glm::dvec2(kW, kH) * 2.0 - 1.0;
        const glm::dvec4 near_point = inverse_projection * glm::dvec4(ndc, -1.0, 1.0);
        const glm::dvec3 ray = glm::dvec3(near_point) / near_point.w;
        const glm::dvec3 exact = glm::dvec3(inverse_view * glm::dvec4(ray * (depth / -ray.z), 1.0));
        const glm::dvec3 rebuilt(exec::world_from_view_depth(rays, px.x, px.y, static_cast<float>(depth)));
        worst = std::max(worst, glm::length(rebuilt - exact) / depth);
      }
    // float32 world coordinates: the camera position's rounding (7.8 units here) is a few parts in
    // a million of the nearest depth, 0.1; the contract's documented bound is 1e-5.
    EXPECT_LT(worst, 1e-5);
    EXPECT_GT(worst, 0.0);  // float32, not the double computation itself
  }
}

TEST(OctahedralNormal, EncodeDecodeRoundTripsEveryDirection) {
  double worst = 0.0;
  for (int i = 0; i < 2000; ++i) {
    // Fibonacci sphere: directions in every octant, poles included.
    const double z = 1.0 - 2.0 * (i + 0.5) / 2000.0, r = std::sqrt(1.0 - z * z), phi = i * 2.399963229728653;
    const glm::vec3 n(static_cast<float>(r * std::cos(phi)), static_cast<float>(r * std::sin(phi)), static_cast<float>(z));
    glm::vec2 stored = exec::encode_octahedral_normal(n);
    stored = glm::round(stored * 65535.0f) / 65535.0f;  // what RG16 keeps
    const glm::dvec3 back(exec::decode_octahedral_normal(stored)), exact(n);
    worst = std::max(worst, degrees_between(back, exact));
  }
  EXPECT_LT(worst, 0.005);
  EXPECT_GT(worst, 0.0);  // RG16 does lose something: the rounding above is real
}

}  // namespace
}  // namespace penumbra::test
