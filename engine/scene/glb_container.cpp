#include "scene/glb_container.h"

#include <cstdint>
#include <cstring>

namespace penumbra::scene::glb {

namespace {

std::uint32_t u32_at(std::string_view bytes, std::size_t at) {
  std::uint32_t v = 0;
  std::memcpy(&v, bytes.data() + at, 4);
  return v;
}

void append_u32(std::string& out, std::uint32_t v) { out.append(reinterpret_cast<const char*>(&v), 4); }

}  // namespace

Result<Chunks> split(std::string_view bytes, const std::string& file) {
  auto fail = [&](const std::string& why) { return file_error(file, "invalid or truncated .glb file: " + why); };
  if (bytes.size() < 20) return fail("shorter than its 12-byte header and first chunk header");
  if (bytes.substr(0, 4) != "glTF") return fail("it does not start with 'glTF'");
  if (u32_at(bytes, 4) != 2) return fail("container version " + std::to_string(u32_at(bytes, 4)) + ", 2 expected");
  // Bytes past the stated length are not part of the container (tinygltf ignores them too).
  if (u32_at(bytes, 8) > bytes.size())
    return fail("its header gives a length of " + std::to_string(u32_at(bytes, 8)) + " bytes; the file has " +
                std::to_string(bytes.size()));
  if (u32_at(bytes, 8) < 20) return fail("its header gives a length of " + std::to_string(u32_at(bytes, 8)) + " bytes");
  bytes = bytes.substr(0, u32_at(bytes, 8));
  if (bytes.substr(16, 4) != "JSON") return fail("its first chunk is not JSON");
  const std::size_t json_length = u32_at(bytes, 12);
  if (json_length > bytes.size() - 20)
    return fail("its JSON chunk of " + std::to_string(json_length) + " bytes runs past the end of the file");
  Chunks out;
  out.json = bytes.substr(20, json_length);
  const std::size_t rest = 20 + json_length;
  if (rest == bytes.size()) return out;
  if (bytes.size() - rest < 8) return fail("a chunk header is cut off after the JSON chunk");
  const std::size_t bin_length = u32_at(bytes, rest);
  if (bytes.substr(rest + 4, 4) != std::string_view("BIN\0", 4)) return fail("its second chunk is not BIN");
  if (bin_length > bytes.size() - rest - 8)
    return fail("its BIN chunk of " + std::to_string(bin_length) + " bytes runs past the end of the file");
  out.bin = bytes.substr(rest + 8, bin_length);
  return out;
}

std::string join(std::string_view json, std::optional<std::string_view> bin) {
  std::string chunk(json);
  while (chunk.size() % 4 != 0) chunk += ' ';
  std::string out = "glTF";
  append_u32(out, 2);
  append_u32(out, 0);  // total length, below
  append_u32(out, static_cast<std::uint32_t>(chunk.size()));
  out += "JSON";
  out += chunk;
  if (bin) {
    append_u32(out, static_cast<std::uint32_t>(bin->size()));
    out.append("BIN\0", 4);
    out += *bin;
  }
  const auto total = static_cast<std::uint32_t>(out.size());
  std::memcpy(out.data() + 8, &total, 4);
  return out;
}

}  // namespace penumbra::scene::glb
