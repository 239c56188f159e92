#include "gl/dynamic_library.h"

#include <dlfcn.h>

#include <utility>

namespace penumbra::gl {

DynamicLibrary::DynamicLibrary(std::initializer_list<const char*> names) {
  std::string tried;
  for (const char* name : names) {
    handle_ = dlopen(name, RTLD_NOW | RTLD_LOCAL);
    if (handle_) return;
    const char* why = dlerror();
    loader_error_ = why ? why : "";
    if (!tried.empty()) tried += ", ";
    tried += name;
  }
  error_ = "could not open " + tried;
}

DynamicLibrary::~DynamicLibrary() {
  if (handle_) dlclose(handle_);
}

DynamicLibrary& DynamicLibrary::operator=(DynamicLibrary&& o) noexcept {
  if (this != &o) {
    if (handle_) dlclose(handle_);
    handle_ = std::exchange(o.handle_, nullptr);
    error_ = std::move(o.error_);
    loader_error_ = std::move(o.loader_error_);
  }
  return *this;
}

void* DynamicLibrary::symbol(const char* name) const {
  return handle_ ? dlsym(handle_, name) : nullptr;
}

}  // namespace penumbra::gl
