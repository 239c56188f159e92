// `penumbra techniques --json` lists every registered technique with every parameter of its
// graph JSON, and `penumbra render` rejects bad --set values with exit code 2 and the valid
// range. Runs the built CLI (PENUMBRA_CLI, a compile definition).
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <nlohmann/json.hpp>
#include <string>

#include "technique/technique.h"
#include "test_support/run_command.h"
#include "test_support/temp_dir.h"
#include "techniques/builtin_techniques.h"

namespace penumbra::test {
namespace {

CommandRun run_cli(const std::string& args) { return test::run_command(std::string(PENUMBRA_CLI) + " " + args); }

TEST(TechniquesCommand, JsonListsEveryParameterOfEveryTechnique) {
  CommandRun r = run_cli("techniques --json");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  nlohmann::json list = nlohmann::json::parse(r.output, nullptr, false);
  ASSERT_FALSE(list.is_discarded()) << r.output;
  ASSERT_TRUE(list.is_array());

  technique::TechniqueRegistry registry;
  register_builtin_techniques(registry);
  ASSERT_EQ(list.size(), registry.all().size());
  for (const technique::Technique& t : registry.all()) {
    SCOPED_TRACE(t.name);
    auto it = std::find_if(list.begin(), list.end(), [&](const auto& j) { return j.value("name", "") == t.name; });
    ASSERT_NE(it, list.end());
    Result<graph::GraphDesc> g = load_technique_graph(registry, t);
    ASSERT_TRUE(g);
    EXPECT_FALSE(g->description.empty());
    EXPECT_EQ((*it)["description"], g->description);
    const nlohmann::json& params = (*it)["parameters"];
    ASSERT_EQ(params.size(), g->parameters.size());
    for (size_t i = 0; i < params.size(); ++i) {
      const graph::ParamDesc& d = g->parameters[i];
      const nlohmann::json& p = params[i];
      SCOPED_TRACE(d.name);
      EXPECT_EQ(p["name"], d.name);
      EXPECT_EQ(p["type"], graph::param_type_name(d.type));
      EXPECT_EQ(p["unit"], d.unit);
      EXPECT_EQ(p["description"], d.description);
      EXPECT_EQ(p["structural"], d.structural);
      ASSERT_TRUE(p.contains("default"));
      if (d.type == graph::ParamType::enumeration) {
        EXPECT_EQ(p["options"], d.options);
        EXPECT_EQ(p["default"], std::get<std::string>(d.default_value));
      } else if (d.has_range()) {
        EXPECT_DOUBLE_EQ(p["min"].get<double>(), d.min);
        EXPECT_DOUBLE_EQ(p["max"].get<double>(), d.max);
      } else {
        EXPECT_TRUE(p["min"].is_null() && p["max"].is_null());
      }
    }
  }
  // The baselines are there with their documented parameters.
  for (const char* name : {"hard", "pcf", "pcss"})
    EXPECT_NE(std::find_if(list.begin(), list.end(), [&](const auto& j) { return j["name"] == name; }), list.end());
}

TEST(TechniquesCommand, TextListsParametersAndBadOptionsExitTwo) {
  CommandRun text = run_cli("techniques");
  ASSERT_EQ(text.exit_code, 0) << text.output;
  EXPECT_NE(text.output.find("--set blocker_samples=16"), std::string::npos) << text.output;
  EXPECT_NE(text.output.find("int, [4, 64]"), std::string::npos) << text.output;
  EXPECT_EQ(run_cli("techniques --bogus").exit_code, 2);
  EXPECT_EQ(run_cli("techniques extra").exit_code, 2);
  EXPECT_EQ(run_cli("techniques --help").exit_code, 0);
}

// A graph that loads but does not compile (a format its slot does not take), and one that does
// not load at all, are listed as broken with their errors and the file; the others as before;
// the exit status says something is broken. PENUMBRA_SHADER_DIR puts the edited graphs first.
TEST(TechniquesCommand, AGraphThatDoesNotCompileIsListedAsBrokenWithItsErrors) {
  const std::filesystem::path dir = fresh_temp_dir("techniques_broken_graph");
  std::filesystem::create_directories(dir / "techniques" / "baseline");
  std::ifstream in(std::string(PENUMBRA_SOURCE_DIR) + "/techniques/baseline/pcf.json");
  std::stringstream text;
  text << in.rdbuf();
  std::string pcf = text.str();
  const size_t at = pcf.find("\"DEPTH32F\"");
  ASSERT_NE(at, std::string::npos) << pcf;
  pcf.replace(at, 10, "\"R16F\"");
  std::ofstream(dir / "techniques" / "baseline" / "pcf.json") << pcf;
  std::ofstream(dir / "techniques" / "baseline" / "hard.json") << "{\"name\": ";
  const std::string env = "PENUMBRA_SHADER_DIR=" + shell_quote(dir.string()) + " ";

  CommandRun listing = run_command(env + PENUMBRA_CLI + " techniques hard pcf pcss");
  EXPECT_EQ(listing.exit_code, 2) << listing.output;
  const std::string file = (dir / "techniques" / "baseline" / "pcf.json").string();
  EXPECT_NE(listing.output.find("BROKEN: its graph does not compile"), std::string::npos) << listing.output;
  EXPECT_NE(listing.output.find(file + ": /passes/"), std::string::npos) << listing.output;
  EXPECT_NE(listing.output.find("format R16F not accepted"), std::string::npos) << listing.output;
  EXPECT_NE(listing.output.find("hard\n  BROKEN: its graph does not load"), std::string::npos) << listing.output;
  EXPECT_NE(listing.output.find("pcss\n"), std::string::npos) << listing.output;
  EXPECT_NE(listing.output.find("do not compile: hard, pcf"), std::string::npos) << listing.output;

  CommandRun json = run_command("{ " + env + PENUMBRA_CLI + " techniques pcf pcss --json 2>/dev/null; }");  // stdout only
  EXPECT_EQ(json.exit_code, 2);
  const nlohmann::json list = nlohmann::json::parse(json.output, nullptr, false);
  ASSERT_TRUE(list.is_array()) << json.output;
  ASSERT_EQ(list.size(), 2u);
  EXPECT_FALSE(list[0]["graph_errors"].empty());
  EXPECT_TRUE(list[1]["graph_errors"].empty());

  // The shipped graphs all compile.
  CommandRun shipped = run_cli("techniques --json");
  ASSERT_EQ(shipped.exit_code, 0) << shipped.output;
  for (const nlohmann::json& t : nlohmann::json::parse(shipped.output)) EXPECT_TRUE(t["graph_errors"].empty()) << t["name"];
}

// A run stopped by SIGTERM (or Ctrl+C) while its outputs are staged leaves none of them, nor the
// folder it made for them: --all-techniques stages every picture until the last is rendered.
TEST(RenderCommand, AStoppedRunLeavesNoHalfWrittenOutputs) {
  const std::filesystem::path dir = fresh_temp_dir("render_stopped");
  const std::string out = (dir / "out").string();
  const std::string script =
      std::string(PENUMBRA_CLI) + " render --context osmesa --scene ball --size 64x48 --shadow-size 512 --all-techniques" +
      " --out-dir " + shell_quote(out) + " >/dev/null 2>&1 & pid=$!; " +
      "for i in $(seq 1 600); do ls " + shell_quote(out) + "/*.pending >/dev/null 2>&1 && break; sleep 0.05; done; " +
      "ls " + shell_quote(out) + "/*.pending >/dev/null 2>&1 && echo staged; kill -TERM $pid; wait $pid; echo status=$?";
  CommandRun r = run_command("sh -c " + shell_quote(script));
  ASSERT_NE(r.output.find("staged"), std::string::npos) << r.output;  // stopped while outputs were staged
  EXPECT_NE(r.output.find("status=143"), std::string::npos) << r.output;  // ended by the signal itself
  EXPECT_FALSE(std::filesystem::exists(out)) << "left behind: " << out;
}

TEST(RenderCommand, BadSetValuesExitTwoWithTheValidRange) {
  const std::string base = "render --context osmesa --scene ball --size 32x32 --mask /dev/null --technique ";
  CommandRun range = run_cli(base + "pcss --set blocker_samples=100");
  EXPECT_EQ(range.exit_code, 2) << range.output;
  EXPECT_NE(range.output.find("[4, 64]"), std::string::npos) << range.output;
  CommandRun unknown = run_cli(base + "pcf --set bogus=1");
  EXPECT_EQ(unknown.exit_code, 2) << unknown.output;
  EXPECT_NE(unknown.output.find("box_size"), std::string::npos) << "lists the valid keys: " << unknown.output;
  CommandRun option = run_cli(base + "pcf --set kernel=gauss");
  EXPECT_EQ(option.exit_code, 2) << option.output;
  EXPECT_NE(option.output.find("box, vogel"), std::string::npos) << option.output;
  CommandRun even = run_cli(base + "pcf --set box_size=4");
  EXPECT_EQ(even.exit_code, 2) << even.output;
  EXPECT_NE(even.output.find("odd"), std::string::npos) << even.output;
}

// The documented examples run through the shipped CLI; a technique graph is composed into the
// frame by itself, and --no-frame shows why that is needed.
TEST(GraphCommand, DocumentedExamplesAndTechniqueGraphsCompile) {
  int examples = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(PENUMBRA_SOURCE_DIR) + "/docs/graph-examples")) {
    CommandRun r = run_cli("graph " + entry.path().string());
    EXPECT_EQ(r.exit_code, 0) << entry.path() << "\n" << r.output;
    ++examples;
  }
  EXPECT_GE(examples, 3);
  const std::string pmchss = std::string(PENUMBRA_SOURCE_DIR) + "/techniques/pmchss/pmchss.json";
  CommandRun composed = run_cli("graph " + pmchss + " --set variant=min_filter --set checkerboard=true");
  EXPECT_EQ(composed.exit_code, 0) << composed.output;
  EXPECT_NE(composed.output.find("composed into the frame"), std::string::npos) << composed.output;
  CommandRun raw = run_cli("graph " + pmchss + " --no-frame");
  EXPECT_EQ(raw.exit_code, 2) << raw.output;
  EXPECT_NE(raw.output.find("gbuffer_depth"), std::string::npos) << raw.output;
}

