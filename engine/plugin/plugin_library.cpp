#include "plugin/plugin_library.h"

#include <algorithm>
#include <cstdlib>

#include "gl/shader_files.h"
#include "plugin/plugin_file_check.h"
#include "util/file_read.h"

namespace penumbra::plugin {

namespace fs = std::filesystem;

namespace {

Error plugin_error(const fs::path& file, std::string message) { return file_error(file.string(), std::move(message)); }

Error abi_mismatch(const fs::path& file, int version) {
  return plugin_error(file, "plugin ABI version " + std::to_string(version) + ", this Penumbra's is " +
                                std::to_string(kPluginAbiVersion) + ": rebuild the plugin against this Penumbra");
}

}  // namespace

Result<PluginLibrary> PluginLibrary::open(const fs::path& file, const fs::path& shown_as) {
  const fs::path shown = shown_as.empty() ? file : shown_as;
  // The file is checked whole and its ABI read before dlopen maps it or runs its constructors.
  Result<int> file_abi = read_plugin_abi_version(file);
  if (!file_abi) return plugin_error(shown, file_abi.error().message);
  if (*file_abi != kPluginAbiVersion) return abi_mismatch(shown, *file_abi);
  gl::DynamicLibrary library({file.c_str()});
  if (!library.loaded()) {
    // An unresolved symbol here usually means a plugin built against another libpenumbra
    // (another version, or a GL-strict build's loader in a release one). The loader's words
    // name the file it opened: name the one the user knows.
    std::string why = library.loader_error();
    if (const std::string opened = file.string(); shown != file)
      for (size_t at = why.find(opened); at != std::string::npos; at = why.find(opened, at + 1))
        why.replace(at, opened.size(), shown.string());
    return plugin_error(shown, "cannot load plugin: " + why);
  }
  PluginAbiVersionFn version_fn = nullptr;
  PluginRegisterFn register_fn = nullptr;
  if (!library.load(version_fn, kPluginAbiVersionSymbol) || !library.load(register_fn, kPluginRegisterSymbol))
    return plugin_error(shown, std::string("not a Penumbra plugin: it does not export ") + kPluginAbiVersionSymbol +
                                   " and " + kPluginRegisterSymbol +
                                   " (add PENUMBRA_PLUGIN(register_fn) from plugin/plugin_api.h)");
  if (const int version = version_fn(); version != kPluginAbiVersion) return abi_mismatch(shown, version);
  return PluginLibrary(std::move(library), shown, register_fn);
}

void PluginLibrary::register_into(technique::TechniqueRegistry& registry) const { register_fn_(registry); }

Result<std::vector<fs::path>> scan_plugin_directory(const std::string& dir) {
  std::error_code ec;
  if (Status s = check_directory(dir); !s) return plugin_error(dir, "plugin " + s.error().message);
  gl::ShaderFileSystem::default_instance().add_root(fs::absolute(dir, ec).lexically_normal());
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(dir, ec))
    if (entry.path().extension() == ".so" && entry.is_regular_file(ec)) files.push_back(entry.path());
  if (ec) return plugin_error(dir, "cannot list the plugin directory: " + ec.message());
  std::sort(files.begin(), files.end());
  return files;
}

std::vector<std::string> plugin_search_path(const std::vector<std::string>& dirs) {
  std::vector<std::string> out = dirs;
  const char* env = std::getenv("PENUMBRA_PLUGIN_PATH");
  if (!env) return out;
  std::string list = env;
  for (size_t start = 0; start <= list.size();) {
    size_t end = list.find(':', start);
    if (end == std::string::npos) end = list.size();
    if (end > start) out.push_back(list.substr(start, end - start));
    start = end + 1;
  }
  return out;
}

Result<int> load_plugin_directory(const std::string& dir, technique::TechniqueRegistry& registry) {
  auto files = scan_plugin_directory(dir);
  if (!files) return files.error();
  int loaded = 0;
  for (const fs::path& file : *files) {
    auto library = PluginLibrary::open(file);
    if (!library) return library.error();
    library->register_into(registry);
    // Never unloaded: the registry, pass libraries and executors run its code until exit.
    new PluginLibrary(std::move(*library));
    ++loaded;
  }
  return loaded;
}

Result<int> load_plugins(const std::vector<std::string>& dirs, technique::TechniqueRegistry& registry) {
  int loaded = 0;
  for (const std::string& dir : plugin_search_path(dirs)) {
    auto n = load_plugin_directory(dir, registry);
    if (!n) return n.error();
    loaded += *n;
  }
  return loaded;
}

}  // namespace penumbra::plugin
