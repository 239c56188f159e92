#include "measurement/memory_peaks.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <vector>

#include "gl/buffer.h"
#include "gl/debug_output.h"
#include "gl/program.h"
#include "gl/texture.h"
#include "gl/timer_query.h"

namespace penumbra::measurement {
namespace {

constexpr int kWarmup = 3, kTimed = 15;
constexpr GLuint kGroupsX = 4096;  // 2D dispatch: 32M invocations exceed one dimension's limit

// Fills a buffer of uvec4 with a hash of the index (the copy must read real data).
const char* kFillBuffer = R"(#version 450
layout(local_size_x = 256) in;
layout(std430, binding = 0) writeonly buffer Dst { uvec4 dst[]; };
uint hash(uint x) { x ^= x >> 16; x *= 0x7feb352du; x ^= x >> 15; x *= 0x846ca68bu; return x ^ (x >> 16); }
void main() {
  uint i = gl_GlobalInvocationID.y * (gl_NumWorkGroups.x * 256u) + gl_GlobalInvocationID.x;
  dst[i] = uvec4(hash(i), hash(i + 1u), hash(i + 2u), hash(i + 3u));
}
)";

const char* kCopyBuffer = R"(#version 450
layout(local_size_x = 256) in;
layout(std430, binding = 0) readonly buffer Src { uvec4 src[]; };
layout(std430, binding = 1) writeonly buffer Dst { uvec4 dst[]; };
void main() {
  uint i = gl_GlobalInvocationID.y * (gl_NumWorkGroups.x * 256u) + gl_GlobalInvocationID.x;
  dst[i] = src[i];
}
)";

const char* kFillTexture = R"(#version 450
layout(local_size_x = 16, local_size_y = 16) in;
layout(rgba8, binding = 0) writeonly uniform image2D u_image;
uint hash(uint x) { x ^= x >> 16; x *= 0x7feb352du; x ^= x >> 15; x *= 0x846ca68bu; return x ^ (x >> 16); }
void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  imageStore(u_image, p, unpackUnorm4x8(hash(uint(p.y) * 65536u + uint(p.x))));
}
)";

// One fetch per texel; the sum is written only where it equals an impossible value, so the
// fetch cannot be optimised away and the writes cost nothing.
const char* kFetchTexture = R"(#version 450
layout(local_size_x = 16, local_size_y = 16) in;
layout(binding = 0) uniform sampler2D u_texture;
layout(std430, binding = 0) writeonly buffer Sink { uint sink[]; };
uniform float u_impossible;
void main() {
  vec4 v = texelFetch(u_texture, ivec2(gl_GlobalInvocationID.xy), 0);
  if (dot(v, vec4(1.0)) == u_impossible) sink[0] = gl_GlobalInvocationID.x;
}
)";

std::string gl_problem(const char* what) {
  GLenum e = glGetError();
  if (e == GL_NO_ERROR) return {};
  char text[96];
  std::snprintf(text, sizeof text, "%s: %s", what, gl::gl_error_name(e));
  while (glGetError() != GL_NO_ERROR) {
  }
  return text;
}

// Median seconds of `kTimed` runs of `dispatch`, after `kWarmup`.
double median_seconds(const std::function<void()>& dispatch, bool gpu_timer) {
  for (int i = 0; i < kWarmup; ++i) dispatch();
  glFinish();
  std::vector<double> seconds;
  for (int i = 0; i < kTimed; ++i) {
    if (gpu_timer) {
      gl::TimerQuery begin, end;
      begin.timestamp();
      dispatch();
      end.timestamp();
      glFinish();
      seconds.push_back(static_cast<double>(end.result_ns() - begin.result_ns()) * 1e-9);
    } else {
      auto t0 = std::chrono::steady_clock::now();
      dispatch();
      glFinish();
      seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    }
  }
  std::sort(seconds.begin(), seconds.end());
  return seconds[seconds.size() / 2];
}

