#pragma once
// glTF 2.0 (.gltf + external/embedded buffers, or .glb) -> Scene, through tinygltf 2.7.0.
// Supported: TRIANGLES primitives (indexed or not; u8/u16/u32 indices), POSITION, NORMAL (flat
// normals are generated when missing), TEXCOORD_0, node hierarchy (matrix or TRS), base colour
// factor and texture, alpha mode OPAQUE/MASK/BLEND with cutoff, double-sided.
// Not supported (rejected with an Error): other primitive modes, sparse accessors, any required
// extension but KHR_lights_punctual (KHR_draco_mesh_compression, ...), non-finite positions or
// transforms, node hierarchies that expand past the limits below. A missing buffer or image
// file is an Error naming it. Before tinygltf sees the file: it is read whole (devices refused,
// 1 GiB at most), its JSON (a .glb's JSON chunk) goes through the one nesting limit
// (util/json_text.h) and the specification's value ranges (scene/gltf_spec_checks.h).
// KHR_lights_punctual: every directional, spot and point light a node of the default scene
// places becomes a SceneLight (Scene::lights) with the node's world position and direction
// (glTF lights shine down the node's local -Z), colour, intensity (copied as is: lux for
// directional, candela otherwise), range and cone angles; size 0 (punctual). A light index out
// of range or an unknown type is an Error naming the node.
// Cameras: every perspective camera a node of the default scene places becomes a SceneCamera
// (Scene::cameras; looking down the node's -Z, roll dropped); orthographic ones are skipped with
// a warning.
// Ignored: skins, animations, other textures (normal, metal-rough, ...), samplers (wrap = repeat
// is assumed).
//
//   Result<Scene> s = load_gltf("assets/Fox/Fox.gltf");
//   if (!s) { spdlog::error("{}", s.error().to_string()); return s.error().exit_code(); }
#include <cstddef>
#include <string>

#include "scene/scene.h"
#include "util/error.h"

namespace penumbra::scene {

// Limits of a scene graph (docs/robustness.md): depth, node visits while flattening (children
// shared by several parents are visited once per path), mesh instances placed.
inline constexpr int kMaxNodeDepth = 256;
inline constexpr size_t kMaxNodeVisits = 1000000;
inline constexpr size_t kMaxInstances = 100000;

// Every Error carries `file` = path; `where` names the mesh/primitive/accessor at fault.
// The default camera is fitted to the bounds (framing.h, 16:9; staging.h refits it to the
// frame's aspect); the default light is the file's own (framing.h file_light) or else one placed
// so the shadows fall towards the camera (default_light). No ground plane is added here: that
// is staging's choice (staging.h).
Result<Scene> load_gltf(const std::string& path);

}  // namespace penumbra::scene
