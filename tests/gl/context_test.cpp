#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "gl/context.h"
#include "test_support/gl_context.h"

using namespace penumbra;

TEST(Context, UnknownNameIsAClearError) {
  auto kind = gl::parse_context_kind("vulkan");
  ASSERT_FALSE(kind);
  EXPECT_NE(kind.error().message.find("'vulkan'"), std::string::npos);
  EXPECT_NE(kind.error().message.find("glfw, osmesa or egl"), std::string::npos);
  EXPECT_EQ(kind.error().exit_code(), 2);
}

TEST(Context, EnvironmentVariableWithUnknownNameNamesTheVariable) {
  ::setenv("PENUMBRA_CONTEXT", "dx12", 1);
  auto ctx = gl::create_context({});
  ::unsetenv("PENUMBRA_CONTEXT");
  ASSERT_FALSE(ctx);
  EXPECT_EQ(ctx.error().where, "PENUMBRA_CONTEXT");
  EXPECT_NE(ctx.error().message.find("'dx12'"), std::string::npos);
}

TEST(Context, GlfwWithoutDisplayIsAClearError) {
  std::string display = std::getenv("DISPLAY") ? std::getenv("DISPLAY") : "";
  ::unsetenv("DISPLAY");
  ::unsetenv("WAYLAND_DISPLAY");
  auto ctx = gl::create_context({.kind = gl::ContextKind::glfw});
  if (!display.empty()) ::setenv("DISPLAY", display.c_str(), 1);
  ASSERT_FALSE(ctx);
  EXPECT_NE(ctx.error().message.find("no display"), std::string::npos);
  EXPECT_NE(ctx.error().message.find("--context egl"), std::string::npos);
  EXPECT_EQ(ctx.error().exit_code(), 2);
}

TEST(Context, HeadlessContextIsGl45Core) {
  const gl::ContextInfo& info = test::gl_context().info();
  EXPECT_GE(info.major * 10 + info.minor, 45);
  EXPECT_FALSE(info.renderer.empty());
  EXPECT_GE(info.max_compute_work_group_invocations, 1024);
  EXPECT_GE(info.max_texture_size, 4096);
}
