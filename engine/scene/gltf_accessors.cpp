#include "scene/gltf_accessors.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <tiny_gltf.h>

namespace penumbra::scene::gltf {

static Error accessor_error(const std::string& file, const std::string& what, const std::string& msg) {
  return file_error(file, msg, what);
}

static size_t component_size(int type) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_INT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0;
  }
}

static int component_count(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return 1;
    case TINYGLTF_TYPE_VEC2: return 2;
    case TINYGLTF_TYPE_VEC3: return 3;
    case TINYGLTF_TYPE_VEC4: return 4;
    default: return 0;  // matrices are never vertex attributes or indices we read
  }
}

Result<AccessorView> view_accessor(const tinygltf::Model& model, int index, const std::string& file,
                                   const std::string& what) {
  const std::string id = "accessor " + std::to_string(index);
  if (index < 0 || static_cast<size_t>(index) >= model.accessors.size())
    return accessor_error(file, what, id + " does not exist (the file has " +
                                          std::to_string(model.accessors.size()) + " accessors)");
  const tinygltf::Accessor& acc = model.accessors[static_cast<size_t>(index)];
  if (acc.sparse.isSparse) return accessor_error(file, what, id + " is sparse, which is not supported");
  if (acc.bufferView < 0 || static_cast<size_t>(acc.bufferView) >= model.bufferViews.size())
    return accessor_error(file, what, id + " has no valid bufferView (index " +
                                          std::to_string(acc.bufferView) + ")");
  const tinygltf::BufferView& bv = model.bufferViews[static_cast<size_t>(acc.bufferView)];
  if (bv.buffer < 0 || static_cast<size_t>(bv.buffer) >= model.buffers.size())
    return accessor_error(file, what, "bufferView " + std::to_string(acc.bufferView) +
                                          " refers to missing buffer " + std::to_string(bv.buffer));
  const std::vector<unsigned char>& buffer = model.buffers[static_cast<size_t>(bv.buffer)].data;

  AccessorView v;
  v.component_type = acc.componentType;
  v.components = component_count(acc.type);
  v.normalized = acc.normalized;
  const size_t csize = component_size(acc.componentType);
  if (csize == 0 || v.components == 0)
    return accessor_error(file, what, id + " has an unsupported component type " +
                                          std::to_string(acc.componentType) + " or type " +
                                          std::to_string(acc.type));
  v.element_size = csize * static_cast<size_t>(v.components);
  v.stride = bv.byteStride != 0 ? bv.byteStride : v.element_size;
  v.count = acc.count;
  if (v.stride < v.element_size)
    return accessor_error(file, what, id + " has byteStride " + std::to_string(v.stride) +
                                          " smaller than its element size " + std::to_string(v.element_size));
  // Bounds: the view must lie in the buffer, and the last element must end inside the view.
  // Written so that no intermediate product can overflow.
  if (bv.byteOffset > buffer.size() || bv.byteLength > buffer.size() - bv.byteOffset)
    return accessor_error(file, what, "bufferView " + std::to_string(acc.bufferView) + " (offset " +
                                          std::to_string(bv.byteOffset) + ", length " +
                                          std::to_string(bv.byteLength) + ") lies outside its buffer of " +
                                          std::to_string(buffer.size()) + " bytes");
  if (v.count == 0) return accessor_error(file, what, id + " has count 0");
  const size_t view_len = bv.byteLength;
  const bool fits = acc.byteOffset <= view_len && v.element_size <= view_len - acc.byteOffset &&
                    (v.count - 1) <= (view_len - acc.byteOffset - v.element_size) / v.stride;
  if (!fits)
    return accessor_error(file, what, id + " (offset " + std::to_string(acc.byteOffset) + ", count " +
                                          std::to_string(v.count) + ", stride " + std::to_string(v.stride) +
                                          ") reads past the end of bufferView " +
                                          std::to_string(acc.bufferView) + " (" + std::to_string(view_len) +
                                          " bytes)");
  v.data = buffer.data() + bv.byteOffset + acc.byteOffset;
  return v;
}

template <class T>
static T load(const uint8_t* p) {
  T t;
  std::memcpy(&t, p, sizeof(T));  // glTF data need not be aligned
  return t;
}

// One component as a float: floats as they are; integers dequantized as KHR_mesh_quantization
// and the glTF 2.0 spec (3.11, "normalized") state: normalized signed c -> max(c / max, -1),
// unsigned c -> c / max; not normalized, the integer's value.
static float component(const uint8_t* p, int type, bool normalized) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return load<float>(p);
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
      const float c = static_cast<float>(load<int8_t>(p));
      return normalized ? std::max(c / 127.0f, -1.0f) : c;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? p[0] / 255.0f : static_cast<float>(p[0]);
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
      const float c = static_cast<float>(load<int16_t>(p));
      return normalized ? std::max(c / 32767.0f, -1.0f) : c;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      const float c = static_cast<float>(load<uint16_t>(p));
      return normalized ? c / 65535.0f : c;
    }
    default: return 0.0f;  // refused by read_floats before it gets here
  }
}

