#include "pmchss_fixture.h"

#include <cstdlib>
#include <filesystem>

#include "metrics/heat_map.h"
#include "techniques/builtin_techniques.h"

namespace penumbra::test {

PmchssRig::PmchssRig(int width, int height, int shadow_size)
    : TechniqueRig({.width = width, .height = height, .shadow_size = shadow_size, .technique = "pmchss",
                    .techniques = register_builtin_techniques}) {}

void save_for_inspection(const std::string& name, const metrics::MaskImage& image) {
  const char* dir = std::getenv("PMCHSS_TEST_IMAGES");
  if (!dir || image.width == 0) return;
  std::filesystem::create_directories(dir);
  (void)metrics::write_png(std::string(dir) + "/" + name + ".png", image);
}

}  // namespace penumbra::test
