#include "test_support/inspection.h"

#include <cstdlib>
#include <filesystem>

#include "metrics/heat_map.h"

namespace penumbra::test {
namespace {

template <typename Image>
void save(const std::string& name, const Image& image) {
  const char* dir = std::getenv("PENUMBRA_TEST_IMAGES");
  if (!dir || !*dir || image.width == 0) return;
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  // A picture that cannot be written fails nothing: it is only there to be looked at.
  (void)metrics::write_png(std::string(dir) + "/" + name + ".png", image);
}

}  // namespace

void save_for_inspection(const std::string& name, const metrics::MaskImage& image) { save(name, image); }
void save_for_inspection(const std::string& name, const metrics::RgbaImage& image) { save(name, image); }

}  // namespace penumbra::test
