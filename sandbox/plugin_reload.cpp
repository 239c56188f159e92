#include "sandbox/plugin_reload.h"

#include <spdlog/spdlog.h>
#include <unistd.h>

#include <optional>

#include "passes/shared_passes.h"

namespace penumbra::sandbox {

namespace fs = std::filesystem;

struct PluginReloader::Plugin {
  fs::path file;                  // the watched .so
  fs::file_time_type mtime{};     // of the build last tried
  std::uintmax_t size = 0;
  std::optional<plugin::PluginLibrary> library;  // the build in use
  std::vector<std::string> techniques;           // what it registered
  std::string error;
};

namespace {

struct Stamp {
  fs::file_time_type mtime;
  std::uintmax_t size;
};

std::optional<Stamp> stamp(const fs::path& file) {
  std::error_code ec;
  Stamp s{fs::last_write_time(file, ec), 0};
  if (ec) return std::nullopt;
  s.size = fs::file_size(file, ec);
  if (ec) return std::nullopt;
  return s;
}

// A build that loaded and whose graphs parse, not yet in use.
struct Build {
  plugin::PluginLibrary library;
  technique::TechniqueRegistry techniques;  // what it registers
};

// Loads `file` through a private copy in `copies` (see plugin_reload.h for why).
Result<Build> open_build(const fs::path& file, const fs::path& copies, int& copy_count) {
  std::error_code ec;
  fs::create_directories(copies, ec);
  const fs::path copy = copies / (file.stem().string() + "." + std::to_string(++copy_count) + ".so");
  if (!fs::copy_file(file, copy, fs::copy_options::overwrite_existing, ec)) {
    Error e = make_error("cannot copy the plugin to " + copy.string() + ": " + ec.message());
    e.file = file.string();
    return e;
  }
  auto library = plugin::PluginLibrary::open(copy, file);
  fs::remove(copy, ec);  // mapped by now (or refused): the copy is not needed any more
  if (!library) return library.error();
  Build build{std::move(*library), {}};
  build.library.register_into(build.techniques);
  for (const technique::Technique& t : build.techniques.all())
    if (auto graph = load_technique_graph(build.techniques, t); !graph) return graph.error();
  return build;
}

}  // namespace

PluginReloader::PluginReloader()
    : copies_(fs::temp_directory_path() / ("penumbra-sandbox-plugins-" + std::to_string(getpid()))) {}

PluginReloader::~PluginReloader() {
  std::error_code ec;
  fs::remove_all(copies_, ec);
}

Status PluginReloader::load(const std::vector<std::string>& dirs, technique::TechniqueRegistry& registry) {
  for (const std::string& dir : plugin::plugin_search_path(dirs)) {
    auto files = plugin::scan_plugin_directory(dir);
    if (!files) return files.error();
    for (const fs::path& file : *files) {
      auto p = std::make_unique<Plugin>();
      p->file = file;
      if (auto s = stamp(file)) std::tie(p->mtime, p->size) = std::tie(s->mtime, s->size);
      auto build = open_build(file, copies_, copy_count_);
      if (!build) return build.error();
      for (const technique::Technique& t : build->techniques.all()) {
        registry.add(t);
        p->techniques.push_back(t.name);
      }
      p->library = std::move(build->library);
      plugins_.push_back(std::move(p));
    }
  }
  return {};
}

Status PluginReloader::reload(Plugin& p, SandboxController& controller, technique::TechniqueRegistry& registry,
                              exec::PassLibrary& library) {
  auto build = open_build(p.file, copies_, copy_count_);
  if (!build) {
    Error e = build.error();
    e.message = "plugin not reloaded, the previous build keeps running: " + e.message;
    return e;
  }
  // Unloaded when this function returns: by then the sessions, the registry and the pass
  // library hold nothing of its code.
  std::optional<plugin::PluginLibrary> previous = std::move(p.library);
  return controller.rebuild_sessions([&]() -> Status {
    for (const std::string& name : p.techniques) registry.remove(name);
    p.techniques.clear();
    for (const technique::Technique& t : build->techniques.all()) {
      registry.add(t);
      p.techniques.push_back(t.name);
    }
    p.library = std::move(build->library);
    library = make_pass_library(registry);
    return {};
  });
}

int PluginReloader::poll(SandboxController& controller, technique::TechniqueRegistry& registry,
                         exec::PassLibrary& library) {
  int swapped = 0;
  for (const std::unique_ptr<Plugin>& p : plugins_) {
    const std::optional<Stamp> now = stamp(p->file);
    if (!now || (now->mtime == p->mtime && now->size == p->size)) continue;  // unchanged, or gone
    p->mtime = now->mtime;
    p->size = now->size;
    if (Status s = reload(*p, controller, registry, library); !s) {
      p->error = s.error().to_string();
      spdlog::warn("{}", p->error);
      (void)controller.note(s);
      continue;
    }
    p->error.clear();
    spdlog::info("reloaded plugin {}", p->file.string());
    ++swapped;
  }
  return swapped;
}

std::vector<PluginReloader::PluginState> PluginReloader::plugins() const {
  std::vector<PluginState> out;
  for (const std::unique_ptr<Plugin>& p : plugins_) out.push_back({p->file, p->techniques, p->error});
  return out;
}

}  // namespace penumbra::sandbox
