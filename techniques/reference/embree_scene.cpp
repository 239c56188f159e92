#include "embree_scene.h"

#include <cmath>
#include <limits>
#include <vector>

#include <embree3/rtcore.h>

namespace penumbra::reference {
namespace {

// The alpha channel of a base-colour texture, copied: the RayScene must not point into the
// scene it was built from, which the caller may destroy first.
struct AlphaTexels {
  int width = 0, height = 0;
  std::vector<uint8_t> alpha;  // row-major, width * height
};

// What the alpha filter needs for one masked geometry; owned by the RayScene.
struct AlphaMaskData {
  std::vector<glm::vec2> uvs;     // per flattened vertex
  std::vector<uint32_t> indices;  // per triangle corner
  AlphaTexels texels;             // empty: the factor's alpha alone decides
  float factor_alpha = 1.0f;
  float cutoff = 0.5f;
};

AlphaTexels alpha_of(const scene::Image& img) {
  AlphaTexels t{img.width, img.height, {}};
  t.alpha.resize(static_cast<size_t>(img.width) * img.height);
  for (size_t i = 0; i < t.alpha.size(); ++i) t.alpha[i] = img.pixels[i * 4 + 3];
  return t;
}

float texture_alpha(const AlphaTexels& img, glm::vec2 uv) {
  // Nearest texel, repeat wrap (glTF's default sampler).
  const float u = uv.x - std::floor(uv.x), v = uv.y - std::floor(uv.y);
  const int x = std::min(img.width - 1, static_cast<int>(u * static_cast<float>(img.width)));
  const int y = std::min(img.height - 1, static_cast<int>(v * static_cast<float>(img.height)));
  return img.alpha[static_cast<size_t>(y) * img.width + x] / 255.0f;
}

// Embree calls this for every candidate hit (closest-hit and any-hit queries alike); clearing
// valid[i] makes the ray continue through the hole.
void alpha_filter(const RTCFilterFunctionNArguments* args) {
  const auto* data = static_cast<const AlphaMaskData*>(args->geometryUserPtr);
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] != -1) continue;
    const unsigned prim = RTCHitN_primID(args->hit, args->N, i);
    const float bu = RTCHitN_u(args->hit, args->N, i), bv = RTCHitN_v(args->hit, args->N, i);
    const glm::vec2 uv = (1.0f - bu - bv) * data->uvs[data->indices[prim * 3]] +
                         bu * data->uvs[data->indices[prim * 3 + 1]] + bv * data->uvs[data->indices[prim * 3 + 2]];
    const float alpha = data->factor_alpha * (data->texels.alpha.empty() ? 1.0f : texture_alpha(data->texels, uv));
    if (alpha < data->cutoff) args->valid[i] = 0;
  }
}

Error embree_error(RTCDevice device, const std::string& what) {
  return make_error("Embree failed to " + what + " (error code " + std::to_string(rtcGetDeviceError(device)) + ")",
                    ErrorKind::internal);
}

}  // namespace

struct RayScene::Impl {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  std::vector<std::unique_ptr<AlphaMaskData>> masks;
  scene::Bounds bounds;
  ~Impl() {
    if (scene) rtcReleaseScene(scene);
    if (device) rtcReleaseDevice(device);
  }
};

