// GL-free properties of the raster reference's per-sample views.
#include <gtest/gtest.h>

#include <algorithm>

#include "scene/builtin_scenes.h"
#include "techniques/reference/sample_view.h"

using namespace penumbra;

TEST(SampleView, EveryBoundsCornerProjectsInsideTheMap) {
  auto s = scene::make_builtin_scene("ball");
  ASSERT_TRUE(s);
  const scene::Bounds& b = s->bounds;
  for (scene::LightType type : {scene::LightType::directional, scene::LightType::spot}) {
    scene::Light light = s->light;
    light.type = type;
    for (const scene::LightSample& sample : scene::light_samples(light, b, 16, 0)) {
      const glm::mat4 vp = reference::sample_view(light, b, sample).view_proj;
      for (int i = 0; i < 8; ++i) {
        const glm::vec3 c((i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y, (i & 4) ? b.max.z : b.min.z);
        const glm::vec4 clip = vp * glm::vec4(c, 1.0f);
        ASSERT_GT(clip.w, 0.0f);
        const glm::vec3 ndc = glm::vec3(clip) / clip.w;
        EXPECT_LE(glm::abs(ndc.x), 1.0f);
        EXPECT_LE(glm::abs(ndc.y), 1.0f);
        EXPECT_LE(glm::abs(ndc.z), 1.0f);
      }
    }
  }
}

TEST(SampleView, EachSampleLooksAlongItsOwnRay) {
  // A point on the sample's own ray through the bounds' centre projects to the same map
  // position as the centre, only deeper: the map's axis is the sample's light direction.
  auto s = scene::make_builtin_scene("ball");
  ASSERT_TRUE(s);
  for (scene::LightType type : {scene::LightType::directional, scene::LightType::spot}) {
    scene::Light light = s->light;
    light.type = type;
    const glm::vec3 c = s->bounds.center();
    for (const scene::LightSample& sample : scene::light_samples(light, s->bounds, 4, 0)) {
      const glm::vec3 ray = sample.is_point ? glm::normalize(c - sample.point) : glm::normalize(sample.direction);
      const glm::mat4 vp = reference::sample_view(light, s->bounds, sample).view_proj;
      const glm::vec4 a = vp * glm::vec4(c, 1.0f), b = vp * glm::vec4(c + 0.5f * ray, 1.0f);
      EXPECT_NEAR(a.x / a.w, b.x / b.w, 1e-4f);
      EXPECT_NEAR(a.y / a.w, b.y / b.w, 1e-4f);
      EXPECT_GT(b.z / b.w, a.z / a.w);
    }
  }
}

TEST(SampleView, ProgressiveOrderIsAPermutation) {
  for (int n : {1, 2, 7, 16, 64, 256, 1000, 1024}) {
    std::vector<int> seen;
    for (int k = 0; k < n; ++k) seen.push_back(reference::progressive_index(k, n));
    std::sort(seen.begin(), seen.end());
    for (int k = 0; k < n; ++k) ASSERT_EQ(seen[k], k) << "n = " << n;
  }
  // The first quarter of the order touches every row of a 16x16 strata grid.
  std::vector<int> rows(16, 0);
  for (int k = 0; k < 64; ++k) rows[reference::progressive_index(k, 256) / 16]++;
  for (int r : rows) EXPECT_GT(r, 0);
}
