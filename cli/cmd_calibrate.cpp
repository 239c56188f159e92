// penumbra calibrate: fits a technique's free parameters to the ray-traced reference (mean
// penumbra RMSE over the fit scenes), writes the result as a preset, and reports it out of sample
// on the validation scenes. See docs/evaluation.md ("Calibration").
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "measurement/calibration.h"
#include "cli/command.h"
#include "cli/context_option.h"
#include "cli/options/plugin_option.h"
#include "measurement/eval_capture.h"
#include "measurement/reference_frame.h"
#include "cli/options/scene_option.h"
#include "measurement/technique_spec.h"
#include "metrics/mask_metrics.h"
#include "technique/frame_graph.h"
#include "technique/preset.h"
#include "techniques/builtin_techniques.h"
#include "util/file_write.h"
#include "passes/shared_passes.h"

namespace penumbra::cli {
using namespace measurement;  // the measurements this command runs and reports
namespace {

const std::vector<OptionSpec> kSpecs = {
    {"technique", true, false, "T[@preset][:k=v...]", "the technique to fit, with fixed settings of its own "
                                                      "(pmchss:variant=regular); the fit starts from its values"},
    {"scenes", true, false, "a,b", "scenes to fit on: built-in names or .gltf/.glb files"},
    {"params", true, false, "p1,p2", "float/int parameters to fit (default: its non-structural float "
                                     "parameters except *_bias)"},
    {"validate", true, false, "c,d", "scenes to report the fit on, out of sample"},
    {"baseline", true, false, "T", "a technique to report beside it on every scene (default pcss; 'none' for none)"},
    {"evals", true, false, "N", "most objective evaluations (default 60; each renders every fit scene)"},
    {"out", true, false, "PRESET.json", "write the fitted parameters as a preset (loadable by the sandbox, "
                                        "eval/bench T@PRESET.json)"},
    {"size", true, false, "WxH", "image size in pixels (default 480x270)"},
    {"shadow-size", true, false, "N", "shadow-map size in texels (default 2048)"},
    {"rays", true, false, "M", "reference rays per pixel (default 64)"},
    {"set", true, true, kAssignmentValueName, "set a parameter of the technique (and the reference) that has it"},
    {"no-cache", false, false, "", "render the references even when cached ones match"},
    context_option_spec(),
    plugin_dir_option_spec(),
};

// Frames rendered before the mask is read: the first compiles shaders, none is timed.
constexpr int kFramesPerEvaluation = 2;

int fail(const Error& e) { return report_failure("calibrate", e); }

struct CalibrateOptions {
  TechniqueSpec technique;
  std::optional<TechniqueSpec> baseline;
  std::vector<std::string> scenes, validate, params, sets;
  int width = 480, height = 270, shadow = 2048, rays = 64, evals = 60;
  std::string out;
  bool use_cache = true;
};

Result<CalibrateOptions> parse_options(const ParsedArgs& args, const technique::TechniqueRegistry& registry) {
  CalibrateOptions o;
  if (!args.positionals.empty()) return make_error("unexpected argument '" + args.positionals[0] + "'");
  if (!args.get("technique")) return make_error("--technique T is required");
  auto specs = parse_technique_specs("technique", *args.get("technique"), registry);
  if (!specs) return specs.error();
  if (specs->size() != 1) return make_error("--technique takes one technique (fit them one at a time)");
  o.technique = specs->front();
  if (o.technique.name == kReferenceTechnique) return make_error("--technique: the reference is what the fit aims at");
  const std::string baseline = args.get("baseline").value_or("pcss");
  if (baseline != "none") {
    auto b = parse_technique_specs("baseline", baseline, registry);
    if (!b) return b.error();
    if (b->size() != 1) return make_error("--baseline takes one technique");
    o.baseline = b->front();
  }
  if (!args.get("scenes")) return make_error("--scenes a,b is required");
  for (auto [option, list] : {std::pair{"scenes", &o.scenes}, {"validate", &o.validate}, {"params", &o.params}})
    if (auto s = args.get(option)) {
      auto items = split_list(option, *s);
      if (!items) return items.error();
      *list = *items;
    }
  if (auto s = args.get("size")) {
    auto size = parse_size("size", *s);
    if (!size) return size.error();
    std::tie(o.width, o.height) = *size;
  }
  struct IntOption { const char* name; int* value; int lo, hi; };
  for (const IntOption& i : {IntOption{"shadow-size", &o.shadow, 16, 16384}, IntOption{"rays", &o.rays, 1, 65536},
                             IntOption{"evals", &o.evals, 1, 10000}})
    if (auto s = args.get(i.name)) {
      auto n = parse_int(i.name, *s, i.lo, i.hi);
      if (!n) return n.error();
      *i.value = *n;
    }
  // The free parameters are checked now, before any reference is rendered.
  const technique::Technique* technique = registry.find(o.technique.name);
  auto graph = load_technique_graph(registry, *technique);
  if (!graph) return graph.error();
  if (auto space = free_params(graph::ParameterSet(graph->parameters), o.params); !space) return space.error();
  o.out = args.get("out").value_or("");
  o.use_cache = !args.has("no-cache");
  o.sets = args.all("set");
  std::vector<std::string> names = {o.technique.name, kReferenceTechnique};
  if (o.baseline) names.push_back(o.baseline->name);
  if (Status s = check_set_keys(registry, names, o.sets); !s) return s.error();
  return o;
}

// One scene with its own session, reference and the technique selected.
struct SceneRig {
  std::string name;
  bool validation = false;
  std::unique_ptr<technique::TechniqueSession> session;
  ReferenceFrame reference;
  metrics::PixelClasses classes;  // of the first frame rendered (the same G-buffer every frame)
  double start = 0.0, fitted = 0.0, baseline = -1.0;  // penumbra RMSE
};

// Over the soft penumbra, as `penumbra eval` reports it.
Result<double> penumbra_rmse(SceneRig& rig) {
  if (Status s = keep_alive(*rig.session, {"gbuffer_depth", "gbuffer_normal"}); !s) return s.error();
  for (int f = 0; f < kFramesPerEvaluation; ++f)
    if (Status s = rig.session->render(); !s) return s.error();
  gl::Texture* mask = rig.session->executor().resource(technique::kShadowMask);
  if (!mask) return make_error("the technique wrote no shadow_mask", ErrorKind::internal);
  if (Status s = frame_classes(*rig.session, rig.reference.mask, rig.reference.coverage, rig.classes); !s)
    return s.error();
  auto errors = metrics::compare_masks(read_mask_image(*mask), rig.reference.mask, rig.reference.coverage, rig.classes);
  if (!errors) return errors.error();
  if (errors->penumbra_pixels == 0)
    return make_error("scene '" + rig.name + "' has no soft penumbra in its reference (docs/evaluation.md, \"Pixel "
                      "classes\"): nothing to fit");
  return errors->rmse_penumbra;
}

Status set_values(SceneRig& rig, const std::vector<FreeParam>& space, const std::vector<double>& values) {
  for (size_t i = 0; i < space.size(); ++i)
    if (Status s = rig.session->set_param(space[i].desc.name, param_value(space[i], values[i])); !s) return s;
  return {};
}

std::string values_text(const std::vector<FreeParam>& space, const std::vector<double>& values) {
  std::string text;
  for (size_t i = 0; i < space.size(); ++i)
    text += (i ? " " : "") + space[i].desc.name + "=" + graph::param_value_to_string(param_value(space[i], values[i]));
  return text;
}

int cmd_calibrate(const std::vector<std::string>& argv) {
  if (help_requested(argv))
    return print_help(
        "penumbra calibrate --technique T[@preset][:k=v...] --scenes a,b [--params p1,p2] [--validate c,d] "
        "[--out PRESET.json] [--evals N] [--size WxH] [--shadow-size N] [--rays M] [--baseline T|none]",
        "Fits a technique's free parameters to the ray-traced reference: bounded Nelder-Mead (NLopt) on\n"
        "each parameter's range (log scale where it spans two decades), minimising the mean penumbra RMSE\n"
        "(pixels with 0.02 < reference < 0.98) over the fit scenes. Prints each evaluation, then the\n"
        "start and fitted RMSE on every fit and validation scene, beside the baseline's. References are\n"
        "cached (see eval). Example:\n"
        "  penumbra calibrate --technique pmchss --scenes ball,poles --validate colonnade,fence \\\n"
        "      --params shadow_filter_max_size,penumbra_kernel_scale --out pmchss.fitted.json",
        kSpecs);
  auto args = parse_args(argv, kSpecs);
  if (!args) return fail(args.error());
  technique::TechniqueRegistry registry;
  if (Status s = register_all_techniques(registry, args->all("plugin-dir")); !s) return fail(s.error());
  auto options = parse_options(*args, registry);
  if (!options) return fail(options.error());
  const CalibrateOptions& o = *options;

  std::vector<SceneRig> rigs;
  for (const auto& [list, validation] : {std::pair{&o.scenes, false}, {&o.validate, true}})
    for (const std::string& name : *list) {
      auto scene = load_scene_option(name);
      if (!scene) return fail(scene.error());
      rigs.push_back({name, validation, nullptr, {}});
    }

  int code = 0;
  auto ctx = open_context(*args, "calibrate", &code, 16, 16);
  if (!ctx) return code;
  exec::PassLibrary library = make_pass_library(registry);
  for (SceneRig& rig : rigs) {
    auto scene = load_scene_option(rig.name);
    if (!scene) return fail(scene.error());
    rig.session = std::make_unique<technique::TechniqueSession>(registry, library);
    rig.session->set_scene(*scene);
    if (Status s = rig.session->resize(o.width, o.height); !s) return fail(s.error());
    if (Status s = rig.session->set_shadow_size(o.shadow); !s) return fail(s.error());
    std::fprintf(stderr, "reference of %s at %dx%d...\n", rig.name.c_str(), o.width, o.height);
    auto reference = reference_frame(*rig.session, {"raytraced", o.rays, 1024, o.sets, o.use_cache});
    if (!reference) return fail(reference.error());
    rig.reference = std::move(*reference);
    if (o.baseline) {
      if (Status s = select_technique(*rig.session, *o.baseline, o.sets); !s) return fail(s.error());
      auto b = penumbra_rmse(rig);
      if (!b) return fail(b.error());
      rig.baseline = *b;
    }
    if (Status s = select_technique(*rig.session, o.technique, o.sets); !s) return fail(s.error());
  }

  auto space = free_params(rigs.front().session->params(), o.params);
  if (!space) return fail(space.error());
  std::vector<double> start;
  for (const FreeParam& p : *space) start.push_back(rigs.front().session->params().get_real(p.desc.name));
  std::fprintf(stderr, "fitting %s (%zu parameters) on %zu scene(s), at most %d evaluations\n",
               o.technique.label.c_str(), space->size(), o.scenes.size(), o.evals);

  // The objective: mean penumbra RMSE over the fit scenes.
  auto mean_rmse = [&](const std::vector<double>& values, bool validation) -> Result<double> {
    double sum = 0.0;
    int n = 0;
    for (SceneRig& rig : rigs) {
      if (rig.validation != validation) continue;
      if (Status s = set_values(rig, *space, values); !s) return s.error();
      auto e = penumbra_rmse(rig);
      if (!e) return e.error();
      sum += *e;
      ++n;
    }
    return n ? sum / n : 0.0;
  };
  auto fit = fit_nelder_mead(
      *space, start, [&](const std::vector<double>& v) { return mean_rmse(v, false); }, {.max_evaluations = o.evals},
      [&](const Evaluation& e) {
        std::fprintf(stderr, "  eval %3d/%d  %s  penumbra RMSE %.5f  (best %.5f)\n", e.index, o.evals,
                     values_text(*space, e.values).c_str(), e.objective, e.best);
      });
  if (!fit) return fail(fit.error());

  // Every scene, fit and validation, at the start point and at the fitted one.
  for (auto [values, field] : {std::pair{&start, &SceneRig::start}, {&fit->values, &SceneRig::fitted}})
    for (SceneRig& rig : rigs) {
      if (Status s = set_values(rig, *space, *values); !s) return fail(s.error());
      auto e = penumbra_rmse(rig);
      if (!e) return fail(e.error());
      rig.*field = *e;
    }

  std::printf("%s: %s after %d evaluations (%s)\n", o.technique.label.c_str(),
              values_text(*space, fit->values).c_str(), fit->evaluations, fit->stopped_because.c_str());
  std::printf("started from %s\n", values_text(*space, start).c_str());
  std::printf("penumbra RMSE at %dx%d, %d^2 shadow map, %d rays:\n", o.width, o.height, o.shadow, o.rays);
  std::printf("%-22s %-9s %9s %9s", "scene", "set", "start", "fitted");
  if (o.baseline) std::printf(" %12s %9s", o.baseline->label.c_str(), "fitted/it");
  std::printf("\n");
  for (const SceneRig& rig : rigs) {
    std::printf("%-22s %-9s %9.4f %9.4f", rig.name.c_str(), rig.validation ? "validate" : "fit", rig.start, rig.fitted);
    if (o.baseline) std::printf(" %12.4f %9.2f", rig.baseline, rig.baseline > 0 ? rig.fitted / rig.baseline : 0.0);
    std::printf("\n");
  }
  if (!o.out.empty()) {
    graph::ParameterSet fitted = rigs.front().session->params();
    if (Status s = write_file_whole(o.out, technique::format_preset(o.technique.name, fitted)); !s) return fail(s.error());
    std::printf("wrote %s\n", o.out.c_str());
  }
  return 0;
}

const CommandRegistration reg{"calibrate", "fit a technique's parameters to the ray-traced reference", cmd_calibrate};

}  // namespace
}  // namespace penumbra::cli