RayScene::RayScene(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
RayScene::RayScene(RayScene&&) noexcept = default;
RayScene& RayScene::operator=(RayScene&&) noexcept = default;
RayScene::~RayScene() = default;
const scene::Bounds& RayScene::bounds() const { return impl_->bounds; }

Result<RayScene> RayScene::build(const scene::Scene& s) {
  auto impl = std::make_unique<Impl>();
  impl->device = rtcNewDevice(nullptr);
  if (!impl->device) return make_error("Embree could not create a device", ErrorKind::unavailable);
  impl->scene = rtcNewScene(impl->device);
  rtcSetSceneBuildQuality(impl->scene, RTC_BUILD_QUALITY_HIGH);
  for (const scene::Instance& inst : s.instances) {
    if (inst.mesh >= s.meshes.size()) continue;
    const scene::Mesh& mesh = s.meshes[inst.mesh];
    if (mesh.indices.size() < 3) continue;
    RTCGeometry geom = rtcNewGeometry(impl->device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                          3 * sizeof(float), mesh.vertices.size()));
    auto* idx = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                               3 * sizeof(uint32_t), mesh.triangle_count()));
    if (!v || !idx) {
      rtcReleaseGeometry(geom);
      return embree_error(impl->device, "allocate geometry buffers");
    }
    for (size_t i = 0; i < mesh.vertices.size(); ++i) {
      const glm::vec3 p = glm::vec3(inst.world * glm::vec4(mesh.vertices[i].position, 1.0f));
      v[3 * i] = p.x, v[3 * i + 1] = p.y, v[3 * i + 2] = p.z;
      impl->bounds.extend(p);
    }
    std::copy(mesh.indices.begin(), mesh.indices.begin() + static_cast<std::ptrdiff_t>(mesh.triangle_count() * 3), idx);
    const scene::Material* mat = mesh.material < s.materials.size() ? &s.materials[mesh.material] : nullptr;
    if (mat && mat->alpha_mode == scene::AlphaMode::mask) {
      auto data = std::make_unique<AlphaMaskData>();
      data->uvs.reserve(mesh.vertices.size());
      for (const scene::Vertex& vx : mesh.vertices) data->uvs.push_back(vx.uv);
      data->indices = mesh.indices;
      if (mat->base_color_texture >= 0 && static_cast<size_t>(mat->base_color_texture) < s.images.size()) {
        const scene::Image& img = s.images[static_cast<size_t>(mat->base_color_texture)];
        if (img.width > 0 && img.height > 0 && img.pixels.size() >= static_cast<size_t>(img.width) * img.height * 4)
          data->texels = alpha_of(img);
      }
      data->factor_alpha = mat->base_color_factor.a;
      data->cutoff = mat->alpha_cutoff;
      rtcSetGeometryUserData(geom, data.get());
      rtcSetGeometryIntersectFilterFunction(geom, alpha_filter);
      rtcSetGeometryOccludedFilterFunction(geom, alpha_filter);
      impl->masks.push_back(std::move(data));
    }
    rtcCommitGeometry(geom);
    rtcAttachGeometry(impl->scene, geom);
    rtcReleaseGeometry(geom);
  }
  rtcCommitScene(impl->scene);
  if (rtcGetDeviceError(impl->device) != RTC_ERROR_NONE) return embree_error(impl->device, "build the scene");
  return RayScene(std::move(impl));
}

bool RayScene::intersect(const glm::vec3& o, const glm::vec3& d, RayHit& hit, float t_near, float t_far) const {
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  RTCRayHit rh{};
  rh.ray.org_x = o.x, rh.ray.org_y = o.y, rh.ray.org_z = o.z;
  rh.ray.dir_x = d.x, rh.ray.dir_y = d.y, rh.ray.dir_z = d.z;
  rh.ray.tnear = t_near;
  rh.ray.tfar = t_far;
  rh.ray.mask = 0xFFFFFFFFu;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(impl_->scene, &ctx, &rh);
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
  hit.t = rh.ray.tfar;
  const glm::vec3 ng(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z);
  const float len = glm::length(ng);
  hit.geometric_normal = len > 0.0f ? ng / len : glm::vec3(0, 1, 0);
  return true;
}

bool RayScene::occluded(const glm::vec3& o, const glm::vec3& d, float t_near, float t_far) const {
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  RTCRay ray{};
  ray.org_x = o.x, ray.org_y = o.y, ray.org_z = o.z;
  ray.dir_x = d.x, ray.dir_y = d.y, ray.dir_z = d.z;
  ray.tnear = t_near;
  ray.tfar = t_far;
  ray.mask = 0xFFFFFFFFu;
  rtcOccluded1(impl_->scene, &ctx, &ray);
  return ray.tfar < 0.0f;  // Embree sets tfar = -inf when blocked
}

}  // namespace penumbra::reference
