// The sandbox controller under OSMesa (no window): the same calls the ImGui widgets and script
// steps make, checked on a tiny technique of the tests' own.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <numeric>

#include "sandbox/controller.h"
#include "sandbox/param_applicability.h"
#include "sandbox/viewed_resource.h"
#include "technique/preset.h"
#include "util/file_write.h"
#include "image_stats.h"
#include "test_support/gl_context.h"
#include "test_support/temp_dir.h"
#include "techniques/builtin_techniques.h"
#include "tiny_technique.h"

namespace penumbra::sandbox {
namespace {

using sandbox_test::kTinyTechnique;

struct Fixture : ::testing::Test {
  Fixture() {
    test::gl_context();
    register_builtin_techniques(registry);
    sandbox_test::register_tiny_technique(registry);
    library = make_pass_library(registry);
  }
  void SetUp() override {
    controller = std::make_unique<SandboxController>(registry, library);
    ASSERT_TRUE(controller->session().set_shadow_size(256));
    Status s = controller->init("ball", kTinyTechnique, 96, 64);
    ASSERT_TRUE(s) << s.error().to_string();
  }
  std::vector<float> mask() {
    return controller->session().executor().resource("shadow_mask")->read();
  }
  std::filesystem::path temp(const std::string& name) {
    return test::temp_dir("sandbox") / name;
  }
  technique::TechniqueRegistry registry;
  exec::PassLibrary library;
  std::unique_ptr<SandboxController> controller;
};

// The resource viewer's read-backs: the histogram counts every texel, a PFM holds the viewed
// channel's floats bit for bit (rows bottom to top), a PNG the display's colours at the
// resource's size; both named after the resource and the frame.
TEST_F(Fixture, ViewedResourceHistogramAndSavedFiles) {
  ASSERT_TRUE(controller->view_resource("shadow_mask"));
  controller->viewer().map = ViewerSettings::Map::grey;
  ASSERT_TRUE(controller->render_frame());
  ASSERT_TRUE(update_histogram(*controller));
  const std::vector<float>& counts = controller->viewer().counts;
  ASSERT_EQ(counts.size(), size_t(kHistogramBins));
  EXPECT_EQ(std::accumulate(counts.begin(), counts.end(), 0.0f), 96.0f * 64.0f);
  const std::filesystem::path dir = test::fresh_temp_dir("viewed_resource");
  Result<std::string> pfm = save_viewed_resource(*controller, dir.string(), ViewFormat::pfm);
  ASSERT_TRUE(pfm) << pfm.error().to_string();
  EXPECT_EQ(std::filesystem::path(*pfm).filename(), "shadow_mask_frame" + std::to_string(controller->frames()) + ".pfm");
  std::ifstream in(*pfm, std::ios::binary);
  std::string magic, scale;
  int w = 0, h = 0;
  in >> magic >> w >> h >> scale;
  in.get();
  EXPECT_EQ(magic, "Pf");
  EXPECT_EQ(w, 96);
  EXPECT_EQ(h, 64);
  EXPECT_EQ(scale, "-1");
  std::vector<float> values(96 * 64);
  in.read(reinterpret_cast<char*>(values.data()), std::streamsize(values.size() * sizeof(float)));
  const std::vector<float> texels = mask();  // R16F: one channel, GL's rows
  EXPECT_EQ(values, texels);
  Result<std::string> png = save_viewed_resource(*controller, dir.string(), ViewFormat::png);
  ASSERT_TRUE(png) << png.error().to_string();
  const auto stats = sandbox_test::png_stats(*png);
  EXPECT_EQ(stats.width, 96);
  EXPECT_EQ(stats.height, 64);
  EXPECT_FALSE(save_viewed_resource(*controller, (dir / "absent").string(), ViewFormat::png));
  std::filesystem::remove_all(dir);
}

// A recorded orbit: one numbered image a frame, the first at the starting pose, the pose back
// afterwards; a bad spec records nothing.
TEST_F(Fixture, RecordedOrbitSavesNumberedFramesAndRestoresThePose) {
  const std::filesystem::path dir = test::fresh_temp_dir("sequence");
  ASSERT_TRUE(controller->render_frame());
  const std::string still = (dir / "still.png").string();
  ASSERT_TRUE(controller->save_presentation_png(still));
  const scene::Camera start = controller->camera();
  EXPECT_FALSE(controller->start_sequence({.frames = 3, .dir = (dir / "absent").string()}));
  EXPECT_FALSE(controller->recording());
  ASSERT_TRUE(controller->start_sequence({.path = SequenceSpec::Path::orbit, .frames = 4, .degrees = 90.0f, .dir = dir.string()}));
  for (int i = 0; i < 4; ++i) {
    EXPECT_TRUE(controller->recording()) << i;
    ASSERT_TRUE(controller->render_frame());
  }
  EXPECT_FALSE(controller->recording());
  EXPECT_EQ(controller->camera().position, start.position);
  EXPECT_EQ(controller->camera().yaw, start.yaw);
  for (int i = 0; i < 4; ++i) EXPECT_TRUE(std::filesystem::exists(dir / ("frame_000" + std::to_string(i) + ".png"))) << i;
  EXPECT_FALSE(std::filesystem::exists(dir / "frame_0004.png"));
  auto bytes = [](const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  EXPECT_EQ(bytes(dir / "frame_0000.png"), bytes(still));  // frame 0 is the starting pose
  EXPECT_NE(bytes(dir / "frame_0002.png"), bytes(still));
  EXPECT_NE(controller->sequence_note().find("recorded 4 frames"), std::string::npos);
  std::filesystem::remove_all(dir);
}

// A frame that cannot be saved (a folder sits where frame 2 goes) stops the sequence, names the
// frame and keeps none: frames 0 and 1 do not stay behind as half a sequence. A deliberate stop
// keeps the frames saved so far.
TEST_F(Fixture, AFailedSequenceFrameKeepsNoneAndAStopKeepsWhatWasSaved) {
  const std::filesystem::path dir = test::fresh_temp_dir("sequence_failed");
  std::filesystem::create_directories(dir / "frame_0002.png");
  ASSERT_TRUE(controller->start_sequence({.frames = 4, .dir = dir.string()}));
  ASSERT_TRUE(controller->render_frame());
  ASSERT_TRUE(controller->render_frame());
  Status third = controller->render_frame();
  ASSERT_FALSE(third);
  EXPECT_EQ(third.error().file, (dir / "frame_0002.png").string());
  EXPECT_NE(third.error().message.find("none of the outputs was written"), std::string::npos) << third.error().message;
  EXPECT_FALSE(controller->recording());
  const auto entries = [&] {
    return std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator());
  };
  EXPECT_EQ(entries(), 1) << "only the folder that was there";

  std::filesystem::remove_all(dir / "frame_0002.png");
  ASSERT_TRUE(controller->start_sequence({.frames = 4, .dir = dir.string()}));
  ASSERT_TRUE(controller->render_frame());
  ASSERT_TRUE(controller->render_frame());
  controller->stop_sequence();
  EXPECT_TRUE(std::filesystem::exists(dir / "frame_0000.png"));
  EXPECT_TRUE(std::filesystem::exists(dir / "frame_0001.png"));
  EXPECT_EQ(entries(), 2);
  std::filesystem::remove_all(dir);
}

// Three-way compare: A | B | reference; A and B are each measured against the third session, so
// a B equal to A has A's statistics exactly, and off frees the third session.
TEST_F(Fixture, ThreeWayCompareMeasuresAAndBAgainstTheReference) {
  ASSERT_TRUE(controller->set_compare(true, kTinyTechnique));
  ASSERT_TRUE(controller->set_three_way(true));
  ASSERT_NE(controller->reference_session(), nullptr);
  EXPECT_EQ(controller->reference_session()->technique(), "reference");
  EXPECT_EQ(controller->shown_sessions().size(), 3u);
  ASSERT_TRUE(controller->render_frame());
  controller->refresh_compare_stats();
  const CompareState& cs = controller->compare();
  ASSERT_TRUE(cs.stats && cs.stats_b) << cs.stats_error;
  EXPECT_EQ(cs.stats->rmse, cs.stats_b->rmse);
  EXPECT_GT(cs.stats->rmse, 0.0);  // the tiny technique's stripes are not the reference's shadows
  ASSERT_TRUE(controller->set_param("lit_level", "0"));  // A changes, B does not
  ASSERT_TRUE(controller->render_frame());
  controller->refresh_compare_stats();
  EXPECT_NE(cs.stats->rmse, cs.stats_b->rmse);
  const std::vector<int> edges = column_edges(cs, controller->width(), 3);
  EXPECT_EQ(edges, (std::vector<int>{0, 32, 64, 96}));  // three equal columns to start
  ASSERT_TRUE(controller->set_three_way(false));
  EXPECT_EQ(controller->reference_session(), nullptr);
  EXPECT_EQ(controller->shown_sessions().size(), 2u);
  EXPECT_TRUE(controller->render_frame());
}

TEST_F(Fixture, UniformChangeUpdatesTheValueWithoutRecompiling) {
  ASSERT_TRUE(controller->render_frame());
  const int compiles = controller->session().compile_count();
  ASSERT_TRUE(controller->set_param("lit_level", "0.25"));
  ASSERT_TRUE(controller->set_param_value("stripe_width", 4));
  ASSERT_TRUE(controller->set_param_value("pattern", std::string("checker")));
  EXPECT_EQ(controller->session().compile_count(), compiles);
  ASSERT_TRUE(controller->render_frame());
  // darken halves the level: 0.125 inside the cells (R16F holds it exactly), 0.5 elsewhere.
  std::vector<float> m = mask();
  EXPECT_NE(std::find(m.begin(), m.end(), 0.125f), m.end());
  EXPECT_EQ(std::find(m.begin(), m.end(), 0.25f), m.end());
}

TEST_F(Fixture, StructuralChangeRecompilesAndChangesThePlan) {
  const int compiles = controller->session().compile_count();
  ASSERT_TRUE(controller->set_param_value("darken", false));
  EXPECT_EQ(controller->session().compile_count(), compiles + 1);
  const auto& disabled = controller->session().plan().disabled;
  EXPECT_NE(std::find(disabled.begin(), disabled.end(), "darken"), disabled.end());
  ASSERT_TRUE(controller->render_frame());
  std::vector<float> m = mask();
  EXPECT_NE(std::find(m.begin(), m.end(), 0.5f), m.end());  // the undarkened level
}

TEST_F(Fixture, BadParameterIsAMessageAndChangesNothing) {
  const std::string before = controller->session().params().to_json();
  EXPECT_FALSE(controller->set_param("lit_level", "7"));
  EXPECT_FALSE(controller->set_param("no_such_param", "1"));
  EXPECT_NE(controller->message().find("no_such_param"), std::string::npos) << controller->message();
  EXPECT_EQ(controller->session().params().to_json(), before);
}

TEST_F(Fixture, ResetAllRestoresDefaults) {
  ASSERT_TRUE(controller->set_param("lit_level", "0.1"));
  ASSERT_TRUE(controller->set_param("darken", "false"));
  ASSERT_TRUE(controller->reset_param("all"));
  EXPECT_DOUBLE_EQ(controller->session().params().get_real("lit_level"), 0.5);
  EXPECT_TRUE(controller->session().params().get_bool("darken"));
}

TEST_F(Fixture, PresetRoundTripThroughFiles) {
  ASSERT_TRUE(controller->set_param("lit_level", "0.75"));
  ASSERT_TRUE(controller->set_param("pattern", "checker"));
  const std::string path = temp("preset.json").string();
  ASSERT_TRUE(controller->save_preset(path));
  const std::string saved = controller->session().params().to_json();
  ASSERT_TRUE(controller->reset_param("all"));
  ASSERT_NE(controller->session().params().to_json(), saved);
  Status s = controller->load_preset(path);
  ASSERT_TRUE(s) << s.error().to_string();
  EXPECT_EQ(controller->session().params().to_json(), saved);

  // Another technique's preset and a preset with an unknown key apply nothing.
  ASSERT_TRUE(controller->reset_param("all"));
  const std::string defaults = controller->session().params().to_json();
  ASSERT_TRUE(write_file_whole(path, R"({"technique": "pcss", "parameters": {"lit_level": 0.1}})"));
  EXPECT_FALSE(controller->load_preset(path));
  EXPECT_NE(controller->message().find("pcss"), std::string::npos);
  ASSERT_TRUE(write_file_whole(path, R"({"technique": "sandbox_tiny", "parameters": {"lit_level": 0.1, "x": 1}})"));
  EXPECT_FALSE(controller->load_preset(path));
  EXPECT_EQ(controller->session().params().to_json(), defaults);
  std::filesystem::remove(path);
}

TEST_F(Fixture, FailedSceneLoadKeepsThePreviousScene) {
  EXPECT_FALSE(controller->load_scene("/nonexistent/scene.gltf"));
  EXPECT_FALSE(controller->message().empty());
  EXPECT_EQ(controller->scene_name(), "ball");
  EXPECT_TRUE(controller->render_frame());
}

TEST_F(Fixture, ViewerKeepsTheResourceAliveAndShowsIt) {
  ASSERT_TRUE(controller->view_resource("raw_mask"));
  const auto& keep = controller->session().compile_options().keep_alive;
  EXPECT_EQ(keep, std::vector<std::string>{"raw_mask"});
  ASSERT_NE(controller->session().executor().resource("raw_mask"), nullptr);
  controller->viewer().placement = ViewerSettings::Placement::full;
  controller->viewer().map = ViewerSettings::Map::heat;
  ASSERT_TRUE(controller->render_frame());
  const std::string path = temp("viewer.png").string();
  ASSERT_TRUE(controller->save_presentation_png(path));
  auto stats = sandbox_test::png_stats(path);
  ASSERT_TRUE(stats.loaded);
  EXPECT_EQ(stats.width, 96);
  EXPECT_GT(stats.variance, 10.0);  // heat-mapped stripes
  // The view depth is in world units and gets a world-unit range (the z-buffer is linearised
  // with the camera's near/far to the same range).
  ASSERT_TRUE(controller->view_resource("gbuffer_depth"));
  EXPECT_GT(controller->viewer().max, controller->viewer().min);
  EXPECT_FLOAT_EQ(controller->viewer().min, controller->camera().near_plane);
  ASSERT_TRUE(controller->render_frame());
  ASSERT_TRUE(controller->view_resource(""));
  EXPECT_TRUE(controller->session().compile_options().keep_alive.empty());
  std::filesystem::remove(path);
}

TEST_F(Fixture, CompareSameSettingsHasZeroErrorAndDifferentHasSome) {
  controller->compare().stats_every = 1;
  ASSERT_TRUE(controller->set_compare(true, kTinyTechnique));
  ASSERT_NE(controller->secondary(), nullptr);
  ASSERT_TRUE(controller->render_frame());
  ASSERT_TRUE(controller->compare().stats.has_value()) << controller->compare().stats_error;
  EXPECT_EQ(controller->compare().stats->rmse, 0.0);
  EXPECT_GT(controller->compare().stats->pixels, 0u);

  // Primary at level 0 (then darkened: 0), secondary at the default 0.25 after darkening:
  // inside stripes |a - b| = 0.25, outside both are 0.5.
  ASSERT_TRUE(controller->set_param("lit_level", "0"));
  const int secondary_compiles = controller->secondary()->compile_count();
  ASSERT_TRUE(controller->render_frame());
  const auto& st = *controller->compare().stats;
  EXPECT_NEAR(st.max_error, 0.25, 1e-3);
  EXPECT_GT(st.rmse, 0.05);
  EXPECT_LT(st.rmse, 0.25);
  EXPECT_EQ(controller->secondary()->compile_count(), secondary_compiles);  // untouched

  // The error view is signed (A - B): A is darker in the stripes, so they are blue, and nothing
  // is red (A is nowhere lighter).
  controller->set_compare_view(CompareState::View::error);
  ASSERT_TRUE(controller->render_frame());
  const std::string path = temp("error.png").string();
  ASSERT_TRUE(controller->save_presentation_png(path));
  EXPECT_GT(sandbox_test::png_stats(path).variance, 10.0);
  int w = 0, h = 0, n = 0;
  unsigned char* px = stbi_load(path.c_str(), &w, &h, &n, 3);
  ASSERT_NE(px, nullptr);
  int blue = 0, red = 0;
  for (int i = 0; i < w * h; ++i) {
    blue += px[3 * i + 2] > px[3 * i] + 60;
    red += px[3 * i] > px[3 * i + 2] + 60;
  }
  stbi_image_free(px);
  EXPECT_GT(blue, w * h / 50);
  EXPECT_EQ(red, 0);
  std::filesystem::remove(path);

  ASSERT_TRUE(controller->set_compare(false));
  EXPECT_EQ(controller->secondary(), nullptr);
  EXPECT_TRUE(controller->render_frame());
}

// The error view's pixel classes: pcss against pcf on the ball, the classes computed from the
// primary's G-buffer and the right-hand mask (pcf's). The picture holds the classes' colours in
// the proportions the statistics counted: orange for the soft penumbra, blue for geometric edges.
TEST_F(Fixture, TheErrorViewShowsThePixelClassesTheStatisticsCount) {
  ASSERT_TRUE(controller->set_technique("pcss"));
  controller->compare().stats_every = 1;
  ASSERT_TRUE(controller->set_compare(true, "pcf"));
  controller->set_compare_view(CompareState::View::error);
  controller->compare().show_classes = true;
  ASSERT_TRUE(controller->render_frame());
  ASSERT_TRUE(controller->render_frame());  // the classes of the first read-back are drawn
  const CompareState& cs = controller->compare();
  ASSERT_TRUE(cs.stats.has_value()) << cs.stats_error;
  ASSERT_GT(cs.stats->geometric_edge_pixels, 0u) << "the ball's outline and the horizon";
  ASSERT_GT(cs.stats->penumbra_pixels, 0u);
  const std::string path = temp("classes.png").string();
  ASSERT_TRUE(controller->save_presentation_png(path));
  int w = 0, h = 0, n = 0;
  unsigned char* px = stbi_load(path.c_str(), &w, &h, &n, 3);
  ASSERT_NE(px, nullptr);
  size_t orange = 0, blue = 0;
  for (int i = 0; i < w * h; ++i) {
    const unsigned char r = px[3 * i], g = px[3 * i + 1], b = px[3 * i + 2];
    orange += r == 255 && g == 140 && b == 0;
    blue += r == 40 && g == 90 && b == 255;
  }
  stbi_image_free(px);
  std::filesystem::remove(path);
  EXPECT_EQ(orange, cs.stats->penumbra_pixels);
  EXPECT_EQ(blue, cs.stats->geometric_edge_pixels);
}

TEST_F(Fixture, UnknownTechniqueKeepsTheCurrentOne) {
  EXPECT_FALSE(controller->set_technique("no_such_technique"));
  EXPECT_EQ(controller->session().technique(), kTinyTechnique);
  EXPECT_NE(controller->message().find("sandbox_tiny"), std::string::npos);  // lists valid names
}

TEST_F(Fixture, DebugSwitchesRecompileAndStillRender) {
  ASSERT_TRUE(controller->set_no_reuse(true));
  EXPECT_TRUE(controller->session().plan().options.no_reuse);
  ASSERT_TRUE(controller->set_extended_lifetimes(true));
  controller->set_immediate(true);
  ASSERT_TRUE(controller->render_frame());
  EXPECT_GE(controller->session().plan().memory.assigned_bytes, controller->session().plan().memory.naive_bytes);
  ASSERT_TRUE(controller->set_no_reuse(false));
  ASSERT_TRUE(controller->set_extended_lifetimes(false));
  controller->set_immediate(false);
  EXPECT_TRUE(SandboxController::check_gl_errors("after debug switches"));
}

TEST_F(Fixture, LightAndCameraControls) {
  ASSERT_TRUE(controller->set_light_direction({0, -1, 0}));
  EXPECT_NEAR(glm::length(controller->light().direction), 1.0f, 1e-5f);
  EXPECT_FALSE(controller->set_light_size(-1.0f));
  ASSERT_TRUE(controller->set_light_size(0.2f));
  EXPECT_FLOAT_EQ(controller->light().size, 0.2f);
  ASSERT_TRUE(controller->align_light_with_camera());
  glm::vec3 f = controller->camera().forward();
  EXPECT_NEAR(glm::dot(controller->light().direction, f), 1.0f, 1e-4f);
  glm::vec3 p0 = controller->camera().position;
  controller->move_camera({0, 0, 1}, 0.5f, false);
  EXPECT_GT(glm::dot(controller->camera().position - p0, f), 0.0f);
  ASSERT_TRUE(controller->set_camera(glm::vec3(0, 3, 6), glm::vec3(0, 0, 0), std::nullopt, std::nullopt));
  EXPECT_LT(controller->camera().pitch, 0.0f);
  EXPECT_TRUE(controller->render_frame());
}

// A frozen light refuses every change, saying how to unfreeze, while the camera still moves.
TEST_F(Fixture, AFrozenLightStaysWhileTheCameraMoves) {
  const scene::Light before = controller->light();
  controller->set_light_frozen(true);
  const Status refused = controller->align_light_with_camera();
  ASSERT_FALSE(refused);
  EXPECT_NE(refused.error().message.find("freeze light"), std::string::npos);
  EXPECT_FALSE(controller->set_light_direction({1, -1, 0}));
  EXPECT_FALSE(controller->set_light_size(0.1f));
  EXPECT_FALSE(controller->set_light_type(scene::LightType::spot));
  const glm::vec3 p0 = controller->camera().position;
  controller->move_camera({1, 0, 0}, 0.5f, false);
  EXPECT_NE(controller->camera().position, p0);
  EXPECT_EQ(controller->light().direction, before.direction);
  EXPECT_EQ(controller->light().size, before.size);
  EXPECT_EQ(controller->light().type, before.type);
  controller->set_light_frozen(false);
  EXPECT_TRUE(controller->set_light_size(0.1f));
}

// The issue's examples on the real techniques: pcf's `samples` has no effect with the box
// kernel and does with vogel; the tiny technique's `darken` switch takes no parameter with it,
// but every parameter of every technique at its defaults either applies or says why not.
TEST_F(Fixture, ParametersWithoutEffectAreFoundFromTheGraph) {
  ASSERT_TRUE(controller->set_technique("pcf"));
  ASSERT_TRUE(controller->set_param("kernel", "box"));
  auto applies = [&](const std::string& name) {
    technique::TechniqueSession& s = controller->session();
    return param_applicability(*s.params().find(name), s.params(), s.graph(), s.plan());
  };
  const Applicability box = applies("samples");
  EXPECT_FALSE(box.applies);
  EXPECT_NE(box.reason.find("vogel"), std::string::npos) << box.reason;
  ASSERT_TRUE(controller->set_param("kernel", "vogel"));
  EXPECT_TRUE(applies("samples").applies);
  for (const std::string& t : controller->technique_names()) {
    if (t == "reference") continue;  // its methods compile Embree scenes: slow, and covered elsewhere
    ASSERT_TRUE(controller->set_technique(t)) << t;
    for (const graph::ParamDesc& d : controller->session().params().descs()) {
      const Applicability a = applies(d.name);
      EXPECT_TRUE(a.applies || !a.reason.empty()) << t << "." << d.name;
      if (!a.applies) std::printf("  %s.%s: %s\n", t.c_str(), d.name.c_str(), a.reason.c_str());
    }
  }
}

// The texel-density view: an 8x larger shadow map puts 8x more texels under each pixel, so
// the log2 heat moves from blue towards red.
TEST_F(Fixture, TexelDensityGrowsWithTheShadowMapSize) {
  controller->debug_views().texel_density = true;
  auto redness = [&](int shadow) {
    EXPECT_TRUE(controller->set_shadow_size(shadow));
    EXPECT_TRUE(controller->render_frame());
    const gl::Texture& t = controller->display().target();
    std::vector<unsigned char> px(static_cast<size_t>(t.width()) * t.height() * 4);
    glGetTextureImage(t.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, static_cast<GLsizei>(px.size()), px.data());
    double sum = 0.0;
    for (size_t i = 0; i < px.size(); i += 4) sum += double(px[i]) - double(px[i + 2]);
    return sum / double(px.size() / 4);
  };
  const double low = redness(32), high = redness(256);
  EXPECT_GT(high, low + 20.0) << "mean red - blue: 32 texels " << low << ", 256 texels " << high;
}

}  // namespace
}  // namespace penumbra::sandbox
