// glTF and GLB files through the scene loader (tinygltf underneath): the input is written to a
// file in memory-backed /dev/shm (the loader takes paths, as users give them), as .glb when it
// starts with the GLB magic, else as .gltf.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

#include "scene/gltf_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const bool glb = size >= 4 && data[0] == 'g' && data[1] == 'l' && data[2] == 'T' && data[3] == 'F';
  const std::string path = "/dev/shm/penumbra_fuzz_" + std::to_string(getpid()) + (glb ? ".glb" : ".gltf");
  if (FILE* f = std::fopen(path.c_str(), "wb")) {
    std::fwrite(data, 1, size, f);
    std::fclose(f);
    (void)penumbra::scene::load_gltf(path);
    std::remove(path.c_str());
  }
  return 0;
}
