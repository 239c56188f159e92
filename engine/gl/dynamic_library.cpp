#include "gl/dynamic_library.h"

#include <dlfcn.h>

namespace penumbra::gl {

DynamicLibrary::DynamicLibrary(std::initializer_list<const char*> names) {
  std::string tried;
  for (const char* name : names) {
    handle_ = dlopen(name, RTLD_NOW | RTLD_LOCAL);
    if (handle_) return;
    if (!tried.empty()) tried += ", ";
    tried += name;
  }
  error_ = "could not open " + tried;
}

DynamicLibrary::~DynamicLibrary() {
  if (handle_) dlclose(handle_);
}

void* DynamicLibrary::symbol(const char* name) const {
  return handle_ ? dlsym(handle_, name) : nullptr;
}

}  // namespace penumbra::gl
