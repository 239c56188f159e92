// ParameterSet: the single description every consumer reads.
#include <gtest/gtest.h>

#include "graph/parameters.h"

namespace penumbra::graph {
namespace {

ParameterSet make_params() {
  return ParameterSet({
      {.name = "radius", .type = ParamType::integer, .default_value = 4, .min = 1, .max = 16,
       .unit = "texels", .description = "Blur radius"},
      {.name = "light_size", .type = ParamType::real, .default_value = 0.5, .min = 0.0,
       .max = 10.0, .unit = "world units", .description = "Light radius"},
      {.name = "use_blur", .type = ParamType::boolean, .default_value = true,
       .description = "Blur the mask", .structural = true},
      {.name = "kernel", .type = ParamType::enumeration, .default_value = std::string("vogel"),
       .description = "Tap pattern", .options = {"box", "vogel", "poisson"}},
  });
}

TEST(ParameterSet, DefaultsAndSetFromString) {
  ParameterSet p = make_params();
  EXPECT_EQ(p.get_int("radius"), 4);
  ASSERT_TRUE(p.set_from_string("radius=7"));
  ASSERT_TRUE(p.set_from_string("light_size=1.25"));
  ASSERT_TRUE(p.set_from_string("use_blur=false"));
  ASSERT_TRUE(p.set_from_string("kernel=box"));
  EXPECT_EQ(p.get_int("radius"), 7);
  EXPECT_DOUBLE_EQ(p.get_real("light_size"), 1.25);
  EXPECT_FALSE(p.get_bool("use_blur"));
  EXPECT_EQ(p.get_enum("kernel"), "box");
  p.reset("radius");
  EXPECT_EQ(p.get_int("radius"), 4);
  p.reset_all();
  EXPECT_TRUE(p.get_bool("use_blur"));
}

TEST(ParameterSet, UnknownKeyListsValidKeys) {
  ParameterSet p = make_params();
  Status s = p.set_from_string("raduis=3");
  ASSERT_FALSE(s);
  const std::string m = s.error().message;
  EXPECT_NE(m.find("raduis"), std::string::npos) << m;
  for (const char* k : {"radius", "light_size", "use_blur", "kernel"}) EXPECT_NE(m.find(k), std::string::npos) << m;
}

TEST(ParameterSet, OutOfRangePrintsTheRange) {
  ParameterSet p = make_params();
  Status s = p.set_from_string("radius=99");
  ASSERT_FALSE(s);
  EXPECT_NE(s.error().message.find("[1, 16] texels"), std::string::npos) << s.error().message;
  EXPECT_EQ(p.get_int("radius"), 4);
  EXPECT_FALSE(p.set_from_string("radius=99999999999999999999"));
  EXPECT_FALSE(p.set_from_string("light_size=-0.1"));
}

TEST(ParameterSet, WrongTypeAndBadSyntax) {
  ParameterSet p = make_params();
  Status s = p.set_from_string("radius=2.5");
  ASSERT_FALSE(s);
  EXPECT_NE(s.error().message.find("int"), std::string::npos);
  EXPECT_FALSE(p.set_from_string("use_blur=maybe"));
  EXPECT_FALSE(p.set_from_string("kernel=gaussian"));
  EXPECT_FALSE(p.set_from_string("radius"));
  EXPECT_FALSE(p.set_from_string("=3"));
  EXPECT_FALSE(p.set_from_string("light_size=nan"));
  EXPECT_FALSE(p.set("radius", std::string("3")));
}

TEST(ParameterSet, JsonApplyIsAllOrNothing) {
  ParameterSet p = make_params();
  Status bad = p.apply_json(R"({"radius": 8, "light_size": 50.0, "nope": 1})");
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().message.find("light_size"), std::string::npos);
  EXPECT_NE(bad.error().message.find("nope"), std::string::npos);
  EXPECT_EQ(p.get_int("radius"), 4) << "a valid key was applied although another failed";
  ASSERT_TRUE(p.apply_json(R"({"radius": 8, "light_size": 2, "kernel": "poisson"})"));
  EXPECT_EQ(p.get_int("radius"), 8);
  EXPECT_DOUBLE_EQ(p.get_real("light_size"), 2.0);
  EXPECT_FALSE(p.apply_json("[1, 2]"));
  EXPECT_FALSE(p.apply_json("{\"radius\": "));
  EXPECT_FALSE(p.apply_json(R"({"radius": 1e400})"));
  EXPECT_FALSE(p.apply_json(R"({"radius": 123456789012345678901234567890})"));
  EXPECT_EQ(p.get_int("radius"), 8);
}

TEST(ParameterSet, JsonRoundTrip) {
  ParameterSet p = make_params();
  ASSERT_TRUE(p.set_from_string("radius=9"));
  ASSERT_TRUE(p.set_from_string("kernel=box"));
  const std::string json = p.to_json();
  EXPECT_EQ(json, R"({"radius":9,"light_size":0.5,"use_blur":true,"kernel":"box"})");
  ParameterSet q = make_params();
  ASSERT_TRUE(q.apply_json(json));
  EXPECT_EQ(q.to_json(), json);
}

}  // namespace
}  // namespace penumbra::graph
