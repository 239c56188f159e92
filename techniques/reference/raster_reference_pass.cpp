// The progressive raster reference (compute accumulation of per-sample-point depth maps).
#include "raster_reference_pass.h"

#include <algorithm>

#include <spdlog/spdlog.h>

#include "exec/gpu_scene.h"
#include "gl/framebuffer.h"
#include "reference_frame_key.h"
#include "exec/pass_decl_builder.h"
#include "passes/shadow_map/shadow_map_pass.h"
#include "graph/parameters.h"
#include "passes/common/shadow_uniforms.h"
#include "sample_view.h"
#include "sphere_light_points.h"

namespace penumbra::reference {
namespace {

using graph::int_param;
using graph::real_param;

using graph::Format;

// Texture unit given to GpuScene::draw for base-colour textures (alpha-masked casters), above
// the units the compute programs use.
constexpr GLuint kSceneTextureUnit = 7;

// The light's sample points: scene::light_samples (the ray tracer's) for spot and directional
// lights; for a point light, points that fill its ball so that every receiver sees them spread
// over its own disk (sphere_light_points.h).
std::vector<scene::LightSample> sample_points(const scene::Light& light, const scene::Bounds& bounds, int count,
                                              uint32_t seed) {
  if (light.type != scene::LightType::point) return scene::light_samples(light, bounds, count, seed);
  std::vector<scene::LightSample> out;
  for (const glm::vec3& p : sphere_light_points(light, count, seed)) out.push_back({.point = p, .is_point = true});
  return out;
}

class RasterReferencePass final : public exec::PassImpl {
 public:
  Status execute(exec::PassContext& ctx) override {
    const exec::FrameInputs& frame = ctx.frame();
    if (!frame.scene) return make_error("reference_raster: no scene", ErrorKind::internal);
    const int samples = ctx.integer("samples"), map_size = ctx.integer("map_size");
    const int seed = ctx.integer("seed");
    const float slope_bias = ctx.real("slope_bias"), constant_bias = ctx.real("constant_bias");
    const float receiver_bias = ctx.real("receiver_bias");
    gl::Texture& accumulation = ctx.texture("accumulation");

    // Reset rule: anything the sum depends on changed since last frame -> start again.
    ReferenceFrameKey key = make_frame_key(frame, {double(samples), double(map_size), double(seed),
                                                   slope_bias, constant_bias, receiver_bias});
    if (!has_key_ || key != key_) {
      if (has_key_) ++restarts_;
      key_ = std::move(key);
      has_key_ = true;
      done_ = 0;
      samples_ = sample_points(frame.light, frame.scene->cpu().bounds, samples, static_cast<uint32_t>(seed));
      accumulation.clear(0.0f);
    }
    if (Status s = ensure_map(map_size); !s) return s;

    // A point light's samples are point lights inside the scene: six faces each, whether or not
    // the frame's own map needs them (scene/light_faces.h).
    const bool six_faces = frame.light.type == scene::LightType::point;
    gl::ShaderSources depth_sources{.vertex = "passes/shadow_map/shadow_map.vert.glsl",
                                    .fragment = "passes/shadow_map/shadow_map.frag.glsl"};
    gl::ShaderSources acc_sources{.compute = "techniques/reference/raster_accumulate.comp.glsl"};
    if (six_faces) {
      depth_sources.defines.push_back({"LINEAR_FACE_DEPTH", "1"});
      acc_sources.defines.push_back({"SIX_FACES", "1"});
    }
    gl::ShaderProgram& depth = ctx.program(depth_sources);
    if (!depth.valid()) return *depth.last_error();
    gl::ShaderProgram& acc = ctx.program(acc_sources);
    if (!acc.valid()) return *acc.last_error();
    gl::ShaderProgram& resolve = ctx.program({.compute = "techniques/reference/raster_resolve.comp.glsl"});
    if (!resolve.valid()) return *resolve.last_error();

    const scene::Bounds& bounds = frame.scene->cpu().bounds;
    // The ray tracer's shadow-ray offset (raytraced_reference.h): 1e-4 of the bounds' diagonal.
    const float normal_offset = 1e-4f * (bounds.empty() ? 1.0f : glm::length(bounds.extent()));
    const int todo = std::min(ctx.integer("maps_per_frame"), samples - done_);
    if (todo > 0) {
      ctx.bind_sampled(acc, "u_depth", "depth");  // units 0, 1
      ctx.bind_sampled(acc, "u_normal", "normal");
      constexpr GLuint map_unit = 2;
      acc.program().set("u_sample_map", static_cast<int>(map_unit));
      acc.program().set("u_normal_offset", normal_offset);
      acc.program().set("u_texel_offset", ctx.real("receiver_bias"));
      ctx.bind_image(0, "accumulation", GL_READ_WRITE);
      for (int i = 0; i < todo; ++i, ++done_) {
        const scene::LightSample& sample = samples_[static_cast<size_t>(progressive_index(done_, samples))];
        if (six_faces) {
          Result<scene::PointLightFaces> faces = render_faces(depth.program(), *frame.scene, frame.light, sample.point,
                                                              map_size, slope_bias, constant_bias);
          if (!faces) return faces.error();
          passes::set_light_face_uniforms(acc.program(), *faces, map_size);
          acc.program().set("u_texel_tan", 2.0f * faces->tan_half_fov / static_cast<float>(faces->tile));
          acc.program().set("u_texel_world", 0.0f);
        } else {
          const SampleView view = sample_view(frame.light, bounds, sample);
          render_map(depth.program(), *frame.scene, view.view_proj, slope_bias, constant_bias);
          acc.program().set("u_sample_view_proj", view.view_proj);
          acc.program().set("u_texel_tan", view.frustum_tan / static_cast<float>(map_size));
          acc.program().set("u_texel_world", view.width_world / static_cast<float>(map_size));
        }
        glBindTextureUnit(map_unit, map_.id());
        glBindSampler(map_unit, 0);
        acc.program().set("u_sample_is_point", sample.is_point ? 1 : 0);
        acc.program().set("u_sample_point", sample.point);
        acc.program().set("u_sample_dir", glm::normalize(sample.is_point ? frame.light.direction : sample.direction));
        ctx.dispatch_over(acc, accumulation.width(), accumulation.height());
        // The next sample reads the sum this one wrote through image stores.
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
      }
    }

    ctx.bind_sampled(resolve, "u_depth", "depth");
    ctx.bind_image(0, "accumulation", GL_READ_ONLY);
    ctx.bind_image(1, "mask", GL_WRITE_ONLY);
    resolve.program().set("u_count", static_cast<float>(std::max(done_, 1)));
    gl::Texture& mask = ctx.texture("mask");
    ctx.dispatch_over(resolve, mask.width(), mask.height());

    ctx.report_progress({.label = "raster", .unit = "shadow maps", .done = done_, .total = samples,
                         .restarts = restarts_});
    return {};
  }

