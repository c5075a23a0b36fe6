#pragma once
// GltfAccessor: one accessor of a glTF file read by tinygltf, every byte of its elements
// checked to lie inside its buffer view and buffer before any is read (tinygltf leaves those
// ranges unchecked). Shared by the glTF reader's meshes (gltf_reader.cpp) and animations
// (gltf_animation.cpp). Throws ModelFileError, saying `what`, for an accessor it cannot read.

#include <tiny_gltf.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <string>

#include "scene/model_file.h"

namespace prt {

class GltfAccessor {
 public:
  static constexpr size_t kMaxElements = size_t{1} << 31;  // vertices or indices of one accessor

  GltfAccessor(const tinygltf::Model& model, int index, const std::string& what) {
    if (index < 0 || static_cast<size_t>(index) >= model.accessors.size()) {
      fail(what + " names accessor " + std::to_string(index) + ", which does not exist");
    }
    const tinygltf::Accessor& a = model.accessors[static_cast<size_t>(index)];
    if (a.sparse.isSparse) fail(what + " uses a sparse accessor, which PRT does not read");
    components_ = tinygltf::GetNumComponentsInType(static_cast<uint32_t>(a.type));
    componentBytes_ = tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(a.componentType));
    if (components_ <= 0 || components_ > 16 || componentBytes_ <= 0) {
      fail(what + ": accessor " + std::to_string(index) + " has an unknown type");
    }
    type_ = a.componentType;
    normalized_ = a.normalized;
    count_ = a.count;
    if (count_ > kMaxElements) fail(what + ": accessor " + std::to_string(index) + " is too long");
    if (a.bufferView < 0) return;  // all zeros (glTF 2.0, 3.6.2.3)
    if (static_cast<size_t>(a.bufferView) >= model.bufferViews.size()) {
      fail(what + ": buffer view " + std::to_string(a.bufferView) + " does not exist");
    }
    const tinygltf::BufferView& view = model.bufferViews[static_cast<size_t>(a.bufferView)];
    if (view.buffer < 0 || static_cast<size_t>(view.buffer) >= model.buffers.size()) {
      fail(what + ": buffer " + std::to_string(view.buffer) + " does not exist");
    }
    const std::vector<unsigned char>& buffer = model.buffers[static_cast<size_t>(view.buffer)].data;
    const size_t element = static_cast<size_t>(components_) * static_cast<size_t>(componentBytes_);
    stride_ = view.byteStride != 0 ? view.byteStride : element;
    if (stride_ < element && count_ > 1) fail(what + ": a stride shorter than an element");
    if (view.byteOffset > buffer.size() || view.byteLength > buffer.size() - view.byteOffset) {
      fail(what + ": buffer view " + std::to_string(a.bufferView) + " reaches past its buffer");
    }
    if (count_ > 0) {
      // offset + (count - 1) * stride + element <= byteLength, without overflowing.
      const size_t length = view.byteLength;
      if (a.byteOffset > length || element > length - a.byteOffset ||
          (count_ - 1) > (length - a.byteOffset - element) / std::max<size_t>(stride_, 1)) {
        fail(what + ": accessor " + std::to_string(index) + " reaches past its buffer view");
      }
    }
    data_ = buffer.data() + view.byteOffset + a.byteOffset;
  }

  size_t count() const { return count_; }
  int components() const { return components_; }
  bool hasData() const { return data_ != nullptr; }
  bool isFloat() const { return type_ == TINYGLTF_COMPONENT_TYPE_FLOAT; }

  // Component c of element i, as a number (normalised integers in [0, 1] or [-1, 1]).
  double get(size_t i, int c) const {
    if (data_ == nullptr) return 0;
    const unsigned char* p = data_ + i * stride_ + static_cast<size_t>(c * componentBytes_);
    switch (type_) {
      case TINYGLTF_COMPONENT_TYPE_FLOAT: return load<float>(p);
      case TINYGLTF_COMPONENT_TYPE_DOUBLE: return load<double>(p);
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return scaled(load<uint8_t>(p), 255.0);
      case TINYGLTF_COMPONENT_TYPE_BYTE: return signedScaled(load<int8_t>(p), 127.0);
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return scaled(load<uint16_t>(p), 65535.0);
      case TINYGLTF_COMPONENT_TYPE_SHORT: return signedScaled(load<int16_t>(p), 32767.0);
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return scaled(load<uint32_t>(p), 4294967295.0);
      case TINYGLTF_COMPONENT_TYPE_INT: return signedScaled(load<int32_t>(p), 2147483647.0);
      default: return 0;
    }
  }
  // Element i of an index accessor.
  uint64_t index(size_t i) const {
    if (data_ == nullptr) return 0;
    const unsigned char* p = data_ + i * stride_;
    switch (type_) {
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return load<uint8_t>(p);
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return load<uint16_t>(p);
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return load<uint32_t>(p);
      default: return ~uint64_t{0};
    }
  }
  bool isIndexType() const {
    return components_ == 1 && (type_ == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                                type_ == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ||
                                type_ == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);
  }

 private:
  template <typename T>
  static T load(const unsigned char* p) {
    T v;
    std::memcpy(&v, p, sizeof v);
    return v;
  }
  double scaled(double v, double range) const { return normalized_ ? v / range : v; }
  double signedScaled(double v, double range) const {
    return normalized_ ? std::max(v / range, -1.0) : v;
  }
  [[noreturn]] static void fail(const std::string& why) { throw ModelFileError(why); }

  const unsigned char* data_ = nullptr;
  size_t count_ = 0, stride_ = 0;
  int components_ = 0, componentBytes_ = 0, type_ = 0;
  bool normalized_ = false;
};

}  // namespace prt
