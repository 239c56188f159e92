// Preset round trip and all-or-nothing rejection (no window, no GL).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "sandbox/user_presets.h"
#include "technique/preset.h"
#include "test_support/temp_dir.h"

namespace penumbra::sandbox {
namespace {

using graph::ParamDesc;
using graph::ParameterSet;
using graph::ParamType;

ParameterSet pcss_like() {
  return ParameterSet({
      {.name = "light_size", .type = ParamType::real, .default_value = 0.5, .min = 0.0, .max = 10.0},
      {.name = "samples", .type = ParamType::integer, .default_value = 16, .min = 1, .max = 64},
      {.name = "use_blur", .type = ParamType::boolean, .default_value = true, .structural = true},
      {.name = "kernel", .type = ParamType::enumeration, .default_value = std::string("vogel"),
       .options = {"box", "vogel"}},
  });
}

TEST(Preset, SaveThenLoadGivesTheSameValues) {
  ParameterSet saved = pcss_like();
  ASSERT_TRUE(saved.set("light_size", 2.25));
  ASSERT_TRUE(saved.set("samples", 40));
  ASSERT_TRUE(saved.set("use_blur", false));
  ASSERT_TRUE(saved.set("kernel", std::string("box")));
  std::string text = technique::format_preset("pcss", saved);

  auto preset = technique::parse_preset(text, "soft.json");
  ASSERT_TRUE(preset) << preset.error().to_string();
  EXPECT_EQ(preset->technique, "pcss");
  auto loaded = technique::preset_applied(*preset, "pcss", pcss_like());
  ASSERT_TRUE(loaded) << loaded.error().to_string();
  EXPECT_DOUBLE_EQ(loaded->get_real("light_size"), 2.25);
  EXPECT_EQ(loaded->get_int("samples"), 40);
  EXPECT_FALSE(loaded->get_bool("use_blur"));
  EXPECT_EQ(loaded->get_enum("kernel"), "box");
  EXPECT_EQ(loaded->to_json(), saved.to_json());
}

TEST(Preset, PresetForAnotherTechniqueIsRejected) {
  auto preset = technique::parse_preset(R"({"technique": "pcf", "parameters": {"samples": 4}})", "p.json");
  ASSERT_TRUE(preset);
  ParameterSet current = pcss_like();
  auto r = technique::preset_applied(*preset, "pcss", current);
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().message.find("'pcf'"), std::string::npos) << r.error().message;
  EXPECT_NE(r.error().message.find("'pcss'"), std::string::npos) << r.error().message;
}

TEST(Preset, UnknownKeyRejectsTheWholePreset) {
  // samples alone would be fine; the unknown key must stop it from being applied partially.
  auto preset = technique::parse_preset(R"({"technique": "pcss", "parameters": {"samples": 4, "bogus": 1}})", "p.json");
  ASSERT_TRUE(preset);
  ParameterSet current = pcss_like();
  const std::string before = current.to_json();
  auto r = technique::preset_applied(*preset, "pcss", current);
  ASSERT_FALSE(r);
  EXPECT_NE(r.error().to_string().find("bogus"), std::string::npos) << r.error().to_string();
  EXPECT_EQ(current.to_json(), before);
}

TEST(Preset, OutOfRangeValueRejectsTheWholePreset) {
  auto preset = technique::parse_preset(R"({"technique": "pcss", "parameters": {"use_blur": false, "samples": 1000}})",
                             "p.json");
  ASSERT_TRUE(preset);
  EXPECT_FALSE(technique::preset_applied(*preset, "pcss", pcss_like()));
}

TEST(Preset, MalformedPresetsNameTheProblem) {
  auto not_json = technique::parse_preset("{", "a.json");
  ASSERT_FALSE(not_json);
  EXPECT_EQ(not_json.error().file, "a.json");
  auto no_technique = technique::parse_preset(R"({"parameters": {}})", "b.json");
  ASSERT_FALSE(no_technique);
  EXPECT_NE(no_technique.error().message.find("technique"), std::string::npos);
  auto extra = technique::parse_preset(R"({"technique": "x", "parameters": {}, "extra": 1})", "c.json");
  ASSERT_FALSE(extra);
  EXPECT_NE(extra.error().message.find("extra"), std::string::npos);
}

}  // namespace
}  // namespace penumbra::sandbox

// The sandbox's own preset folder: listed per technique, names checked.
namespace {
TEST(UserPresets, ListedPerTechniqueAndNamesChecked) {
  namespace fs = std::filesystem;
  const fs::path dir = penumbra::test::fresh_temp_dir("user_presets");
  EXPECT_TRUE(penumbra::sandbox::user_presets(dir, "pcss").empty());  // no folder yet
  fs::create_directories(dir / "pcss");
  fs::create_directories(dir / "pcf");
  for (const char* f : {"pcss/soft.json", "pcss/a-1.json", "pcss/notes.txt", "pcf/other.json"}) std::ofstream(dir / f) << "{}";
  EXPECT_EQ(penumbra::sandbox::user_presets(dir, "pcss"), (std::vector<std::string>{"a-1", "soft"}));
  auto ok = penumbra::sandbox::user_preset_path(dir, "pcss", "my_look.v2");
  ASSERT_TRUE(ok);
  EXPECT_EQ(*ok, dir / "pcss" / "my_look.v2.json");
  for (const char* bad : {"", "../x", "a/b", ".hidden", "two words"})
    EXPECT_FALSE(penumbra::sandbox::user_preset_path(dir, "pcss", bad)) << bad;
  fs::remove_all(dir);
}
}  // namespace