 private:
  Status ensure_map(int size) {
    if (map_ && map_.width() == size) return {};
    map_ = gl::Texture(gl::Format::DEPTH32F, size, size);
    map_.set_label("reference_sample_map");
    fb_ = gl::Framebuffer();
    fb_.attach_depth(map_);
    return fb_.finish();
  }

  // One sample point's depth map: the shared shadow_map program (alpha-tested casters) with a
  // slope-scaled + constant polygon offset, as passes/shadow_map does.
  void render_map(const gl::Program& program, const exec::GpuScene& scene, const glm::mat4& view_proj,
                  float slope_bias, float constant_bias) {
    passes::render_depth_map(fb_, program, scene, view_proj, slope_bias, constant_bias, kSceneTextureUnit);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
  }

  // One point light sample's six faces (a point light of no size at `point`), with the same
  // biases; the depth written is linear along each face's axis (shadow_map.frag.glsl).
  Result<scene::PointLightFaces> render_faces(const gl::Program& program, const exec::GpuScene& scene,
                                              const scene::Light& light, const glm::vec3& point, int map_size,
                                              float slope_bias, float constant_bias) {
    scene::Light at = light;
    at.position = point;
    at.size = 0.0f;
    Result<scene::PointLightFaces> faces = scene::point_light_faces(at, scene.cpu().bounds, map_size);
    if (!faces) return faces.error();
    program.set("u_light_near", faces->near_plane);
    program.set("u_light_far", faces->far_plane);
    program.set("u_slope_bias", slope_bias);
    program.set("u_constant_bias", constant_bias);
    passes::render_depth_faces(fb_, program, scene, faces->faces, slope_bias, constant_bias, kSceneTextureUnit);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return faces;
  }

  gl::Texture map_;
  gl::Framebuffer fb_;
  ReferenceFrameKey key_;
  bool has_key_ = false;
  int done_ = 0;
  std::uint64_t restarts_ = 0;
  std::vector<scene::LightSample> samples_;
};

}  // namespace

exec::PassType raster_reference_pass_type() {
  return exec::PassDeclBuilder("reference_raster")
      .describe("Ground truth: accumulated hard visibility of shadow maps from stratified light points (progressive)")
      .imported("scene")
      .imported("light")
      .imported("camera", false)
      .sampled("depth", {Format::R32F})
      .sampled("normal")
      .image_inout("accumulation", {Format::R32F})
      .image_out("mask", {Format::R32F})
      .same_size({"depth", "normal", "accumulation", "mask"})
      .param(int_param("samples", 1024, 1, 65536, "", "Light sample points N (one shadow map each)"))
      .param(int_param("map_size", 4096, 64, 16384, "texels", "Resolution of each sample point's depth map"))
      .param(int_param("maps_per_frame", 16, 1, 65536, "", "Shadow maps accumulated per frame (progressive: keeps the sandbox interactive)"))
      .param(int_param("seed", 0, 0, 1000000, "", "light_sample_points seed (same as the ray tracer's)"))
      .param(real_param("receiver_bias", 1.0, 0.0, 16.0, "texels",
                        "Receiver moved towards the sample point by this many texel footprints x tan(incidence) (acne)"))
      .param(real_param("slope_bias", 0.0, 0.0, 10.0, "", "glPolygonOffset factor of the sample maps"))
      .param(real_param("constant_bias", 2.0, 0.0, 1000.0, "depth steps", "glPolygonOffset units of the sample maps"))
      .build<RasterReferencePass>();
}

}  // namespace penumbra::reference
