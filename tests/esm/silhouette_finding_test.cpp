// The finding pass (shaders/silhouette_find.comp.glsl): on the GPU, every quad of every instance
// tested against the light; the list holds exactly the quads the CPU's is_silhouette keeps, with
// each instance's own world and plane matrices, the draw command counts six vertices each, and
// the compute writer's dispatch one work group each.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "exec/gpu_scene.h"
#include "gl/program.h"
#include "scene/builtin_scenes.h"
#include "scene/mesh_builder.h"
#include "techniques/esm/silhouette/silhouette_buffers.h"
#include "test_support/gl_context.h"

using namespace penumbra;

namespace {

// The silhouettes a light sees over every instance, counted on the CPU from the builder's quads.
size_t cpu_silhouettes(const scene::Scene& s, const glm::vec4& light) {
  Result<std::vector<esm::SilhouetteGeometry>> g = esm::build_scene_silhouettes(s);
  EXPECT_TRUE(g);
  size_t n = 0;
  for (const scene::Instance& inst : s.instances) {
    const glm::mat4 planes = glm::inverseTranspose(inst.world);
    for (esm::SilhouetteQuad q : (*g)[inst.mesh].quads) {
      q.p = planes * q.p;
      q.q = planes * q.q;
      n += esm::is_silhouette(q, light) ? 1 : 0;
    }
  }
  return n;
}

gl::Program find_program() {
  Result<gl::Program> p = gl::build_program(
      {.compute = "techniques/esm/shaders/silhouette_find.comp.glsl", .defines = esm::silhouette_shader_defines()},
      gl::ShaderFileSystem::default_instance());
  EXPECT_TRUE(p) << p.error().to_string();
  return p ? std::move(*p) : gl::Program();
}

class SilhouetteFinding : public test::GlTest {};

}  // namespace

TEST_F(SilhouetteFinding, ListsExactlyTheQuadsTheLightSeparatesOnEveryInstance) {
  // Colonnade's meshes, plus a box placed three times: turned, stretched unevenly (planes need the
  // inverse transpose) and mirrored (a negative determinant).
  scene::Scene s = *scene::make_builtin_scene("colonnade");
  scene::Mesh box;
  box.name = "box";
  scene::build::add_box(box, {0, 0, 0}, {1.0f, 0.5f, 0.75f});
  box.material = 0;
  s.meshes.push_back(box);
  const uint32_t b = static_cast<uint32_t>(s.meshes.size() - 1);
  const glm::mat4 turned = glm::rotate(glm::translate(glm::mat4(1), {2, 1, 0}), 0.7f, glm::vec3(0.3f, 1, 0.2f));
  const glm::mat4 stretched = glm::scale(glm::translate(glm::mat4(1), {-2, 1, 1}), {3.0f, 0.2f, 1.5f});
  const glm::mat4 mirrored = glm::scale(glm::translate(glm::mat4(1), {0, 2, -2}), {-1.0f, 1.0f, 1.0f});
  for (const glm::mat4& m : {turned, stretched, mirrored}) s.instances.push_back({b, m});
  exec::GpuScene gpu(s);
  Result<std::shared_ptr<esm::SilhouetteBuffers>> buffers = esm::SilhouetteBuffers::for_scene(gpu);
  ASSERT_TRUE(buffers) << buffers.error().to_string();
  const gl::Program find = find_program();
  ASSERT_TRUE(find);
  size_t instance_quads = 0;
  Result<std::vector<esm::SilhouetteGeometry>> g = esm::build_scene_silhouettes(s);
  for (const scene::Instance& inst : s.instances) instance_quads += (*g)[inst.mesh].quads.size();
  EXPECT_EQ((*buffers)->instance_quads(), instance_quads);
  const glm::vec4 lights[] = {glm::vec4(glm::normalize(glm::vec3(0.4f, 1.0f, 0.3f)), 0.0f),  // towards the sun
                              glm::vec4(glm::normalize(glm::vec3(-1.0f, 0.5f, 0.1f)), 0.0f),
                              glm::vec4(0.5f, 1.5f, 0.5f, 1.0f),    // a point light among the columns
                              glm::vec4(1.0f, 30.0f, -4.0f, 1.0f)};
  for (const glm::vec4& light : lights) {
    (*buffers)->find(find, light);
    const size_t expected = cpu_silhouettes(s, light);
    EXPECT_EQ((*buffers)->found(), expected) << "light " << light.x << " " << light.y << " " << light.z;
    // The compute writer's dispatch: one work group per listed quad.
    const std::array<std::uint32_t, 3> groups = (*buffers)->write_groups();
    EXPECT_EQ(groups[0], expected);
    EXPECT_EQ(groups[1], 1u);
    EXPECT_EQ(groups[2], 1u);
    EXPECT_TRUE((*buffers)->can_write_found());
    // Silhouettes are a small part of the quads: the raster's work follows them, not the mesh.
    EXPECT_GT(expected, 0u);
    EXPECT_LT(expected, instance_quads / 2);
  }
}

TEST_F(SilhouetteFinding, AFindAfterAnotherStartsFromAnEmptyList) {
  scene::Scene s = *scene::make_builtin_scene("ball");
  exec::GpuScene gpu(s);
  Result<std::shared_ptr<esm::SilhouetteBuffers>> buffers = esm::SilhouetteBuffers::for_scene(gpu);
  ASSERT_TRUE(buffers) << buffers.error().to_string();
  const gl::Program find = find_program();
  const glm::vec4 light(glm::normalize(glm::vec3(0.2f, 1.0f, 0.1f)), 0.0f);
  (*buffers)->find(find, light);
  const size_t once = (*buffers)->found();
  (*buffers)->find(find, light);
  EXPECT_EQ((*buffers)->found(), once);
  EXPECT_EQ((*buffers)->write_groups()[0], once);
  EXPECT_EQ(once, cpu_silhouettes(s, light));
}

TEST_F(SilhouetteFinding, ASceneWithoutQuadsFindsNothing) {
  scene::Scene s;
  s.materials.push_back({});
  scene::Mesh empty;
  empty.name = "empty";
  s.meshes.push_back(empty);
  s.instances.push_back({0, glm::mat4(1.0f)});
  exec::GpuScene gpu(s);
  Result<std::shared_ptr<esm::SilhouetteBuffers>> buffers = esm::SilhouetteBuffers::for_scene(gpu);
  ASSERT_TRUE(buffers) << buffers.error().to_string();
  EXPECT_EQ((*buffers)->instance_quads(), 0u);
  const gl::Program find = find_program();
  (*buffers)->find(find, glm::vec4(0, 1, 0, 0));
  EXPECT_EQ((*buffers)->found(), 0u);
}
