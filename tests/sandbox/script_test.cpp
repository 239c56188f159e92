// Script parsing, its errors (which must name the step), the generated scripts and the command
// line (no window, no GL).
#include <gtest/gtest.h>

#include <filesystem>

#include "sandbox/options.h"
#include "sandbox/script.h"

namespace penumbra::sandbox {
namespace {

TEST(Script, ParsesEveryStepKind) {
  auto steps = parse_script(R"([
    {"scene": "ball"}, {"technique": "pcss"}, {"set": {"samples": 32, "use_blur": false, "light_size": 0.25,
     "kernel": "box"}}, {"reset": "all"},
    {"camera": {"position": [0, 2, 6], "yaw": 10, "pitch": -15}},
    {"light": {"type": "spot", "direction": [-1, -2, -1], "size": 0.3}}, {"shadow_size": 1024},
    {"wait": 3}, {"screenshot": "a.png"}, {"compare": true}, {"compare": "reference"},
    {"compare": {"view": "error", "classes": true}}, {"view": {"resource": "gbuffer_depth", "map": "heat", "placement": "full"}},
    {"resize": [320, 200]}, {"expect_no_gl_error": true}])", "s.json");
  ASSERT_TRUE(steps) << steps.error().to_string();
  ASSERT_EQ(steps->size(), 15u);
  const auto& s = *steps;
  EXPECT_EQ(s[0].kind, StepKind::scene);
  EXPECT_EQ(s[2].kind, StepKind::set);
  ASSERT_EQ(s[2].assignments.size(), 4u);
  EXPECT_EQ(s[2].assignments[0], (std::pair<std::string, std::string>{"samples", "32"}));
  EXPECT_EQ(s[2].assignments[1].second, "false");
  EXPECT_EQ(s[2].assignments[2].second, "0.25");
  EXPECT_EQ(s[2].assignments[3].second, "box");
  EXPECT_EQ(s[3].text, "all");
  EXPECT_FLOAT_EQ(s[4].camera.position->y, 2.0f);
  EXPECT_FLOAT_EQ(*s[4].camera.pitch_deg, -15.0f);
  EXPECT_EQ(*s[5].light.type, "spot");
  EXPECT_FLOAT_EQ(*s[5].light.size, 0.3f);
  EXPECT_EQ(s[6].number, 1024);
  EXPECT_EQ(s[7].number, 3);
  EXPECT_EQ(s[8].text, "a.png");
  EXPECT_TRUE(s[9].compare.enabled);
  EXPECT_EQ(s[10].compare.with, "reference");
  EXPECT_EQ(s[11].compare.view, "error");
  EXPECT_EQ(s[11].compare.classes, true);
  EXPECT_FALSE(s[10].compare.classes.has_value()) << "unchanged unless given";
  EXPECT_EQ(s[12].view.resource, "gbuffer_depth");
  EXPECT_EQ(s[12].view.placement, "full");
  EXPECT_EQ(s[13].width, 320);
  EXPECT_EQ(s[13].height, 200);
  EXPECT_EQ(s[14].kind, StepKind::expect_no_gl_error);
  for (size_t i = 0; i < s.size(); ++i) EXPECT_EQ(s[i].index, static_cast<int>(i));
}

TEST(Script, LightTypesIncludePoint) {
  auto steps = parse_script(R"([{"light": {"type": "point", "position": [0, 2, 0], "size": 0}}])", "s.json");
  ASSERT_TRUE(steps) << steps.error().to_string();
  EXPECT_EQ(*(*steps)[0].light.type, "point");
  EXPECT_FLOAT_EQ((*steps)[0].light.position->y, 2.0f);
}

// Every bad step is reported with its index, the file, and what was expected.
struct BadScript {
  const char* text;
  const char* must_contain;
};

class ScriptErrors : public ::testing::TestWithParam<BadScript> {};

TEST_P(ScriptErrors, NameTheStep) {
  auto r = parse_script(GetParam().text, "bad.json");
  ASSERT_FALSE(r);
  const std::string msg = r.error().to_string();
  EXPECT_NE(msg.find("bad.json"), std::string::npos) << msg;
  EXPECT_NE(msg.find(GetParam().must_contain), std::string::npos) << msg;
  EXPECT_EQ(r.error().exit_code(), 2);
}

INSTANTIATE_TEST_SUITE_P(
    Sandbox, ScriptErrors,
    ::testing::Values(
        BadScript{R"([{"wait": 1}, {"jump": 3}])", "step 1: unknown step 'jump'"},
        BadScript{R"([{"wait": 0}])", "step 0: wait (frames) must be in [1, 100000]"},
        BadScript{R"([{"wait": 1}, {"wait": 1}, {"resize": [10]}])", "step 2: resize must be [width, height]"},
        BadScript{R"([{"technique": 3}])", "step 0: technique must be a string"},
        BadScript{R"([{"wait": 1, "technique": "x"}])", "step 0: each step must be an object with exactly one key"},
        BadScript{R"([{"camera": {"position": [1, 2]}}])", "step 0: camera.position must be an array of 3 numbers"},
        BadScript{R"([{"camera": {"roll": 3}}])", "step 0: camera: unknown key 'roll'"},
        BadScript{R"([{"light": {"type": "area"}}])", "step 0: light.type must be \"directional\", \"spot\" or \"point\""},
        BadScript{R"([{"light": {"size": -1}}])", "step 0: light.size must be >= 0"},
        BadScript{R"([{"set": {}}])", "step 0: set must be a non-empty object"},
        BadScript{R"([{"set": {"k": [1]}}])", "step 0: set: value of 'k' must be a boolean, number or string"},
        BadScript{R"([{"compare": {"view": "side"}}])", "step 0: compare.view must be"},
        BadScript{R"([{"compare": {"classes": "yes"}}])", "compare.classes"},
        BadScript{R"([{"expect_no_gl_error": false}])", "step 0: expect_no_gl_error must be true"},
        BadScript{R"([{"ground": "yes"}])", "step 0: ground must be true or false"},
        BadScript{R"([{"camera": "orbit"}])", "step 0: camera must be \"fit\", \"file\""},
        BadScript{R"({"wait": 1})", "must be a JSON array"},
        BadScript{R"([{"wait": 1},)", "not valid JSON"}));

TEST(Script, RuntimeErrorsUseTheSameWords) {
  auto steps = parse_script(R"([{"wait": 1}, {"technique": "nope"}])", "s.json");
  ASSERT_TRUE(steps);
  Error e = step_error((*steps)[1], "unknown technique 'nope'");
  EXPECT_NE(e.to_string().find("script step 1 (technique): unknown technique 'nope'"), std::string::npos)
      << e.to_string();
}

std::vector<TechniqueInfo> two_techniques() {
  using graph::ParamType;
  return {{"a", {{.name = "r", .type = ParamType::real, .default_value = 0.5, .min = 0.0, .max = 2.0},
                 {.name = "b", .type = ParamType::boolean, .default_value = true, .structural = true}}},
          {"b", {{.name = "k", .type = ParamType::enumeration, .default_value = std::string("x"),
                  .options = {"x", "y"}},
                 {.name = "n", .type = ParamType::integer, .default_value = 3}}}};
}

TEST(Script, ExhaustiveScriptVisitsMinMaxDefaultOfEveryParameter) {
  // Screenshot directories must exist when the script is read: use one that does.
  const std::string dir = ::testing::TempDir();
  std::string text = exhaustive_script(two_techniques(), dir + "shots", 480, 320, 512);
  std::filesystem::create_directories(dir + "shots");
  auto steps = parse_script(text, "generated");
  ASSERT_TRUE(steps) << steps.error().to_string();
  std::vector<std::string> sets, techniques, shots;
  for (const ScriptStep& s : *steps) {
    if (s.kind == StepKind::set) sets.push_back(s.assignments[0].first + "=" + s.assignments[0].second);
    if (s.kind == StepKind::technique) techniques.push_back(s.text);
    if (s.kind == StepKind::screenshot) shots.push_back(s.text);
  }
  EXPECT_EQ(techniques, (std::vector<std::string>{"a", "b"}));
  EXPECT_EQ(sets, (std::vector<std::string>{"r=0.0", "r=2.0", "r=0.5", "b=false", "b=true", "b=true", "k=x",
                                            "k=y", "k=x", "n=7", "n=3"}));
  const std::string d = dir + "shots/";
  EXPECT_EQ(shots, (std::vector<std::string>{d + "a.png", d + "a_compare.png", d + "b.png", d + "b_compare.png"}));
}

TEST(Script, SoakScriptIsReproducibleAndParses) {
  std::string a = soak_script(two_techniques(), 7, 500, 128);
  EXPECT_EQ(a, soak_script(two_techniques(), 7, 500, 128));
  EXPECT_NE(a, soak_script(two_techniques(), 8, 500, 128));
  auto steps = parse_script(a, "soak");
  ASSERT_TRUE(steps) << steps.error().to_string();
  EXPECT_EQ(steps->size(), 500u);
  int resizes = 0, swaps = 0, sets = 0;
  for (const ScriptStep& s : *steps) {
    resizes += s.kind == StepKind::resize;
    swaps += s.kind == StepKind::technique;
    sets += s.kind == StepKind::set;
    if (s.kind == StepKind::resize) {
      EXPECT_GE(s.width, 16);
      EXPECT_LE(s.width, 128);
    }
  }
  EXPECT_GT(resizes, 10);
  EXPECT_GT(swaps, 10);
  EXPECT_GT(sets, 100);
}

TEST(Options, ParsesTheDocumentedCommandLine) {
  auto o = parse_sandbox_options({"--scene", "ball", "--technique", "pcss", "--size", "480x320", "--script",
                                  "s.json", "--screenshot", "o.png", "--context", "glfw"});
  ASSERT_TRUE(o) << o.error().to_string();
  EXPECT_EQ(o->scene, "ball");
  EXPECT_EQ(o->technique, "pcss");
  EXPECT_EQ(o->width, 480);
  EXPECT_EQ(o->height, 320);
  EXPECT_EQ(o->script, "s.json");
  EXPECT_EQ(o->screenshot, "o.png");
  EXPECT_TRUE(parse_sandbox_options({"--help"})->help);
  EXPECT_NE(sandbox_help().find("--script FILE"), std::string::npos);
}

TEST(Script, GroundAndCameraChoiceSteps) {
  auto steps = parse_script(R"([{"ground": false}, {"camera": "fit"}, {"camera": "file:front"}])", "s.json");
  ASSERT_TRUE(steps) << steps.error().to_string();
  ASSERT_EQ(steps->size(), 3u);
  EXPECT_EQ((*steps)[0].kind, StepKind::ground);
  EXPECT_FALSE((*steps)[0].flag);
  EXPECT_EQ((*steps)[1].camera.choice, "fit");
  EXPECT_EQ((*steps)[2].camera.choice, "file:front");
  EXPECT_FALSE((*steps)[2].camera.position);
}

TEST(Script, InspectAndViewZoomSteps) {
  auto steps = parse_script(R"([{"view": {"resource": "shadow_mask", "zoom": 4, "center": [0.25, 0.5], "auto_range": true}},
                               {"inspect": {"at": [10, 20], "out": "p.json"}}, {"metrics": "m.json"}])", "s.json");
  ASSERT_TRUE(steps) << steps.error().to_string();
  EXPECT_EQ(*(*steps)[0].view.zoom, 4.0f);
  EXPECT_EQ(*(*steps)[0].view.center, glm::vec2(0.25f, 0.5f));
  EXPECT_TRUE(*(*steps)[0].view.auto_range);
  EXPECT_EQ((*steps)[1].kind, StepKind::inspect);
  EXPECT_EQ((*steps)[1].inspect.x, 10);
  EXPECT_EQ((*steps)[1].inspect.y, 20);
  EXPECT_EQ((*steps)[1].inspect.out, "p.json");
  EXPECT_EQ((*steps)[2].kind, StepKind::metrics);
  EXPECT_FALSE(parse_script(R"([{"view": {"zoom": 100}}])", "s.json"));
  EXPECT_FALSE(parse_script(R"([{"inspect": {"at": [1, 2]}}])", "s.json"));
  EXPECT_FALSE(parse_script(R"([{"metrics": ""}])", "s.json"));
}

