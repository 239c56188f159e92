// The ray-traced reference as a pass: G-buffer read-back -> trace_visibility -> upload.
#include "raytraced_reference_pass.h"

#include <chrono>
#include <mutex>
#include <optional>

#include <spdlog/spdlog.h>

#include "exec/gbuffer_readback.h"
#include "exec/gpu_scene.h"
#include "raytraced_reference.h"
#include "reference_frame_key.h"
#include "exec/pass_decl_builder.h"
#include "graph/parameters.h"

namespace penumbra::reference {
namespace {

using graph::int_param;

using graph::Format;

// One Embree scene per GpuScene, shared by every pass instance (a recompile or a switch of
// method must not rebuild the BVH). Keyed like the reset rule: by the scene's serial.
struct RaySceneCache {
  std::mutex mutex;
  std::uint64_t scene = 0;  // GpuScene::serial() of the scene it was built from
  std::optional<RayScene> ray_scene;
};

RaySceneCache& ray_scene_cache() {
  static RaySceneCache cache;
  return cache;
}

Result<const RayScene*> ray_scene_for(const exec::GpuScene& gpu) {
  RaySceneCache& c = ray_scene_cache();
  std::lock_guard<std::mutex> lock(c.mutex);
  if (!c.ray_scene || c.scene != gpu.serial()) {
    const auto t0 = std::chrono::steady_clock::now();
    Result<RayScene> built = RayScene::build(gpu.cpu());
    if (!built) return built.error();
    c.ray_scene.emplace(std::move(*built));
    c.scene = gpu.serial();
    spdlog::info("reference: Embree scene of {} triangles built in {:.0f} ms", gpu.triangle_count(),
                 std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  }
  return &*c.ray_scene;
}

class RaytracedReferencePass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    const exec::FrameInputs& frame = ctx.frame();
    if (!frame.scene) return make_error("reference_raytraced: no scene", ErrorKind::internal);
    const int rays = ctx.integer("rays"), seed = ctx.integer("seed"), pixel_samples = ctx.integer("pixel_samples");
    gl::Texture& mask = ctx.texture("mask");
    ReferenceFrameKey key = make_frame_key(frame, {double(rays), double(seed), double(pixel_samples)});
    if (!has_key_ || key != key_ || result_.size() != static_cast<size_t>(mask.width()) * mask.height()) {
      if (has_key_) ++restarts_;
      if (Status s = trace(ctx, rays, seed, pixel_samples); !s) return s;
      key_ = std::move(key);
      has_key_ = true;
    }
    mask.upload(result_.data());
    return {};
  }

 private:
  Status trace(exec::PassContext& ctx, int rays, int seed, int pixel_samples) {
    auto rs = ray_scene_for(*ctx.frame().scene);
    if (!rs) return rs.error();
    // G-buffer read-back; rows stay in GL order (bottom to top): the trace is per pixel, and the
    // result is uploaded in the same order.
    const gl::Texture& depth_tex = ctx.texture("depth");
    const int w = depth_tex.width(), h = depth_tex.height();
    const std::vector<glm::vec4> pos = exec::read_positions(depth_tex, ctx.frame().camera);
    std::vector<glm::vec3> normals = exec::read_normals(ctx.texture("normal"));
    const size_t n = static_cast<size_t>(w) * h;
    std::vector<glm::vec3> positions(n);
    metrics::CoverageMask coverage(n, 0);
    size_t receivers = 0;
    for (size_t i = 0; i < n; ++i) {
      positions[i] = glm::vec3(pos[i]);
      coverage[i] = pos[i].w > 0.0f ? 1 : 0;
      receivers += coverage[i];
    }
    // A zero-size light is traced with one ray per sample point (trace_visibility).
    if (ctx.frame().light.size <= 0.0f) rays = 1;
    const std::int64_t total = static_cast<std::int64_t>(receivers) * rays * pixel_samples * pixel_samples;
    const auto t0 = std::chrono::steady_clock::now();
    int next_report = 1;  // in tenths
    TraceOptions options{.samples = rays, .seed = static_cast<uint32_t>(seed)};
    options.pixel_samples = pixel_samples;
    options.camera = ctx.frame().camera;
    options.rows_bottom_up = true;  // GL row order, see above
    auto report = [&](std::int64_t done) {
      ctx.report_progress({.label = "raytraced", .unit = "rays", .done = done, .total = total, .restarts = restarts_});
    };
    options.progress = [&](float f) {
      report(static_cast<std::int64_t>(f * static_cast<double>(total)));
      // Progress lines only for long traces (a full-HD frame at M = 256), every ~10%.
      const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      if (f * 10.0f >= static_cast<float>(next_report) && f < 1.0f && elapsed > 2.0) {
        spdlog::info("reference: ray tracing {:.0f}% ({} receivers x {} rays)", 100.0f * f, receivers, rays);
        next_report = static_cast<int>(f * 10.0f) + 1;
      }
    };
    metrics::MaskImage traced = trace_visibility(**rs, ctx.frame().light, positions, normals, w, h, options, coverage);
    result_ = std::move(traced.pixels);
    report(total);
    spdlog::info("reference: traced {}x{} ({} receivers x {} rays) in {:.2f} s", w, h, receivers, rays,
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    return {};
  }

  ReferenceFrameKey key_;
  bool has_key_ = false;
  std::uint64_t restarts_ = 0;
  std::vector<float> result_;  // R32F texels, GL row order
};

}  // namespace

exec::PassType raytraced_reference_pass_type() {
  // The mask is written by a texture upload (glTextureSubImage2D); declared as an incoherent
  // image write so readers get a barrier, which is harmless for an upload.
  return exec::PassDeclBuilder("reference_raytraced")
      .describe("Ground truth: exact area-light visibility ray-traced on the CPU (Embree), traced when inputs change")
      .imported("scene")
      .imported("light")
      .imported("camera", false)
      .sampled("depth", {Format::R32F})
      .sampled("normal", {Format::RG16})
      .image_out("mask", {Format::R32F})
      .same_size({"depth", "normal", "mask"})
      .param(int_param("rays", 256, 1, 65536, "", "Shadow rays per pixel M (stratified light points)"))
      .param(int_param("seed", 0, 0, 1000000, "", "light_sample_points seed (same as the raster reference's)"))
      .param(int_param("pixel_samples", 1, 1, 16, "", "K x K sub-pixel samples per pixel on the receiver's tangent plane (box filter; 4 with a "
                       "size-0 light = anti-aliased exact hard shadow)"))
      .build<RaytracedReferencePass>();
}

}  // namespace penumbra::reference