// A technique README's parameter table is generated from its graph JSON
// (scripts/update-parameter-tables.sh): the description exists once, the README cannot drift.
TEST(TechniqueDocs, ReadmeParameterTablesAreGeneratedFromTheJson) {
  const std::string begin = "<!-- parameters: generated by `penumbra techniques --markdown ";
  int checked = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(PENUMBRA_SOURCE_DIR) + "/techniques")) {
    std::ifstream in(entry.path() / "README.md");
    if (!in) continue;
    std::stringstream text;
    text << in.rdbuf();
    const std::string readme = text.str();
    size_t at = readme.find(begin);
    if (at == std::string::npos) continue;
    SCOPED_TRACE(entry.path().string());
    const std::string name = readme.substr(at + begin.size(), readme.find('`', at + begin.size()) - at - begin.size());
    size_t table = readme.find('\n', at) + 1;
    size_t end = readme.find("<!-- end of parameters -->", table);
    ASSERT_NE(end, std::string::npos);
    CommandRun r = run_cli("techniques --markdown " + name);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_EQ(readme.substr(table, end - table), r.output)
        << "run scripts/update-parameter-tables.sh after changing " << name << "'s JSON";
    ++checked;
  }
  EXPECT_GE(checked, 1);
}

}  // namespace
}  // namespace penumbra::test
