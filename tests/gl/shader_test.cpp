// The shader system: #include chains, errors that name the right file and line, and reload
// keeping the last good program.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <thread>

#include "gl/program.h"
#include "gl/shader_preprocessor.h"
#include "gl/texture.h"
#include "test_support/gl_context.h"
#include "test_support/temp_dir.h"

using namespace penumbra;
namespace fs = std::filesystem;

class Shaders : public ::testing::Test {
 protected:
  void SetUp() override {
    test::gl_context();
    root_ = test::fresh_temp_dir(std::string("shader_test_") +
                                 ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(root_ / "lib");
    fs::create_directories(root_ / "pass");
    files_ = gl::ShaderFileSystem({root_}, false);
    files_.add_include_dir("lib");
  }
  void TearDown() override { fs::remove_all(root_); }
  void write(const std::string& path, const std::string& text) {
    std::ofstream(root_ / path) << text;
  }
  // Compute shader writing `value()` into a 1x1 R32F image, read back.
  float run(const gl::ShaderProgram& p) {
    gl::Texture t(gl::Format::R32F, 1, 1);
    glUseProgram(p.id());
    glBindImageTexture(0, t.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
    glDispatchCompute(1, 1, 1);
    glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT);
    return t.read()[0];
  }
  static std::string main_shader(const std::string& include) {
    return "#version 450 core\n#include \"" + include + "\"\n"
           "layout(local_size_x = 1) in;\n"
           "layout(r32f, binding = 0) uniform writeonly image2D dst;\n"
           "void main() { imageStore(dst, ivec2(0), vec4(value())); }\n";
  }
  fs::path root_;
  gl::ShaderFileSystem files_{{}, false};
};

TEST_F(Shaders, IncludeChainResolvesRelativeThenSearchPath) {
  write("pass/main.comp.glsl", main_shader("helpers.glsl"));
  write("pass/helpers.glsl", "#include \"base.glsl\"\nfloat value() { return base() * 2.0; }\n");
  write("lib/base.glsl", "float base() { return 21.0; }\n");  // found via the include dir
  gl::ShaderProgram p({.compute = "pass/main.comp.glsl"}, files_);
  ASSERT_TRUE(p.build()) << p.last_error()->to_string() << p.last_error()->details;
  EXPECT_EQ(run(p), 42.0f);
}

// An include directory is a root for names with folders: "sampling/noise.glsl" from anywhere.
TEST_F(Shaders, IncludeWithAFolderResolvesThroughAnIncludeDirectory) {
  fs::create_directories(root_ / "lib/sampling");
  write("pass/main.comp.glsl", main_shader("sampling/noise.glsl"));
  write("lib/sampling/noise.glsl", "#include \"twice.glsl\"\nfloat value() { return twice(4.0); }\n");
  write("lib/sampling/twice.glsl", "float twice(float x) { return 2.0 * x; }\n");  // its sibling
  gl::ShaderProgram p({.compute = "pass/main.comp.glsl"}, files_);
  ASSERT_TRUE(p.build()) << p.last_error()->to_string() << p.last_error()->details;
  EXPECT_EQ(run(p), 8.0f);
}

// `..` is refused even where the file exists: include directories make it unnecessary, and a
// climbing path only works in one layout of the files (the source tree, not a plugin folder).
TEST_F(Shaders, IncludeThatClimbsIsAnErrorNamingFileAndLine) {
  write("lib/base.glsl", "float base() { return 21.0; }\n");
  for (const std::string name : {"../lib/base.glsl", "lib/../lib/base.glsl", "/lib/base.glsl"}) {
    write("pass/main.comp.glsl", "#version 450 core\n\n#include \"" + name + "\"\n");
    auto out = gl::preprocess_shader("pass/main.comp.glsl", files_);
    ASSERT_FALSE(out) << name;
    EXPECT_EQ(out.error().file, "pass/main.comp.glsl") << name;
    EXPECT_EQ(out.error().line, 3) << name;
    EXPECT_NE(out.error().message.find("'..' and absolute paths are not allowed"), std::string::npos)
        << out.error().message;
  }
}

TEST_F(Shaders, FileIncludedTwiceIsPastedOnce) {
  write("pass/main.comp.glsl", "#version 450 core\n#include \"a.glsl\"\n#include \"a.glsl\"\n"
                               "float value() { return A; }\nlayout(local_size_x = 1) in;\n"
                               "layout(r32f, binding = 0) uniform writeonly image2D dst;\n"
                               "void main() { imageStore(dst, ivec2(0), vec4(value())); }\n");
  write("pass/a.glsl", "const float A = 3.0;\n");
  gl::ShaderProgram p({.compute = "pass/main.comp.glsl"}, files_);
  ASSERT_TRUE(p.build()) << p.last_error()->details;
  EXPECT_EQ(run(p), 3.0f);
}

TEST_F(Shaders, DefinesFollowTheVersionLine) {
  write("pass/main.comp.glsl", main_shader("d.glsl"));
  write("pass/d.glsl", "float value() { return float(TAPS); }\n");
  gl::ShaderProgram p({.compute = "pass/main.comp.glsl", .defines = {{"TAPS", "16"}}}, files_);
  ASSERT_TRUE(p.build()) << p.last_error()->details;
  EXPECT_EQ(run(p), 16.0f);
}

TEST_F(Shaders, MissingIncludeNamesFileAndLine) {
  write("pass/main.comp.glsl", "#version 450 core\n\n\n#include \"nowhere.glsl\"\n");
  gl::ShaderProgram p({.compute = "pass/main.comp.glsl"}, files_);
  Status s = p.build();
  ASSERT_FALSE(s);
  EXPECT_EQ(s.error().file, "pass/main.comp.glsl");
  EXPECT_EQ(s.error().line, 4);
  EXPECT_NE(s.error().message.find("nowhere.glsl"), std::string::npos);
}

TEST_F(Shaders, MissingShaderFileNamesThePath) {
  gl::ShaderProgram p({.compute = "pass/absent.comp.glsl"}, files_);
  Status s = p.build();
  ASSERT_FALSE(s);
  EXPECT_EQ(s.error().file, "pass/absent.comp.glsl");
  EXPECT_NE(s.error().message.find("not found"), std::string::npos);
}

TEST_F(Shaders, SyntaxErrorInIncludedFileNamesThatFileAndLine) {
  write("pass/main.comp.glsl", main_shader("helpers.glsl"));
  write("pass/helpers.glsl", "// line 1\n// line 2\nfloat value() { return 1.0 +; }\n");
  gl::ShaderProgram p({.compute = "pass/main.comp.glsl"}, files_);
  Status s = p.build();
  ASSERT_FALSE(s);
  EXPECT_EQ(s.error().file, "pass/helpers.glsl") << s.error().details;
  EXPECT_EQ(s.error().line, 3) << s.error().details;
  EXPECT_NE(s.error().details.find("pass/helpers.glsl:3"), std::string::npos) << s.error().details;
}

// Mesa reports an undeclared identifier with source string 0 whatever #line said (the syntax
// error above it gets right): the file must still be the included one.
TEST_F(Shaders, UndeclaredIdentifierInIncludedFileNamesThatFileAndLine) {
  write("pass/main.comp.glsl", main_shader("helpers.glsl"));
  write("pass/helpers.glsl", "// line 1\nfloat value() {\n  return vec2(undeclared_thing).x;\n}\n");
  gl::ShaderProgram p({.compute = "pass/main.comp.glsl"}, files_);
  Status s = p.build();
  ASSERT_FALSE(s);
  EXPECT_EQ(s.error().file, "pass/helpers.glsl") << s.error().details;
  EXPECT_EQ(s.error().line, 3) << s.error().details;
  EXPECT_EQ(s.error().details.find("pass/main.comp.glsl"), std::string::npos) << s.error().details;
}

TEST_F(Shaders, SyntaxErrorAfterAnIncludeNamesTheMainFileLine) {
  write("pass/main.comp.glsl", "#version 450 core\n#include \"h.glsl\"\nlayout(local_size_x = 1) in;\n"
                               "void main() { undefined_call(); }\n");
  write("pass/h.glsl", "float a() { return 1.0; }\nfloat b() { return 2.0; }\n");
  gl::ShaderProgram p({.compute = "pass/main.comp.glsl"}, files_);
  Status s = p.build();
  ASSERT_FALSE(s);
  EXPECT_EQ(s.error().file, "pass/main.comp.glsl") << s.error().details;
  EXPECT_EQ(s.error().line, 4) << s.error().details;
}

TEST_F(Shaders, IncludeCycleIsAnError) {
  write("pass/main.comp.glsl", main_shader("a.glsl"));
  write("pass/a.glsl", "#include \"b.glsl\"\n");
  write("pass/b.glsl", "#include \"a.glsl\"\n");
  gl::ShaderProgram p({.compute = "pass/main.comp.glsl"}, files_);
  Status s = p.build();
  ASSERT_FALSE(s);
  EXPECT_NE(s.error().message.find("cycle"), std::string::npos);
  EXPECT_EQ(s.error().file, "pass/b.glsl");
}

TEST_F(Shaders, ReloadKeepsLastGoodProgramAndPicksUpFixes) {
  write("pass/main.comp.glsl", main_shader("v.glsl"));
  write("pass/v.glsl", "float value() { return 1.0; }\n");
  gl::ShaderProgram p({.compute = "pass/main.comp.glsl"}, files_);
  ASSERT_TRUE(p.build());
  GLuint good = p.id();
  EXPECT_FALSE(p.sources_changed());

  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  write("pass/v.glsl", "float value() { return syntax error }\n");
  fs::last_write_time(root_ / "pass/v.glsl", fs::file_time_type::clock::now() + std::chrono::seconds(1));
  EXPECT_TRUE(p.sources_changed());
  Status s = p.reload();
  ASSERT_FALSE(s);
  EXPECT_EQ(p.id(), good);  // the old program stays in use
  ASSERT_TRUE(p.last_error().has_value());
  EXPECT_EQ(p.last_error()->file, "pass/v.glsl");
  EXPECT_EQ(run(p), 1.0f);

  write("pass/v.glsl", "float value() { return 2.0; }\n");
  fs::last_write_time(root_ / "pass/v.glsl", fs::file_time_type::clock::now() + std::chrono::seconds(2));
  EXPECT_TRUE(p.sources_changed());
  ASSERT_TRUE(p.reload());
  EXPECT_FALSE(p.last_error().has_value());
  EXPECT_EQ(run(p), 2.0f);
}

TEST_F(Shaders, DriverLogLinesMapToFiles) {
  std::vector<std::string> files = {"a.glsl", "b.glsl"};
  Error mesa = gl::map_compile_log("1:7(12): error: syntax error\n", files, "compute");
  EXPECT_EQ(mesa.file, "b.glsl");
  EXPECT_EQ(mesa.line, 7);
  EXPECT_EQ(mesa.column, 12);
  Error nv = gl::map_compile_log("0(5) : error C0000: syntax error, unexpected '}'\n", files, "fragment");
  EXPECT_EQ(nv.file, "a.glsl");
  EXPECT_EQ(nv.line, 5);
}

// Every .glsl of the repository resolves its includes with the default include directories, read
// from the source tree (development builds) and from the embedded table alone (bundled binaries).
TEST(RepositoryShaders, EveryIncludeResolvesInTheTreeAndEmbedded) {
  const gl::ShaderFileSystem tree({PENUMBRA_SOURCE_DIR}, false), embedded({}, true);
  int shaders = 0;
  for (const gl::EmbeddedShaderFile& f : gl::embedded_shader_files()) {
    const std::string path = f.path;
    if (!path.ends_with(".glsl")) continue;
    ++shaders;
    for (const gl::ShaderFileSystem* files : {&tree, &embedded}) {
      auto out = gl::preprocess_shader(path, *files);
      EXPECT_TRUE(out) << (out ? "" : out.error().to_string());
    }
  }
  EXPECT_GT(shaders, 40);
}

TEST(EmbeddedShaders, RepositoryShadersAreEmbedded) {
  gl::ShaderFileSystem embedded_only({}, true);
  auto text = embedded_only.read("engine/gl/shaders/fullscreen.vert.glsl");
  ASSERT_TRUE(text) << text.error().to_string();
  EXPECT_NE(text->find("gl_VertexID"), std::string::npos);
}
