#include "gl/shader_preprocessor.h"

#include <filesystem>
#include <regex>
#include <set>
#include <sstream>

namespace penumbra::gl {
namespace {

// A `..` or an absolute path would tie the includer to one layout of the files, and the source
// tree, the embedded table, share/penumbra/shaders and a plugin folder lay them out differently;
// the include directories are the same in all of them.
bool climbs_out(const std::string& name) {
  std::filesystem::path p(name);
  if (p.is_absolute() || p.has_root_name() || p.has_root_directory()) return true;
  for (const auto& part : p)
    if (part == "..") return true;
  return false;
}

Error climbing_include(const std::string& name, const std::string& path, int line,
                       const std::vector<std::string>& include_dirs) {
  std::string dirs;
  for (const std::string& dir : include_dirs) dirs += (dirs.empty() ? "" : ", ") + dir;
  Error e = make_error("#include \"" + name + "\": name the file from an include directory (" + dirs +
                       ") or next to " + path + "; '..' and absolute paths are not allowed");
  e.file = path;
  e.line = line;
  return e;
}

struct Expander {
  const ShaderFileSystem& files;
  PreprocessedShader out;
  std::set<std::string> pasted;
  std::vector<std::string> stack;  // include chain, to report cycles

  // Finds `name` next to `from`, then in the include directories.
  std::string resolve(const std::string& from, const std::string& name) const {
    std::string sibling =
        (std::filesystem::path(from).parent_path() / name).lexically_normal().generic_string();
    if (files.exists(sibling)) return sibling;
    for (const std::string& dir : files.include_dirs()) {
      std::string candidate = (std::filesystem::path(dir) / name).lexically_normal().generic_string();
      if (files.exists(candidate)) return candidate;
    }
    return {};
  }

  // Mesa reports some errors (undeclared identifiers, bad constructors) with source string 0
  // whatever the #line said, so the line number alone must name the file: file k's lines are
  // numbered from k * kLinesPerShaderFile.
  static std::string line_directive(int index, int line) {
    return "#line " + std::to_string(index * kLinesPerShaderFile + line) + " " + std::to_string(index) + "\n";
  }

  Status expand(const std::string& path, const std::string& text, bool top, std::ostringstream& dst,
                const std::vector<std::pair<std::string, std::string>>& defines) {
    int index = static_cast<int>(out.files.size());
    out.files.push_back(path);
    stack.push_back(path);
    std::istringstream in(text);
    std::string line;
    int line_no = 0;
    bool version_seen = false;
    static const std::regex include_re(R"re(^\s*#\s*include\s*"([^"]+)"\s*(//.*)?$)re");
    static const std::regex version_re(R"re(^\s*#\s*version\b.*)re");
    if (!top) dst << line_directive(index, 1);
    while (std::getline(in, line)) {
      ++line_no;
      if (!line.empty() && line.back() == '\r') line.pop_back();
      std::smatch m;
      if (top && !version_seen && std::regex_match(line, version_re)) {
        version_seen = true;
        dst << line << "\n";
        for (const auto& [name, value] : defines) dst << "#define " << name << " " << value << "\n";
        dst << line_directive(index, line_no + 1);
        continue;
      }
      if (std::regex_match(line, m, include_re)) {
        std::string name = m[1];
        if (climbs_out(name)) return climbing_include(name, path, line_no, files.include_dirs());
        std::string resolved = resolve(path, name);
        if (resolved.empty()) {
          Error e = make_error("#include \"" + name + "\" not found (looked next to " + path +
                               " and in the include directories)");
          e.file = path;
          e.line = line_no;
          return e;
        }
        for (const std::string& open : stack) {
          if (open == resolved) {
            Error e = make_error("#include \"" + name + "\" forms a cycle through " + resolved);
            e.file = path;
            e.line = line_no;
            return e;
          }
        }
        if (pasted.insert(resolved).second) {
          auto child = files.read(resolved);
          if (!child) {
            Error e = child.error();
            e.message = "#include \"" + name + "\": " + e.message;
            e.file = path;
            e.line = line_no;
            return e;
          }
          if (Status s = expand(resolved, *child, false, dst, defines); !s) return s;
        }
        dst << line_directive(index, line_no + 1);
        continue;
      }
      dst << line << "\n";
    }
    stack.pop_back();
    return {};
  }
};

}  // namespace

Result<PreprocessedShader> preprocess_shader(
    const std::string& path, const ShaderFileSystem& files,
    const std::vector<std::pair<std::string, std::string>>& defines) {
  auto text = files.read(path);
  if (!text) return text.error();
  Expander ex{files, {}, {path}, {}};
  std::ostringstream dst;
  if (Status s = ex.expand(path, *text, true, dst, defines); !s) return s.error();
  ex.out.text = dst.str();
  return std::move(ex.out);
}

Error map_compile_log(const std::string& log, const std::vector<std::string>& files,
                      const std::string& stage) {
  // Mesa: "0:12(3): error: ...", NVIDIA: "0(12) : error C0000: ...".
  static const std::regex loc_re(R"re(^(\d+)(?::(\d+)\((\d+)\)|\((\d+)\))\s*:\s*(.*)$)re");
  Error e = make_error(stage + " shader failed to compile");
  std::istringstream in(log);
  std::string line, mapped;
  while (std::getline(in, line)) {
    std::smatch m;
    if (std::regex_match(line, m, loc_re)) {
      size_t idx = std::stoul(m[1]);
      int ln = m[2].matched ? std::stoi(m[2]) : std::stoi(m[4]);
      if (ln >= kLinesPerShaderFile) {  // the line names the file (line_directive), not the driver's index
        idx = static_cast<size_t>(ln / kLinesPerShaderFile);
        ln %= kLinesPerShaderFile;
      }
      int col = m[3].matched ? std::stoi(m[3]) : 0;
      std::string file = idx < files.size() ? files[idx] : "<source " + std::string(m[1]) + ">";
      std::string rest = m[5];
      if (e.file.empty() && rest.find("error") != std::string::npos) {
        e.file = file;
        e.line = ln;
        e.column = col;
        e.message = stage + " shader: " + rest;
      }
      mapped += file + ":" + std::to_string(ln) + (col ? ":" + std::to_string(col) : "") + ": " + rest + "\n";
    } else if (!line.empty()) {
      mapped += line + "\n";
    }
  }
  if (e.file.empty() && !files.empty()) e.file = files[0];
  e.details = mapped;  // the whole mapped log, for the UI
  return e;
}

}  // namespace penumbra::gl
