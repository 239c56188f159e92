#include "gl/image_declarations.h"

#include <map>
#include <regex>
#include <sstream>

namespace penumbra::gl {

std::vector<ImageDeclaration> image_declarations(const std::string& glsl) {
  static const std::regex define_re(R"(^\s*#\s*define\s+(\w+)\s+(\w+)\s*$)");
  static const std::regex image_re(
      R"(layout\s*\(([^)]*)\)\s*(?:\w+\s+)*uniform\s+(?:\w+\s+)*[iu]?image2D\s+(\w+))");
  static const std::regex binding_re(R"(binding\s*=\s*(\d+))");
  std::map<std::string, std::string> defines;
  std::vector<ImageDeclaration> out;
  std::istringstream lines(glsl);
  std::string line;
  while (std::getline(lines, line)) {
    std::smatch m;
    if (std::regex_match(line, m, define_re)) {
      defines[m[1]] = m[2];
      continue;
    }
    if (!std::regex_search(line, m, image_re)) continue;
    const std::string layout = m[1], name = m[2];
    std::smatch b;
    if (!std::regex_search(layout, b, binding_re)) continue;
    ImageDeclaration d;
    d.binding = static_cast<unsigned>(std::stoul(b[1]));
    d.name = name;
    std::istringstream parts(layout);
    std::string part;
    while (std::getline(parts, part, ',')) {
      const size_t first = part.find_first_not_of(" \t"), last = part.find_last_not_of(" \t");
      if (first == std::string::npos) continue;
      std::string token = part.substr(first, last - first + 1);
      if (token.find('=') != std::string::npos) continue;
      auto define = defines.find(token);
      d.qualifier = define == defines.end() ? token : define->second;
    }
    if (!d.qualifier.empty()) out.push_back(std::move(d));
  }
  return out;
}

}  // namespace penumbra::gl