// `n` floats per element from a FLOAT, BYTE, UNSIGNED_BYTE, SHORT or UNSIGNED_SHORT accessor.
template <int N>
static Result<std::vector<glm::vec<N, float>>> read_floats(const tinygltf::Model& model, int accessor,
                                                          AttributeKind kind, const std::string& file,
                                                          const std::string& what) {
  Result<AccessorView> v = view_accessor(model, accessor, file, what);
  if (!v) return v.error();
  const std::string id = "accessor " + std::to_string(accessor);
  if (v->components != N)
    return accessor_error(file, what, id + " must be VEC" + std::to_string(N));
  const int t = v->component_type;
  const bool integer = t == TINYGLTF_COMPONENT_TYPE_BYTE || t == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                       t == TINYGLTF_COMPONENT_TYPE_SHORT || t == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
  if (t != TINYGLTF_COMPONENT_TYPE_FLOAT && !integer)
    return accessor_error(file, what, id + " has component type " + std::to_string(t) +
                                          "; FLOAT, or with KHR_mesh_quantization BYTE, UNSIGNED_BYTE, SHORT or "
                                          "UNSIGNED_SHORT, are allowed");
  // KHR_mesh_quantization: normals are normalized BYTE or SHORT, never raw integers.
  if ((kind == AttributeKind::normal || kind == AttributeKind::rotation) && integer &&
      (!v->normalized || t == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE || t == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT))
    return accessor_error(file, what, id + " holds integers that are not normalized BYTE or SHORT (the only "
                                          "integer forms of a normal or a rotation: KHR_mesh_quantization, "
                                          "EXT_mesh_gpu_instancing)");
  const size_t csize = t == TINYGLTF_COMPONENT_TYPE_FLOAT ? 4 : (t == TINYGLTF_COMPONENT_TYPE_SHORT ||
                                                                 t == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) ? 2 : 1;
  std::vector<glm::vec<N, float>> out(v->count);
  for (size_t i = 0; i < v->count; ++i) {
    const uint8_t* p = v->data + i * v->stride;
    for (int c = 0; c < N; ++c) {
      const float x = component(p + static_cast<size_t>(c) * csize, t, v->normalized);
      // A NaN or infinite value draws nothing (or everything) and poisons the bounds the camera
      // and light are fitted to: refuse it where it is.
      if (!std::isfinite(x))
        return accessor_error(file, what, id + " element " + std::to_string(i) + " is not finite (NaN or infinity)");
      out[i][c] = x;
    }
  }
  return out;
}

Result<std::vector<glm::vec3>> read_vec3(const tinygltf::Model& model, int accessor, AttributeKind kind,
                                         const std::string& file, const std::string& what) {
  return read_floats<3>(model, accessor, kind, file, what);
}

Result<std::vector<glm::vec4>> read_vec4(const tinygltf::Model& model, int accessor, AttributeKind kind,
                                         const std::string& file, const std::string& what) {
  return read_floats<4>(model, accessor, kind, file, what);
}

Result<std::vector<glm::vec2>> read_uv(const tinygltf::Model& model, int accessor, const std::string& file,
                                       const std::string& what) {
  return read_floats<2>(model, accessor, AttributeKind::texcoord, file, what);
}

Result<std::vector<uint32_t>> read_indices(const tinygltf::Model& model, int accessor, size_t vertex_count,
                                           const std::string& file, const std::string& what) {
  Result<AccessorView> v = view_accessor(model, accessor, file, what);
  if (!v) return v.error();
  if (v->components != 1)
    return accessor_error(file, what, "index accessor " + std::to_string(accessor) + " must be SCALAR");
  std::vector<uint32_t> out(v->count);
  for (size_t i = 0; i < v->count; ++i) {
    const uint8_t* p = v->data + i * v->stride;
    switch (v->component_type) {
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: out[i] = p[0]; break;
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: out[i] = load<uint16_t>(p); break;
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: out[i] = load<uint32_t>(p); break;
      default:
        return accessor_error(file, what, "index accessor " + std::to_string(accessor) +
                                              " must be unsigned byte, short or int");
    }
    if (out[i] >= vertex_count)
      return accessor_error(file, what, "index " + std::to_string(out[i]) + " at position " +
                                            std::to_string(i) + " is out of range (the primitive has " +
                                            std::to_string(vertex_count) + " vertices)");
  }
  return out;
}

}  // namespace penumbra::scene::gltf
