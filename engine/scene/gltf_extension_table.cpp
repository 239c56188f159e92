#include "scene/gltf_extension_table.h"

#include <algorithm>
#include <iterator>

#include <spdlog/spdlog.h>

namespace penumbra::scene {

namespace {

using enum GltfExtensionSupport;

// Khronos-ratified (KHR_) and multi-vendor (EXT_) extensions, with the archived ones still met
// in files in the wild.
constexpr GltfExtension kExtensions[] = {
    {"KHR_lights_punctual", supported, "directional, spot and point lights placed by nodes"},
    {"KHR_texture_transform", supported,
     "offset, rotation, scale and texCoord of the base colour texture, whose alpha is the mask casters are cut by"},
    {"KHR_mesh_quantization", supported,
     "byte and short positions, normals and texture coordinates, normalized or not, dequantized at load"},
    {"KHR_draco_mesh_compression", supported, "Draco-compressed primitives, decoded with libdraco"},
    {"EXT_meshopt_compression", supported,
     "meshopt-compressed buffer views (attributes, triangles, indices; octahedral, quaternion and exponential "
     "filters), decoded with libmeshoptimizer; fallback buffers need no data"},
    {"EXT_mesh_gpu_instancing", supported,
     "a node's mesh drawn once per instance (TRANSLATION, ROTATION, SCALE), every instance a caster"},
    {"KHR_materials_clearcoat", ignored, "shading only: a coat changes reflection, not what light reaches a surface"},
    {"KHR_materials_sheen", ignored, "shading only"},
    {"KHR_materials_specular", ignored, "shading only"},
    {"KHR_materials_ior", ignored, "shading only"},
    {"KHR_materials_iridescence", ignored, "shading only"},
    {"KHR_materials_anisotropy", ignored, "shading only"},
    {"KHR_materials_emissive_strength", ignored, "shading only: emission lights no other surface here"},
    {"KHR_materials_unlit", ignored, "shading only: an unlit surface still casts its shadow"},
    {"KHR_materials_dispersion", ignored, "shading only"},
    {"KHR_materials_transmission", ignored,
     "shadows follow alphaMode only: a transmissive surface casts a full shadow, as in every shadow-map technique"},
    {"KHR_materials_volume", ignored, "as KHR_materials_transmission"},
    {"KHR_materials_diffuse_transmission", ignored, "as KHR_materials_transmission"},
    {"KHR_materials_variants", ignored, "the default material of each primitive is drawn"},
    {"KHR_animation_pointer", ignored, "animation: the static pose is drawn"},
    {"KHR_xmp_json_ld", ignored, "metadata"},
    {"KHR_xmp", ignored, "metadata (archived)"},
    {"EXT_mesh_manifold", ignored, "metadata about the mesh's topology"},
    {"EXT_lights_image_based", ignored, "image-based light casts no shadow map; the scene's light does"},
    {"KHR_texture_basisu", ignored,
     "the texture's PNG or JPEG fallback source is used; a base colour of an alpha-tested material with no "
     "fallback is refused (its mask would be lost)"},
    {"EXT_texture_webp", ignored, "as KHR_texture_basisu"},
    {"EXT_texture_avif", ignored, "as KHR_texture_basisu"},
    {"KHR_materials_pbrSpecularGlossiness", refused,
     "its diffuse texture and factor carry the alpha an alpha-tested material is cut by (archived)"},
    {"KHR_techniques_webgl", refused, "custom shaders may move vertices or discard fragments (archived)"},
    {"KHR_materials_common", refused, "legacy materials whose transparency would be lost (archived)"},
};

}  // namespace

std::span<const GltfExtension> gltf_extensions() { return kExtensions; }

const GltfExtension* find_gltf_extension(std::string_view name) {
  const auto it = std::find_if(std::begin(kExtensions), std::end(kExtensions),
                               [&](const GltfExtension& e) { return e.name == name; });
  return it == std::end(kExtensions) ? nullptr : &*it;
}

Status check_required_gltf_extensions(const std::vector<std::string>& required, const std::string& file) {
  std::string ignored_names;
  for (const std::string& name : required) {
    const GltfExtension* e = find_gltf_extension(name);
    if (!e)
      return file_error(file, "requires the glTF extension '" + shortened(name) +
                                  "', which Penumbra does not know, so cannot tell whether ignoring it changes "
                                  "shadows (docs/gltf.md lists the known ones)");
    if (e->support == refused)
      return file_error(file, "requires the glTF extension '" + name + "', which Penumbra refuses: " +
                                  std::string(e->reason));
    if (e->support == ignored) ignored_names += (ignored_names.empty() ? "" : ", ") + name;
  }
  if (!ignored_names.empty())
    spdlog::warn("{}: requires {}, ignored: they cannot change a shadow (docs/gltf.md)", file, ignored_names);
  return {};
}

}  // namespace penumbra::scene
