#include "sandbox/sandbox_main.h"

#include <cstdio>

#include "sandbox/controller.h"
#include "sandbox/layout.h"
#include "sandbox/options.h"
#include "sandbox/plugin_reload.h"
#include "technique/preset.h"
#include "util/file_write.h"
#include "sandbox/script.h"
#include "sandbox/script_runner.h"
#include "sandbox/window_host.h"
#include "util/file_read.h"
#include "gl/context.h"
#include "techniques/builtin_techniques.h"
#include "passes/shared_passes.h"

namespace penumbra::sandbox {

namespace {

int fail(const Error& e) {
  std::fprintf(stderr, "penumbra-sandbox: %s\n", e.to_string().c_str());
  if (!e.details.empty()) std::fprintf(stderr, "%s\n", e.details.c_str());
  return e.exit_code();
}

// Tool mode: the test script that visits every registered technique and parameter.
int write_exhaustive(const technique::TechniqueRegistry& registry, const SandboxOptions& o) {
  std::vector<TechniqueInfo> infos;
  for (const technique::Technique& t : registry.all()) {
    auto g = load_technique_graph(registry, t);
    if (!g) return fail(g.error());
    infos.push_back({t.name, g->parameters});
  }
  if (infos.empty())
    return fail(make_error("no techniques are registered: nothing to write", ErrorKind::internal));
  std::string text = exhaustive_script(infos, o.screenshot_dir, o.width, o.height, o.shadow_size.value_or(512));
  if (Status s = write_file_whole(o.exhaustive_script, text); !s) return fail(s.error());
  std::printf("wrote %s (%zu techniques)\n", o.exhaustive_script.c_str(), infos.size());
  return 0;
}

}  // namespace

int sandbox_main(int argc, char** argv, const ExtraTechniques& extra) {
  std::vector<std::string> args(argv + 1, argv + argc);
  auto options = parse_sandbox_options(args);
  if (!options) return fail(options.error());
  const SandboxOptions& o = *options;
  if (o.help) {
    std::printf("%s", sandbox_help().c_str());
    return 0;
  }

  PluginReloader plugins;  // declared first: it unloads plugin code after all that runs it is gone
  technique::TechniqueRegistry registry;
  register_builtin_techniques(registry);
  if (extra) extra(registry);
  if (Status s = plugins.load(o.plugin_dirs, registry); !s) return fail(s.error());
  if (!o.exhaustive_script.empty()) return write_exhaustive(registry, o);

  // Output paths and a bad script are reported before any window opens, not after the run.
  for (const std::string& path : {o.screenshot, o.state_file})
    if (!path.empty())
      if (Status s = check_output_path(path); !s) return fail(s.error());
  std::optional<std::vector<ScriptStep>> script;
  if (!o.script.empty()) {
    auto text = read_file_whole(o.script);
    if (!text) return fail(text.error());
    auto parsed = parse_script(*text, o.script);
    if (!parsed) return fail(parsed.error());
    script = std::move(*parsed);
  }

  exec::PassLibrary library = make_pass_library(registry);
  gl::ContextOptions copts;
  copts.kind = gl::ContextKind::glfw;
  if (!o.context.empty()) copts.kind = *gl::parse_context_kind(o.context);
  copts.want_window = true;
  // A window holds the panel beside the frame: --size is the frame's (the viewport's) size.
  copts.width = copts.kind == gl::ContextKind::glfw ? window_width_for(o.width, kDefaultPanelWidth) : o.width;
  copts.height = o.height;
  copts.title = "Penumbra sandbox";
  auto context = gl::create_context(copts);
  if (!context) return fail(context.error());

  SandboxController controller(registry, library);
  controller.set_reload_hook([&] { plugins.poll(controller, registry, library); });
  controller.set_staging(o.staging);
  if (o.shadow_size)
    if (Status s = controller.session().set_shadow_size(*o.shadow_size); !s) return fail(s.error());
  if (Status s = controller.session().set_cascades(o.cascades); !s) return fail(s.error());
  if (Status s = controller.init(o.scene, o.technique, o.width, o.height); !s) return fail(s.error());

  if ((*context)->window()) return run_window(**context, controller, {script, o.screenshot, o.max_fps, o.state_file});

  // Headless (osmesa/egl): the same script path without a window or UI.
  ScriptRunner runner(script.value_or(std::vector<ScriptStep>{}),
                      [&](int w, int h) { return controller.resize(w, h); });
  if (Status s = run_script_headless(controller, runner); !s) return fail(s.error());
  if (!o.screenshot.empty()) {
    for (int i = 0; i < 2; ++i)
      if (Status s = controller.render_frame(); !s) return fail(s.error());
    if (Status s = controller.save_presentation_png(o.screenshot); !s) return fail(s.error());
  }
  return 0;
}

}  // namespace penumbra::sandbox