TEST(Script, SaveViewAndChannelSteps) {
  auto steps = parse_script(R"([{"view": {"resource": "color", "map": "signed", "channels": "ra"}},
                               {"save_view": {"format": "pfm", "dir": "."}}, {"save_view": {"format": "png"}}])", "s.json");
  ASSERT_TRUE(steps) << steps.error().to_string();
  EXPECT_EQ((*steps)[0].view.map, "signed");
  EXPECT_EQ(*(*steps)[0].view.channel_mask, 0x9u);
  EXPECT_EQ((*steps)[1].kind, StepKind::save_view);
  EXPECT_EQ((*steps)[1].format, "pfm");
  EXPECT_EQ((*steps)[2].text, ".");
  for (const char* bad : {R"([{"save_view": {"format": "exr"}}])", R"([{"save_view": {"format": "png", "dir": "no/such/dir"}}])",
                          R"([{"save_view": {"format": "png", "path": "x.png"}}])", R"([{"view": {"channels": "rgbx"}}])",
                          R"([{"view": {"channels": ""}}])", R"([{"view": {"map": "rainbow"}}])"}) {
    auto s = parse_script(bad, "s.json");
    EXPECT_FALSE(s) << bad;
  }
}

TEST(Script, RecordStep) {
  auto steps = parse_script(R"([{"record": {"frames": 12, "path": "light", "degrees": -90, "dir": "."}}])", "s.json");
  ASSERT_TRUE(steps) << steps.error().to_string();
  EXPECT_EQ((*steps)[0].kind, StepKind::record);
  EXPECT_EQ((*steps)[0].sequence.frames, 12);
  EXPECT_EQ((*steps)[0].sequence.path, SequenceSpec::Path::light);
  EXPECT_EQ((*steps)[0].sequence.degrees, -90.0f);
  for (const char* bad : {R"([{"record": {"frames": 0, "dir": "."}}])", R"([{"record": {"path": "spiral", "dir": "."}}])",
                          R"([{"record": {"frames": 3}}])", R"([{"record": {"frames": 3, "dir": "no/such"}}])",
                          R"([{"record": {"frames": 3, "dir": ".", "degrees": 99999}}])", R"([{"record": {"fps": 3, "dir": "."}}])"})
    EXPECT_FALSE(parse_script(bad, "s.json")) << bad;
}