std::string measure_copy(MemoryPeaks& peaks, bool gpu_timer) {
  auto fill = gl::build_compute_from_text(kFillBuffer);
  auto copy = gl::build_compute_from_text(kCopyBuffer);
  if (!fill) return "copy kernel: " + fill.error().message;
  if (!copy) return "copy kernel: " + copy.error().message;
  const std::uint64_t bytes = gpu_timer ? (512ull << 20) : (32ull << 20);
  const GLuint invocations = static_cast<GLuint>(bytes / 16);
  const GLuint groups_x = std::min<GLuint>(kGroupsX, invocations / 256), groups_y = invocations / 256 / groups_x;
  gl::Buffer src(bytes), dst(bytes);
  if (std::string p = gl_problem("allocating the copy buffers"); !p.empty()) return p;
  src.bind_base(GL_SHADER_STORAGE_BUFFER, 0);
  glUseProgram(fill->id());
  glDispatchCompute(groups_x, groups_y, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  dst.bind_base(GL_SHADER_STORAGE_BUFFER, 1);
  glUseProgram(copy->id());
  double s = median_seconds([&] { glDispatchCompute(groups_x, groups_y, 1); }, gpu_timer);
  glUseProgram(0);
  if (std::string p = gl_problem("running the copy kernel"); !p.empty()) return p;
  peaks.copy_buffer_bytes = bytes;
  peaks.copy_gb_per_s = 2.0 * static_cast<double>(bytes) / s / 1e9;
  return {};
}

std::string measure_fetch(MemoryPeaks& peaks, bool gpu_timer) {
  auto fill = gl::build_compute_from_text(kFillTexture);
  auto fetch = gl::build_compute_from_text(kFetchTexture);
  if (!fill) return "fetch kernel: " + fill.error().message;
  if (!fetch) return "fetch kernel: " + fetch.error().message;
  const int size = gpu_timer ? 8192 : 1024;
  gl::Texture texture(gl::Format::RGBA8, size, size);
  gl::Buffer sink(16);
  if (std::string p = gl_problem("allocating the fetch texture"); !p.empty()) return p;
  texture.set_filter(GL_NEAREST, GL_NEAREST);
  glBindImageTexture(0, texture.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA8);
  glUseProgram(fill->id());
  glDispatchCompute(size / 16, size / 16, 1);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
  glBindTextureUnit(0, texture.id());
  sink.bind_base(GL_SHADER_STORAGE_BUFFER, 0);
  glUseProgram(fetch->id());
  fetch->set("u_impossible", -1.0f);
  double s = median_seconds([&] { glDispatchCompute(size / 16, size / 16, 1); }, gpu_timer);
  glUseProgram(0);
  if (std::string p = gl_problem("running the fetch kernel"); !p.empty()) return p;
  const double texels = static_cast<double>(size) * size;
  peaks.fetch_width = peaks.fetch_height = size;
  peaks.fetch_gtexels_per_s = texels / s / 1e9;
  peaks.fetch_gb_per_s = texels * 4.0 / s / 1e9;
  return {};
}

}  // namespace

MemoryPeaks measure_memory_peaks(bool gpu_timer) {
  MemoryPeaks peaks;
  while (glGetError() != GL_NO_ERROR) {
  }
  std::string problem = measure_copy(peaks, gpu_timer);
  if (problem.empty()) problem = measure_fetch(peaks, gpu_timer);
  peaks.measured = problem.empty();
  peaks.problem = problem;
  return peaks;
}

std::string describe_memory_peaks(const MemoryPeaks& p) {
  if (!p.measured) return "not measured: " + p.problem;
  char text[256];
  std::snprintf(text, sizeof text, "copy %.1f GB/s (2 x %llu MiB buffers), fetch %.2f Gtexel/s = %.1f GB/s (RGBA8 %dx%d)",
                p.copy_gb_per_s, static_cast<unsigned long long>(p.copy_buffer_bytes >> 20), p.fetch_gtexels_per_s,
                p.fetch_gb_per_s, p.fetch_width, p.fetch_height);
  return text;
}

}  // namespace penumbra::measurement
