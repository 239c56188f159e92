#pragma once
// A library opened at run time, so one binary starts on a machine that lacks it
// (the GPU server has no OSMesa; a CI box may have no EGL vendor), and technique plugins
// (plugin/plugin_library.h). Closed by the destructor.
#include <string>

namespace penumbra::gl {

class DynamicLibrary {
 public:
  DynamicLibrary() = default;
  // Tries each name in turn; error() says which were tried when none opened.
  explicit DynamicLibrary(std::initializer_list<const char*> names);
  ~DynamicLibrary();
  DynamicLibrary(const DynamicLibrary&) = delete;
  DynamicLibrary& operator=(const DynamicLibrary&) = delete;
  DynamicLibrary(DynamicLibrary&& o) noexcept
      : handle_(o.handle_), error_(std::move(o.error_)), loader_error_(std::move(o.loader_error_)) {
    o.handle_ = nullptr;
  }
  DynamicLibrary& operator=(DynamicLibrary&& o) noexcept;

  bool loaded() const { return handle_ != nullptr; }
  const std::string& error() const { return error_; }
  // The dynamic loader's own words for the last name that failed (dlerror: "undefined symbol:
  // ...", "file too short"), empty when that name opened.
  const std::string& loader_error() const { return loader_error_; }
  void* symbol(const char* name) const;
  template <class Fn>
  bool load(Fn& fn, const char* name) const {
    fn = reinterpret_cast<Fn>(symbol(name));
    return fn != nullptr;
  }

 private:
  void* handle_ = nullptr;
  std::string error_;
  std::string loader_error_;
};

}  // namespace penumbra::gl
