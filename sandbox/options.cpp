#include "sandbox/options.h"

#include "cli/options/args.h"
#include "cli/options/cascade_option.h"
#include "cli/options/plugin_option.h"
#include "cli/options/scene_option.h"

namespace penumbra::sandbox {

namespace {
const std::vector<cli::OptionSpec>& specs() {
  static const std::vector<cli::OptionSpec> s = cli::with_cascade_options(cli::with_scene_options({
      {"scene", true, false, "NAME|FILE", "built-in scene or glTF file (default showcase)"},
      {"technique", true, false, "T", "technique to start with (default sspcss, a contact-hardening one)"},
      {"size", true, false, "WxH", "window / frame size in pixels (default 1280x800)"},
      {"shadow-size", true, false, "N", "shadow-map resolution in texels"},
      {"script", true, false, "FILE", "run a JSON script of steps, then exit"},
      {"screenshot", true, false, "OUT.png", "save a screenshot when done (after the script)"},
      {"context", true, false, "glfw|osmesa|egl",
       "GL context (default glfw: a window; osmesa/egl run the script without a window or UI)"},
      {"write-exhaustive-script", true, false, "FILE",
       "write a script that visits every technique and parameter (for tests), then exit"},
      {"screenshot-dir", true, false, "DIR", "where the exhaustive script's screenshots go (default .)"},
      {"max-fps", true, false, "N", "cap the frame rate (1..1000; default: the display's refresh)"},
      {"state-file", true, false, "FILE",
       "rewrite FILE every frame with the window's state as JSON: widgets, open popup, parameters "
       "(for tests that drive the window with real input)"},
      cli::plugin_dir_option_spec(),
  }));
  return s;
}
}  // namespace

std::string sandbox_help() {
  return cli::format_help(
      "penumbra-sandbox [--scene NAME|FILE] [--technique T] [--size WxH] [--script FILE]\n"
      "                        [--screenshot OUT.png] [--context glfw]\n"
      "                        [--camera C] [--light-dir X,Y,Z] [--light-size S] [--ground on|off]",
      "Interactive soft-shadow sandbox: swap and tune techniques live, inspect every graph\n"
      "resource, compare two techniques or a technique against the reference.\n"
      "Controls: WASD move, right mouse drag look, Shift faster, Space light = view direction,\n"
      "F12 screenshot, Esc closes the open list, the full-screen resource view or the compare split.\n"
      "Scripts: see docs/sandbox.md. Exit codes: 0 ok, 2 bad input, 1 internal.",
      specs());
}

namespace {
bool wants_help(const std::vector<std::string>& argv) {
  for (const std::string& a : argv)
    if (a == "--help" || a == "-h") return true;
  return false;
}
}  // namespace

Result<SandboxOptions> parse_sandbox_options(const std::vector<std::string>& argv) {
  SandboxOptions o;
  if (wants_help(argv)) {
    o.help = true;
    return o;
  }
  auto args = cli::parse_args(argv, specs());
  if (!args) return args.error();
  if (!args->positionals.empty())
    return make_error("unexpected argument '" + args->positionals[0] + "' (see --help)");
  if (auto v = args->get("scene")) o.scene = *v;
  if (auto v = args->get("technique")) o.technique = *v;
  if (auto v = args->get("size")) {
    auto size = cli::parse_size("size", *v, 8192);
    if (!size) return size.error();
    o.width = size->first;
    o.height = size->second;
  }
  if (auto v = args->get("shadow-size")) {
    auto n = cli::parse_int("shadow-size", *v, 16, 16384);
    if (!n) return n.error();
    o.shadow_size = *n;
  }
  auto cascades = cli::parse_cascade_options(*args);
  if (!cascades) return cascades.error();
  o.cascades = *cascades;
  auto staging = cli::parse_scene_options(*args);
  if (!staging) return staging.error();
  o.staging = staging->staging;
  if (auto v = args->get("script")) o.script = *v;
  if (auto v = args->get("screenshot")) o.screenshot = *v;
  if (auto v = args->get("context")) {
    if (*v != "glfw" && *v != "osmesa" && *v != "egl")
      return make_error("--context must be glfw, osmesa or egl, got '" + *v + "'");
    o.context = *v;
  }
  if (auto v = args->get("write-exhaustive-script")) o.exhaustive_script = *v;
  if (auto v = args->get("screenshot-dir")) o.screenshot_dir = *v;
  if (auto v = args->get("max-fps")) {
    auto n = cli::parse_int("max-fps", *v, 1, 1000);
    if (!n) return n.error();
    o.max_fps = *n;
  }
  if (auto v = args->get("state-file")) o.state_file = *v;
  o.plugin_dirs = args->all("plugin-dir");
  return o;
}

}  // namespace penumbra::sandbox