TEST(Options, SceneStagingOptionsAreTheClis) {
  auto o = parse_sandbox_options({"--camera", "1,2,3:0,0,0", "--light-dir", "0,-2,0", "--light-size", "0.5",
                                  "--ground", "off"});
  ASSERT_TRUE(o) << o.error().to_string();
  EXPECT_EQ(o->staging.camera.kind, scene::CameraChoice::Kind::pose);
  EXPECT_EQ(o->staging.camera.position, glm::vec3(1, 2, 3));
  EXPECT_EQ(*o->staging.light_direction, glm::vec3(0, -1, 0));
  EXPECT_FLOAT_EQ(*o->staging.light_size, 0.5f);
  EXPECT_FALSE(o->staging.ground);
  EXPECT_TRUE(parse_sandbox_options({})->staging.ground) << "the ground plane is on by default";
  EXPECT_FALSE(parse_sandbox_options({"--ground", "maybe"}));
  EXPECT_FALSE(parse_sandbox_options({"--light-dir", "0,0,0"}));
  EXPECT_NE(sandbox_help().find("--ground"), std::string::npos);
}

TEST(Options, BadInputIsAnError) {
  EXPECT_FALSE(parse_sandbox_options({"--size", "480"}));
  EXPECT_FALSE(parse_sandbox_options({"--context", "vulkan"}));
  EXPECT_FALSE(parse_sandbox_options({"--frobnicate"}));
  EXPECT_FALSE(parse_sandbox_options({"stray"}));
}

}  // namespace
}  // namespace penumbra::sandbox
