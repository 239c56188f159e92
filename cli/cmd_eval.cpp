// penumbra eval: each technique's shadow_mask against a ground-truth reference of the same frame
// (same scene, camera, light, size), over receiver pixels, plus the technique's GPU time.
// Everything is computed before anything is written, so bad input or a failure leaves no
// partial JSON or heat map behind.
#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <optional>
#include <filesystem>
#include <fstream>

#include "cli/command.h"
#include "util/file_write.h"
#include "util/output_batch.h"
#include "cli/context_option.h"
#include "cli/options/plugin_option.h"
#include "measurement/eval_capture.h"
#include "measurement/eval_report.h"
#include "measurement/flicker_run.h"
#include "cli/options/cascade_option.h"
#include "cli/options/scene_option.h"
#include "measurement/reference_frame.h"
#include "measurement/technique_eval.h"
#include "measurement/technique_spec.h"
#include "metrics/heat_map.h"
#include "technique/frame_graph.h"
#include "techniques/builtin_techniques.h"

namespace penumbra::cli {
using namespace measurement;  // the measurements this command runs and reports
namespace {

// Heat maps show |technique - reference| / kHeatMapScale (white at 0.25 and above).
constexpr float kHeatMapScale = 0.25f;

const std::vector<OptionSpec> kSpecs = with_cascade_options(with_scene_options({
    scene_name_option(),
    {"techniques", true, false, "a,b:k=v,...", "techniques to evaluate, each with settings of its own (pmchss:variant=regular:k=2)"},
    {"reference", true, false, "raytraced|raster", "ground truth method (default raytraced)"},
    {"size", true, false, "WxH", "image size in pixels (default 640x360)"},
    {"shadow-size", true, false, "N", "techniques' shadow-map size in texels (default 2048)"},
    {"rays", true, false, "M", "raytraced reference: rays per pixel (default 256)"},
    {"samples", true, false, "N", "raster reference: light sample points / shadow maps (default 1024)"},
    {"frames", true, false, "N", "measured frames per technique for the median time (default 10)"},
    {"json", true, false, "OUT.json", "write the results as JSON"},
    {"heatmaps", true, false, "DIR", "write one error heat-map PNG per technique into DIR, and the frame's pixel classes (SCENE_classes.png)"},
    {"masks", true, false, "DIR", "write each technique's shadow mask and the reference's as grey PNGs into DIR"},
    {"set", true, true, kAssignmentValueName, "set a parameter of every listed technique (and the reference) that has it"},
    {"no-cache", false, false, "", "render the reference even when a cached one matches, and do not cache it"},
    {"flicker", true, false, "pan|light", "also measure temporal stability over a slow camera pan or light motion"},
    {"flicker-frames", true, false, "N", "frames of the --flicker motion (default 8; each needs a reference)"},
    {"flicker-step", true, false, "DEG|Npx", "--flicker motion per frame, degrees (default 0.25); pan: Npx turns the image centre by N pixels (1px: a wide band of pixels lands on pixel centres, for --flicker-match)"},
    {"flicker-match", true, false, "PX", "compare only pixels whose reprojection lands within PX (0.001-0.5) of a pixel centre, "
                                         "read without interpolation (default: bilinear, every pixel)"},
    context_option_spec(),
    plugin_dir_option_spec(),
}));

constexpr int kWarmupFrames = 3;

int fail(const Error& e) { return report_failure("eval", e); }

struct EvalOptions {
  std::string scene_name;
  scene::CascadeSettings cascades;
  std::vector<TechniqueSpec> techniques;
  std::string reference = "raytraced";
  int width = 640, height = 360, shadow = 2048, rays = 256, samples = 1024, frames = 10;
  bool use_cache = true;
  std::string json, heatmaps, masks;
  std::vector<std::string> sets;
  std::optional<FlickerSettings> flicker;
};

Result<EvalOptions> parse_eval_options(const ParsedArgs& args, const technique::TechniqueRegistry& registry) {
  EvalOptions o;
  if (!args.positionals.empty()) return make_error("unexpected argument '" + args.positionals[0] + "'");
  if (!args.get("scene")) return make_error("--scene NAME|FILE is required");
  o.scene_name = *args.get("scene");
  if (!args.get("techniques")) return make_error("--techniques a,b,c is required");
  auto specs = parse_technique_specs("techniques", *args.get("techniques"), registry);
  if (!specs) return specs.error();
  o.techniques = *specs;
  if (auto r = args.get("reference")) {
    if (*r != "raytraced" && *r != "raster")
      return make_error("--reference expects raytraced or raster, got '" + *r + "'");
    o.reference = *r;
  }
  if (auto s = args.get("size")) {
    auto size = parse_size("size", *s);
    if (!size) return size.error();
    std::tie(o.width, o.height) = *size;
  }
  struct IntOption { const char* name; int* value; int lo, hi; };
  for (const IntOption& i : {IntOption{"shadow-size", &o.shadow, 16, 16384}, IntOption{"rays", &o.rays, 1, 65536},
                             IntOption{"samples", &o.samples, 1, 65536}, IntOption{"frames", &o.frames, 1, 240}})
    if (auto s = args.get(i.name)) {
      auto n = parse_int(i.name, *s, i.lo, i.hi);
      if (!n) return n.error();
      *i.value = *n;
    }
  Result<scene::CascadeSettings> cascades = parse_cascade_options(args);
  if (!cascades) return cascades.error();
  o.cascades = *cascades;
  if (auto m = args.get("flicker")) {
    if (Status s = check_flicker_motion(*m); !s) return s.error();
    FlickerSettings f;
    f.motion = *m;
    if (auto n = args.get("flicker-frames")) {
      auto frames = parse_int("flicker-frames", *n, 2, 240);
      if (!frames) return frames.error();
      f.frames = *frames;
    }
    if (auto d = args.get("flicker-step")) {
      const bool pixels = d->size() > 2 && d->compare(d->size() - 2, 2, "px") == 0;
      if (pixels) {
        auto step = parse_real("flicker-step", d->substr(0, d->size() - 2), 0.05, 50.0);
        if (!step) return make_error("--flicker-step expects degrees in [0.001, 10] or pixels in [0.05, 50] written NNpx, got '" + shortened(*d) + "'");
        if (f.motion != "pan") return make_error("--flicker-step in pixels (" + shortened(*d) + ") needs --flicker pan");
        f.pixels_per_frame = static_cast<float>(*step);
      } else {
        auto step = parse_real("flicker-step", *d, 0.001, 10.0);
        if (!step) return make_error("--flicker-step expects degrees in [0.001, 10] or pixels in [0.05, 50] written NNpx, got '" + shortened(*d) + "'");
        f.degrees_per_frame = static_cast<float>(*step);
      }
    }
    if (auto d = args.get("flicker-match")) {
      auto within = parse_real("flicker-match", *d, 0.001, 0.5);
      if (!within) return within.error();
      f.reprojection.match_within = static_cast<float>(*within);
    }
    o.flicker = f;
  } else if (args.get("flicker-frames") || args.get("flicker-step") || args.get("flicker-match")) {
    return make_error("--flicker-frames, --flicker-step and --flicker-match need --flicker pan|light");
  }
  o.json = args.get("json").value_or("");
  o.heatmaps = args.get("heatmaps").value_or("");
  o.masks = args.get("masks").value_or("");
  // Odd places are refused before the reference is rendered, not after.
  if (!o.json.empty())
    if (Status s = check_output_path(o.json); !s) return s.error();
  for (const std::string& dir : {o.heatmaps, o.masks}) {
    std::error_code ec;
    if (!dir.empty() && std::filesystem::exists(dir, ec) && !std::filesystem::is_directory(dir, ec)) {
      Error e = make_error("is not a directory");
      e.file = dir;
      return e;
    }
  }
  o.use_cache = !args.has("no-cache");
  o.sets = args.all("set");
  std::vector<std::string> with_reference = technique_names(o.techniques);
  with_reference.push_back(kReferenceTechnique);
  if (Status s = check_set_keys(registry, with_reference, o.sets); !s) return s.error();
  return o;
}

// A row label as a file name: "pmchss:variant=regular" -> "pmchss-variant-regular".
std::string file_label(const std::string& label) {
  std::string out;
  for (char c : label) out += std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' ? c : '-';
  return out;
}

// Every output or none (util/output_batch.h): a report beside heat maps of another run misleads.
Status write_outputs(const EvalOptions& o, const EvalReport& report, const std::vector<metrics::MaskImage>& masks,
                     const metrics::MaskImage& reference, const metrics::CoverageMask& coverage,
                     const metrics::PixelClasses& classes) {
  OutputBatch out;
  std::vector<std::string> written;
  auto write = [&](const std::string& path, auto&& write_to) -> Status {
    Result<std::string> tmp = out.staged(path);
    if (!tmp) return out.not_written(tmp.error());
    if (Status s = write_to(*tmp); !s) {
      Error e = s.error();
      e.file = path;
      return out.not_written(e);
    }
    written.push_back(path);
    return {};
  };
  if (!o.heatmaps.empty()) {
    if (Status s = out.create_directory(o.heatmaps); !s) return out.not_written(s.error());
    // The pixels the statistics judged: receivers outside the light show as background.
    const metrics::CoverageMask judged = classes.classes.empty() ? coverage : metrics::judged_pixels(classes);
    for (size_t i = 0; i < masks.size(); ++i) {
      auto map = metrics::error_heat_map(masks[i], reference, judged, kHeatMapScale);
      if (!map) return map.error();
      const std::string path = o.heatmaps + "/" + report.scene + "_" + file_label(report.rows[i].technique) + "_error.png";
      if (Status s = write(path, [&](const std::string& tmp) { return metrics::write_png(tmp, *map); }); !s) return s;
    }
    if (!classes.classes.empty()) {  // what the penumbra and geometric-edge columns count
      const std::string path = o.heatmaps + "/" + report.scene + "_classes.png";
      const metrics::RgbaImage image = metrics::pixel_class_image(classes);
      if (Status s = write(path, [&](const std::string& tmp) { return metrics::write_png(tmp, image); }); !s) return s;
    }
  }
  if (!o.masks.empty()) {
    if (Status s = out.create_directory(o.masks); !s) return out.not_written(s.error());
    for (size_t i = 0; i <= masks.size(); ++i) {
      const bool is_reference = i == masks.size();
      const std::string path = o.masks + "/" + report.scene + "_" +
                               (is_reference ? std::string(kReferenceTechnique) : file_label(report.rows[i].technique)) + "_mask.png";
      const metrics::MaskImage& mask = is_reference ? reference : masks[i];
      if (Status s = write(path, [&](const std::string& tmp) { return metrics::write_png(tmp, mask); }); !s) return s;
    }
  }
  if (!o.json.empty()) {
    const std::string text = eval_report_json(report);
    if (Status s = write(o.json, [&](const std::string& tmp) { return write_file_whole(tmp, text); }); !s) return s;
  }
  if (Status s = out.commit(); !s) return s;
  for (const std::string& path : written) std::printf("wrote %s\n", path.c_str());
  return {};
}

// Each technique's temporal change over the motion, minus the reference's on the same frames, and
// its temporal error against the reference's frames.
Status measure_flicker(technique::TechniqueSession& session, const EvalOptions& o, EvalReport& report) {
  auto resolved = resolved_flicker(session, *o.flicker);
  if (!resolved) return resolved.error();
  const FlickerSettings& f = *resolved;
  std::fprintf(stderr, "flicker: %d frames of %s (%.4g deg/frame), reference...\n", f.frames, f.motion.c_str(),
               f.degrees_per_frame);
  auto reference = reference_motion_frames(session, {o.reference, o.rays, o.samples, o.sets, o.use_cache}, f);
  if (!reference) return reference.error();
  auto reference_change = metrics::temporal_change(*reference, f.reprojection);
  if (!reference_change) return reference_change.error();
  // A mean over no pixels would read as a perfectly steady mask.
  if (reference_change->pixels == 0) {
    char m[256];
    std::snprintf(m, sizeof m, "--flicker-match %.3g: no receiver pixel of the motion lands within %.3g px of a pixel centre "
                  "(%zu left out); a pan by whole pixels makes a wide band that does: --flicker-step 1px",
                  f.reprojection.match_within, f.reprojection.match_within, reference_change->unmatched);
    return make_error(m, ErrorKind::bad_input);
  }
  report.flicker_motion = f.motion;
  report.flicker_frames = f.frames;
  report.flicker_degrees_per_frame = f.degrees_per_frame;
  report.flicker_match = f.reprojection.match_within;
  report.flicker_reference = reference_change->mean_abs_change;
  report.flicker_pixels = reference_change->pixels;
  for (size_t i = 0; i < o.techniques.size(); ++i) {
    std::fprintf(stderr, "flicker: technique %s...\n", o.techniques[i].label.c_str());
    auto frames = technique_motion_frames(session, o.techniques[i], o.sets, f);
    if (!frames) return frames.error();
    auto change = metrics::temporal_change(*frames, f.reprojection);
    if (!change) return change.error();
    report.rows[i].temporal_change = change->mean_abs_change;
    report.rows[i].flicker = change->mean_abs_change - reference_change->mean_abs_change;
    auto error = metrics::temporal_error(*frames, *reference, f.reprojection);
    if (!error) return error.error();
    report.rows[i].temporal_error = error->mean_abs_change;
    report.rows[i].temporal_pixels = error->pixels;
  }
  return {};
}

int cmd_eval(const std::vector<std::string>& argv) {
  if (help_requested(argv))
    return print_help("penumbra eval --scene NAME|FILE --techniques a,b,c [--reference raytraced|raster] "
                                    "[--size WxH] [--shadow-size N] [--rays M] [--samples N] [--json OUT.json] "
                                    "[--heatmaps DIR] [--masks DIR] [--flicker pan|light [--flicker-match PX]] [--set k=v]...\n"
                                    "                     [--camera C] [--light-dir X,Y,Z] [--light-size S] [--ground on|off]",
                                    "Renders a ground-truth reference once, then each technique on the same frame,\n"
                                    "and compares shadow masks over receiver pixels (RMSE, MAE, max error, SSIM,\n"
                                    "edge error = mean |error| within 3 px of a reference edge) and times the\n"
                                    "technique's passes (median ms). Receivers are split into classes from the\n"
                                    "reference and the G-buffer: geometric edges (2 px of a depth or normal\n"
                                    "discontinuity or a self-shadowing terminator: their own RMSE column), the\n"
                                    "soft penumbra (0.02 < ref < 0.98 elsewhere: RMSE penumbra, marked * when it\n"
                                    "is under 1% of the receivers or mostly single pixels), lit and umbra;\n"
                                    "receivers outside a spot light's cone count in no statistic.\n"
                                    "Exact hard reference: --light-size 0 (one ray per pixel sample); add\n"
                                    "--set pixel_samples=4 for the pixel-box-filtered (anti-aliased) one.\n"
                                    "--flicker pan|light renders a slow motion and reports each technique's mean\n"
                                    "frame-to-frame change on the same surface points (reprojected with depth,\n"
                                    "disocclusions left out) minus the reference's: what the technique adds;\n"
                                    "and its temporal error (t-error): the mean per pixel of |its change - the\n"
                                    "reference's change|, zero only for a technique that changes as the truth does.\n"
                                    "Bilinear reprojection changes a sharp mask more than a blurred one; with\n"
                                    "--flicker-match 0.05 only pixels that land within 0.05 px of a pixel centre\n"
                                    "are compared, without that bias. See docs/evaluation.md.",
                                    kSpecs);
  auto args = parse_args(argv, kSpecs);
  if (!args) return fail(args.error());
  technique::TechniqueRegistry registry;
  if (Status s = register_all_techniques(registry, args->all("plugin-dir")); !s) return fail(s.error());
  auto options = parse_eval_options(*args, registry);
  if (!options) return fail(options.error());
  const EvalOptions& o = *options;
  auto scene = load_scene_option(o.scene_name, *args, o.width, o.height);
  if (!scene) return fail(scene.error());

  int code = 0;
  auto ctx = open_context(*args, "eval", &code, 16, 16);
  if (!ctx) return code;
  exec::PassLibrary library = make_pass_library(registry);
  technique::TechniqueSession session(registry, library);
  session.set_scene(*scene);
  if (Status s = session.resize(o.width, o.height); !s) return fail(s.error());
  if (Status s = session.set_shadow_size(o.shadow); !s) return fail(s.error());
  if (Status s = session.set_cascades(o.cascades); !s) return fail(s.error());

  std::fprintf(stderr, "reference (%s) on %s at %dx%d...\n", o.reference.c_str(), scene->name.c_str(), o.width, o.height);
  const auto t0 = std::chrono::steady_clock::now();
  auto reference = reference_frame(session, {o.reference, o.rays, o.samples, o.sets, o.use_cache});
  if (!reference) return fail(reference.error());
  std::fprintf(stderr, "reference (%s) %s in %.2f s\n", o.reference.c_str(),
               reference->from_cache ? ("read from the cache, " + reference->cache_file).c_str() : "done",
               std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());

  if (std::find(reference->coverage.begin(), reference->coverage.end(), uint8_t{1}) == reference->coverage.end()) {
    const scene::Camera& c = session.camera();
    const glm::vec3 f = c.forward();
    char where[200];
    std::snprintf(where, sizeof where, "the camera at (%g, %g, %g) looking along (%.3f, %.3f, %.3f)", c.position.x,
                  c.position.y, c.position.z, f.x, f.y, f.z);
    return fail(make_error(std::string(where) + " sees no surface of " + scene->name +
                               ": no receiver pixel to compare (choose another --camera, or `fit`)",
                           ErrorKind::bad_input));
  }

  EvalReport report{scene->name, o.reference, {}};
  std::vector<metrics::MaskImage> masks;
  metrics::PixelClasses classes;  // the frame's: the same for every technique
  for (const TechniqueSpec& t : o.techniques) {
    std::fprintf(stderr, "technique %s...\n", t.label.c_str());
    auto evaluated = evaluate_technique(session, t, o.sets, *reference, kWarmupFrames, o.frames, classes);
    if (!evaluated) return fail(evaluated.error());
    report.rows.push_back(evaluated->row);
    masks.push_back(std::move(evaluated->mask));
  }
  if (o.flicker) {
    if (Status s = measure_flicker(session, o, report); !s) return fail(s.error());
  }
  std::printf("scene %s, reference %s, %dx%d, %zu receiver pixels (%zu soft penumbra, %zu geometric edge)\n",
              report.scene.c_str(), o.reference.c_str(), o.width, o.height,
              report.rows.empty() ? size_t{0} : report.rows[0].errors.pixels,
              report.rows.empty() ? size_t{0} : report.rows[0].errors.penumbra_pixels,
              report.rows.empty() ? size_t{0} : report.rows[0].errors.geometric_edge_pixels);
  std::printf("%s", eval_report_table(report).c_str());
  std::printf("ms: median of %d frames of the technique's passes, timed with %s\n", o.frames,
              timing_mode_note(session).c_str());
  if (o.flicker) {
    const float match = o.flicker->reprojection.match_within;
    char how[96] = "bilinear reprojection";
    if (match > 0.0f) std::snprintf(how, sizeof how, "pixels that land within %.3g px of a centre", match);
    std::printf("flicker: mean |change| of the reprojected mask over a %d-frame %s (%.4g deg/frame; %s; %zu pixel "
                "pairs), minus the reference's (%.5f); t-error: mean |its change - the reference's| per pixel\n",
                o.flicker->frames, o.flicker->motion == "pan" ? "camera pan" : "light motion",
                report.flicker_degrees_per_frame, how, report.flicker_pixels, report.flicker_reference);
  }
  if (Status s = write_outputs(o, report, masks, reference->mask, reference->coverage, classes); !s)
    return fail(s.error());
  return 0;
}

const CommandRegistration reg{"eval", "compare techniques' shadow masks with a ground-truth reference", cmd_eval};

}  // namespace
}  // namespace penumbra::cli
