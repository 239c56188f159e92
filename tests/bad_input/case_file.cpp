#include "case_file.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace penumbra::test {

namespace {

std::string expand_repeats(const std::string& text) {
  std::string out;
  size_t pos = 0;
  while (true) {
    size_t at = text.find("{repeat ", pos);
    if (at == std::string::npos) break;
    size_t close = text.find('}', at);
    size_t end = text.find("{end}", close);
    if (close == std::string::npos || end == std::string::npos) break;
    out += text.substr(pos, at - pos);
    const long count = std::stol(text.substr(at + 8, close - at - 8));
    const std::string unit = text.substr(close + 1, end - close - 1);
    for (long i = 0; i < count; ++i) out += unit;
    pos = end + 5;
  }
  return out + text.substr(pos);
}

std::string decode_base64(const std::string& text) {
  auto value = [](char c) -> int {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+') return 62;
    if (c == '/') return 63;
    return -1;
  };
  std::string out;
  int bits = 0, buffer = 0;
  for (char c : text) {
    int v = value(c);
    if (v < 0) continue;
    buffer = (buffer << 6) | v;
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out += static_cast<char>((buffer >> bits) & 0xff);
    }
  }
  return out;
}

}  // namespace

BadInputCase read_case(const std::string& path) {
  BadInputCase c;
  c.name = std::filesystem::path(path).stem().string();
  std::ifstream in(path, std::ios::binary);
  std::string line;
  std::string* file = nullptr;
  bool base64 = false;
  auto finish_file = [&] {
    if (!file) return;
    if (!file->empty() && file->back() == '\n') file->pop_back();
    *file = base64 ? decode_base64(*file) : expand_repeats(*file);
  };
  while (std::getline(in, line)) {
    if (line.rfind("--- ", 0) == 0) {
      finish_file();
      std::istringstream header(line.substr(4));
      std::string name, encoding;
      header >> name >> encoding;
      base64 = encoding == "base64";
      c.files.emplace_back(name, "");
      file = &c.files.back().second;
      continue;
    }
    if (file) {
      *file += line + "\n";
    } else if (line.rfind("# ", 0) == 0 && c.description.empty()) {
      c.description = line.substr(2);
    } else if (line.rfind("run: ", 0) == 0) {
      c.run = line.substr(5);
    } else if (line.rfind("env: ", 0) == 0) {
      c.env.push_back(line.substr(5));
    } else if (line.rfind("exit: ", 0) == 0) {
      c.exit_code = std::stoi(line.substr(6));
    } else if (line.rfind("stderr: ", 0) == 0) {
      c.stderr_contains.push_back(line.substr(8));
    } else if (!line.empty() && line[0] != '#') {
      c.problem = "unknown line '" + line + "'";
    }
  }
  finish_file();
  if (c.run.empty()) c.problem = "no 'run:' line";
  if (c.description.empty()) c.problem = "no '# description' line";
  return c;
}

std::vector<std::string> list_cases(const std::string& dir) {
  std::vector<std::string> out;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.path().extension() == ".case") out.push_back(e.path().string());
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace penumbra::test
