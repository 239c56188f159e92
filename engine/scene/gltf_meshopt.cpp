#include "scene/gltf_meshopt.h"

#include <cstring>
#include <vector>

#include <meshoptimizer.h>
#include <tiny_gltf.h>

namespace penumbra::scene::gltf {

namespace {

// Why a stream's parameters cannot be decoded, or empty (EXT_meshopt_compression, "Mode" and
// "Filter"; the same limits libmeshoptimizer 0.18 asserts on).
std::string unusable(const MeshoptView& v) {
  using Mode = MeshoptView::Mode;
  using Filter = MeshoptView::Filter;
  if (v.mode == Mode::attributes && (v.byte_stride % 4 != 0 || v.byte_stride > 256))
    return "ATTRIBUTES needs a byteStride that is a multiple of 4, at most 256";
  if (v.mode != Mode::attributes && v.byte_stride != 2 && v.byte_stride != 4)
    return "TRIANGLES and INDICES need a byteStride of 2 or 4";
  if (v.mode == Mode::triangles && v.count % 3 != 0) return "TRIANGLES needs a count that is a multiple of 3";
  if (v.filter != Filter::none && v.mode != Mode::attributes) return "filters apply to ATTRIBUTES only";
  if (v.filter == Filter::octahedral && v.byte_stride != 4 && v.byte_stride != 8)
    return "OCTAHEDRAL needs a byteStride of 4 or 8";
  if (v.filter == Filter::quaternion && v.byte_stride != 8) return "QUATERNION needs a byteStride of 8";
  return {};
}

}  // namespace

Status decode_meshopt_views(tinygltf::Model& model, const ExtensionData& extensions, const std::string& file) {
  for (const auto& [buffer, length] : extensions.fallback_buffers)
    if (buffer < model.buffers.size()) model.buffers[buffer].data.assign(length, 0);
  for (const auto& [index, v] : extensions.meshopt) {
    const std::string where = "bufferView " + std::to_string(index) + " (EXT_meshopt_compression)";
    if (index >= model.bufferViews.size()) return file_error(file, "bufferView does not exist", where);
    if (const std::string why = unusable(v); !why.empty()) return file_error(file, why, where);
    const tinygltf::BufferView& view = model.bufferViews[index];
    const std::vector<unsigned char>& source = model.buffers[static_cast<size_t>(v.buffer)].data;
    if (v.byte_offset > source.size() || v.byte_length > source.size() - v.byte_offset)
      return file_error(file, "the compressed stream (offset " + std::to_string(v.byte_offset) + ", length " +
                                  std::to_string(v.byte_length) + ") lies outside buffer " + std::to_string(v.buffer) +
                                  " (" + std::to_string(source.size()) + " bytes)", where);
    if (view.buffer < 0 || static_cast<size_t>(view.buffer) >= model.buffers.size())
      return file_error(file, "refers to missing buffer " + std::to_string(view.buffer), where);
    std::vector<unsigned char>& target = model.buffers[static_cast<size_t>(view.buffer)].data;
    const size_t decoded = v.count * v.byte_stride;  // count < 2^31, stride <= 256: no overflow
    if (decoded > view.byteLength)
      return file_error(file, "decodes to " + std::to_string(v.count) + " x " + std::to_string(v.byte_stride) +
                                  " bytes, more than the bufferView's byteLength " + std::to_string(view.byteLength),
                        where);
    if (view.byteOffset > target.size() || view.byteLength > target.size() - view.byteOffset)
      return file_error(file, "the bufferView (offset " + std::to_string(view.byteOffset) + ", length " +
                                  std::to_string(view.byteLength) + ") lies outside buffer " +
                                  std::to_string(view.buffer) + " (" + std::to_string(target.size()) + " bytes)",
                        where);
    std::vector<unsigned char> out(decoded);
    const unsigned char* in = source.data() + v.byte_offset;
    int rc = 0;
    switch (v.mode) {
      case MeshoptView::Mode::attributes:
        rc = meshopt_decodeVertexBuffer(out.data(), v.count, v.byte_stride, in, v.byte_length);
        break;
      case MeshoptView::Mode::triangles:
        rc = meshopt_decodeIndexBuffer(out.data(), v.count, v.byte_stride, in, v.byte_length);
        break;
      case MeshoptView::Mode::indices:
        rc = meshopt_decodeIndexSequence(out.data(), v.count, v.byte_stride, in, v.byte_length);
        break;
    }
    if (rc != 0)
      return file_error(file, "the compressed stream does not decode (libmeshoptimizer error " +
                                  std::to_string(rc) + ": truncated or damaged)", where);
    switch (v.filter) {
      case MeshoptView::Filter::none: break;
      case MeshoptView::Filter::octahedral: meshopt_decodeFilterOct(out.data(), v.count, v.byte_stride); break;
      case MeshoptView::Filter::quaternion: meshopt_decodeFilterQuat(out.data(), v.count, v.byte_stride); break;
      case MeshoptView::Filter::exponential: meshopt_decodeFilterExp(out.data(), v.count, v.byte_stride); break;
    }
    std::memcpy(target.data() + view.byteOffset, out.data(), out.size());
  }
  return {};
}

}  // namespace penumbra::scene::gltf
