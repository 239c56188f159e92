#pragma once
// A library opened at run time, so one binary starts on a machine that lacks it
// (the GPU server has no OSMesa; a CI box may have no EGL vendor).
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
  DynamicLibrary(DynamicLibrary&& o) noexcept : handle_(o.handle_), error_(std::move(o.error_)) {
    o.handle_ = nullptr;
  }

  bool loaded() const { return handle_ != nullptr; }
  const std::string& error() const { return error_; }
  void* symbol(const char* name) const;
  template <class Fn>
  bool load(Fn& fn, const char* name) const {
    fn = reinterpret_cast<Fn>(symbol(name));
    return fn != nullptr;
  }

 private:
  void* handle_ = nullptr;
  std::string error_;
};

}  // namespace penumbra::gl
