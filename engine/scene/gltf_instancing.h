#pragma once
// EXT_mesh_gpu_instancing: a node's mesh drawn once per instance, each placed by the node's world
// transform times the instance's TRANSLATION, ROTATION and SCALE (each optional; all of one
// count). Instances are casters, so they become scene instances like any other.
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "util/error.h"

namespace tinygltf {
class Model;
class Node;
}  // namespace tinygltf

namespace penumbra::scene::gltf {

// The instances' local transforms (to be multiplied onto the node's world transform), or
// nullopt when the node has no such extension. Errors name the node and the accessor.
Result<std::optional<std::vector<glm::mat4>>> node_instances(const tinygltf::Model& model, const tinygltf::Node& node,
                                                            const std::string& file, const std::string& where);

}  // namespace penumbra::scene::gltf
