// Sandbox scripts through the parser the sandbox runs before opening a window.
#include <cstddef>
#include <cstdint>
#include <string>

#include "sandbox/script.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  (void)penumbra::sandbox::parse_script(std::string(reinterpret_cast<const char*>(data), size), "fuzz.json");
  return 0;
}
