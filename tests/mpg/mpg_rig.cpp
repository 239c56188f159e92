#include "mpg_rig.h"

#include <cstdlib>
#include <filesystem>

#include "metrics/heat_map.h"
#include "techniques/builtin_techniques.h"

namespace penumbra::test {

MpgRig::MpgRig(int width, int height, int shadow_size)
    : TechniqueRig({.width = width, .height = height, .shadow_size = shadow_size, .technique = "mpg",
                    .techniques = register_builtin_techniques}) {}

namespace {
const char* image_dir() {
  const char* dir = std::getenv("MPG_TEST_IMAGES");
  if (dir) std::filesystem::create_directories(dir);
  return dir;
}
}  // namespace

void save_for_inspection(const std::string& name, const metrics::MaskImage& image) {
  const char* dir = image_dir();
  if (dir && image.width > 0) (void)metrics::write_png(std::string(dir) + "/" + name + ".png", image);
}

void save_for_inspection(const std::string& name, const metrics::RgbaImage& image) {
  const char* dir = image_dir();
  if (dir && image.width > 0) (void)metrics::write_png(std::string(dir) + "/" + name + ".png", image);
}

}  // namespace penumbra::test
