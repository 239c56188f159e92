#pragma once
// The image uniforms a compute shader declares with an explicit binding and format qualifier
// (`layout(r16f, binding = 0) uniform writeonly image2D u_mask;`), read from its preprocessed
// text, so a pass can be refused before it stores into a texture of another format (GL would
// convert silently: an rgba32f image over an RGBA16F texture writes garbage).
#include <string>
#include <vector>

namespace penumbra::gl {

struct ImageDeclaration {
  unsigned binding = 0;
  std::string qualifier;  // "r16f", "rgba8", ...; object-like #defines are expanded
  std::string name;       // the uniform's name
};

// Every declaration in `glsl`, in order. Declarations in both branches of an #if are all
// listed: a binding may then accept more than one qualifier.
std::vector<ImageDeclaration> image_declarations(const std::string& glsl);

}  // namespace penumbra::gl
