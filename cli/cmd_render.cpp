// penumbra render: one frame of a technique on a scene, written as PNG (lit colour and/or the
// raw shadow_mask). With --all-techniques, one PNG per registered technique into --out-dir.
#include <cstdio>
#include <filesystem>

#include "cli/command.h"
#include "cli/context_option.h"
#include "cli/options/plugin_option.h"
#include "cli/options/cascade_option.h"
#include "cli/options/scene_option.h"
#include "gl/texture_png.h"
#include "measurement/progressive_render.h"
#include "technique/technique_session.h"
#include "techniques/builtin_techniques.h"
#include "util/file_write.h"
#include "util/output_batch.h"

namespace penumbra::cli {
namespace {

const std::vector<OptionSpec> kSpecs = with_cascade_options(with_scene_options({
    scene_name_option(),
    {"technique", true, false, "T", "technique name (default pcss if registered, else the first); see 'penumbra techniques'"},
    {"set", true, true, kAssignmentValueName, "set a technique parameter"},
    {"size", true, false, "WxH", "image size in pixels (default 640x360)"},
    {"shadow-size", true, false, "N", "shadow-map size in texels (default 2048)"},
    {"out", true, false, "OUT.png", "write the lit image"},
    {"mask", true, false, "MASK.png", "write the shadow_mask (grey, 1 = lit = white)"},
    {"all-techniques", false, false, "", "render every registered technique into --out-dir"},
    {"out-dir", true, false, "DIR", "directory for --all-techniques (default out)"},
    {"frames", true, false, "N", "frames to run before writing (progressive techniques; default 1)"},
    context_option_spec(),
    plugin_dir_option_spec(),
}));

int fail(const Error& e) { return report_failure("render", e); }

Status render_frames(technique::TechniqueSession& session, int frames) {
  for (int i = 0; i < frames; ++i)
    if (Status s = session.render(); !s) return s;
  return {};
}

// A progressive technique (one whose pass reports progress, as the reference's do) is written
// once its result is complete, with progress on stderr.
Status finish_progressive(technique::TechniqueSession& session) {
  if (!session.progress() || session.progress()->complete()) return {};
  return measurement::render_until_complete(session, 1000000, [&](const exec::PassProgress& p) {
    std::fprintf(stderr, "  %s (%s)\n", session.technique().c_str(), measurement::progress_text(p).c_str());
  });
}

// Staged in `batch`: --out and --mask, and every technique of --all-techniques, appear together
// once all rendered, or none does (util/output_batch.h).
Status write_outputs(technique::TechniqueSession& session, OutputBatch& batch, std::vector<std::string>& written,
                     const std::string& out, const std::string& mask) {
  for (const auto& [path, resource] : {std::pair{out, "color"}, std::pair{mask, "shadow_mask"}}) {
    if (path.empty()) continue;
    gl::Texture* texture = session.executor().resource(resource);
    if (!texture) return make_error(std::string("the frame has no '") + resource + "' resource", ErrorKind::internal);
    Result<std::string> tmp = batch.staged(path);
    if (!tmp) return batch.not_written(tmp.error());
    if (Status s = gl::write_texture_png(*texture, *tmp); !s) {
      Error e = s.error();
      e.file = path;
      return batch.not_written(e);
    }
    written.push_back(path);
  }
  return {};
}

int cmd_render(const std::vector<std::string>& argv) {
  if (help_requested(argv))
    return print_help("penumbra render --scene NAME|FILE [--technique T] [--set k=v]... "
                                    "[--size WxH] [--shadow-size N] [--out OUT.png] [--mask MASK.png]\n"
                                    "                       [--camera C] [--light-dir X,Y,Z] [--light-size S] [--ground on|off]",
                                    "Renders one frame of a shadow technique headless and writes PNGs.",
                                    kSpecs);
  auto args = parse_args(argv, kSpecs);
  if (!args) return fail(args.error());
  if (!args->positionals.empty()) return fail(make_error("unexpected argument '" + args->positionals[0] + "'"));
  int width = 640, height = 360, shadow = 2048, frames = 1;
  if (auto s = args->get("size")) {
    auto size = parse_size("size", *s);
    if (!size) return fail(size.error());
    std::tie(width, height) = *size;
  }
  if (auto s = args->get("shadow-size")) {
    auto n = parse_int("shadow-size", *s, 16, 16384);
    if (!n) return fail(n.error());
    shadow = *n;
  }
  Result<scene::CascadeSettings> cascades = parse_cascade_options(*args);
  if (!cascades) return fail(cascades.error());
  if (auto s = args->get("frames")) {
    auto n = parse_int("frames", *s, 1, 100000);
    if (!n) return fail(n.error());
    frames = *n;
  }
  bool all = args->has("all-techniques");
  std::string out = args->get("out").value_or(""), mask = args->get("mask").value_or("");
  if (!all && out.empty() && mask.empty()) out = "render.png";
  for (const std::string& path : {out, mask})  // before rendering, not after
    if (!all && !path.empty())
      if (Status s = check_output_path(path); !s) return fail(s.error());

  technique::TechniqueRegistry registry;
  if (Status s = register_all_techniques(registry, args->all("plugin-dir")); !s) return fail(s.error());
  std::vector<std::string> techniques;
  if (all) {
    techniques = registry.names();
  } else {
    std::string t = args->get("technique").value_or(registry.find("pcss") ? "pcss" : registry.names().front());
    if (!registry.find(t)) {
      std::string valid;
      for (const std::string& n : registry.names()) valid += (valid.empty() ? "" : ", ") + n;
      return fail(make_error("unknown technique '" + shortened(t) + "' (available: " + valid + ")"));
    }
    techniques = {t};
  }
  auto scene = load_scene_option(args->get("scene").value_or("showcase"), *args, width, height);
  if (!scene) return fail(scene.error());

  int code = 0;
  auto ctx = open_context(*args, "render", &code, 16, 16);
  if (!ctx) return code;
  exec::PassLibrary library = make_pass_library(registry);
  technique::TechniqueSession session(registry, library);
  session.set_scene(*scene);
  if (Status s = session.resize(width, height); !s) return fail(s.error());
  if (Status s = session.set_shadow_size(shadow); !s) return fail(s.error());
  if (Status s = session.set_cascades(*cascades); !s) return fail(s.error());

  std::string dir = args->get("out-dir").value_or("out");
  OutputBatch batch;
  std::vector<std::string> written;
  if (all)
    if (Status s = batch.create_directory(dir); !s) return fail(s.error());
  for (const std::string& t : techniques) {
    if (Status s = session.set_technique(t); !s) return fail(s.error());
    for (const std::string& kv : args->all("set"))
      if (Status s = session.set_param(kv); !s) {
        if (all) continue;  // a key of another technique
        Error e = s.error();
        e.where = "--set " + shortened(kv);
        return fail(e);
      }
    std::fprintf(stderr, "rendering %s on %s at %dx%d (shadow map %d)...\n", t.c_str(),
                 scene->name.c_str(), width, height, shadow);
    if (Status s = render_frames(session, frames); !s) return fail(s.error());
    if (Status s = finish_progressive(session); !s) return fail(s.error());
    std::string o = all ? dir + "/" + scene->name + "_" + t + ".png" : out;
    std::string m = all ? dir + "/" + scene->name + "_" + t + "_mask.png" : mask;
    if (Status s = write_outputs(session, batch, written, o, m); !s) return fail(s.error());
  }
  if (Status s = batch.commit(); !s) return fail(s.error());
  for (const std::string& path : written) std::printf("wrote %s\n", path.c_str());
  return 0;
}

const CommandRegistration reg{"render", "render a technique on a scene headless into PNGs", cmd_render};

}  // namespace
}  // namespace penumbra::cli
