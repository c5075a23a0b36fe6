#pragma once
// GltfAccessor: one accessor of a glTF file read by tinygltf, every byte of its elements
// checked to lie inside its buffer view and buffer before any is read (tinygltf leaves those
// ranges unchecked), sparse ones included (elements replaced by index). Shared by the glTF
// reader's meshes (gltf_reader.cpp) and animations (gltf_animation.cpp). Throws
// ModelFileError, saying `what`, for an accessor it cannot read.

#include <tiny_gltf.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "scene/model_file.h"

namespace prt {

class GltfAccessor {
 public:
  static constexpr size_t kMaxElements = size_t{1} << 31;  // vertices or indices of one accessor
  // Of an accessor without a buffer view (zeros, some replaced by sparse values): no buffer
  // bounds its count, so a few bytes of JSON could ask for any amount of memory. A reader
  // whose count is bounded otherwise (an attribute must have POSITION's) may allow more.
  static constexpr size_t kMaxZeroFilled = size_t{1} << 20;

  GltfAccessor(const tinygltf::Model& model, int index, const std::string& what,
               size_t maxZeroFilled = kMaxZeroFilled) {
    if (index < 0 || static_cast<size_t>(index) >= model.accessors.size()) {
      fail(what + " names accessor " + std::to_string(index) + ", which does not exist");
    }
    const tinygltf::Accessor& a = model.accessors[static_cast<size_t>(index)];
    const std::string name = "accessor " + std::to_string(index);
    components_ = tinygltf::GetNumComponentsInType(static_cast<uint32_t>(a.type));
    componentBytes_ = tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(a.componentType));
    if (components_ <= 0 || components_ > 16 || componentBytes_ <= 0) {
      fail(what + ": " + name + " has an unknown type");
    }
    type_ = a.componentType;
    normalized_ = a.normalized;
    count_ = a.count;
    if (count_ > kMaxElements) fail(what + ": " + name + " is too long");
    const size_t element = static_cast<size_t>(components_) * static_cast<size_t>(componentBytes_);
    // Without a buffer view: all zeros (glTF 2.0, 3.6.2.3), unless sparse values replace some.
    if (a.bufferView >= 0) {
      data_ = elements(model, a.bufferView, a.byteOffset, count_, element, false, stride_, what,
                       name);
    } else if (a.sparse.isSparse && count_ > maxZeroFilled) {
      fail(what + ": " + name + " has no buffer view and " + std::to_string(count_) +
           " elements, more than the " + std::to_string(maxZeroFilled) + " PRT fills with zeros");
    }
    if (a.sparse.isSparse) readSparse(model, a, element, what, name + "'s sparse");
  }

  size_t count() const { return count_; }
  int components() const { return components_; }
  // False for an accessor of zeros only (no buffer view, no sparse values).
  bool hasData() const { return data_ != nullptr || !sparseAt_.empty(); }
  // Zeros but for the sparse values: only the elements sparseIndices() names are not zero.
  bool onlySparse() const { return data_ == nullptr && !sparseAt_.empty(); }
  const std::vector<uint32_t>& sparseIndices() const { return sparseAt_; }
  bool isFloat() const { return type_ == TINYGLTF_COMPONENT_TYPE_FLOAT; }

  // Component c of element i, as a number (normalised integers in [0, 1] or [-1, 1]).
  double get(size_t i, int c) const {
    const unsigned char* p = element(i);
    if (p == nullptr) return 0;
    p += static_cast<size_t>(c * componentBytes_);
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
    const unsigned char* p = element(i);
    return p == nullptr ? 0 : unsignedAt(p, type_);
  }
  bool isIndexType() const {
    return components_ == 1 && (type_ == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                                type_ == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ||
                                type_ == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);
  }

 private:
  // An unsigned integer of glTF component type `type` at p; ~0 for another type.
  static uint64_t unsignedAt(const unsigned char* p, int type) {
    switch (type) {
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return load<uint8_t>(p);
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return load<uint16_t>(p);
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return load<uint32_t>(p);
      default: return ~uint64_t{0};
    }
  }

  // The first byte of element i: from the sparse values when they replace it, else from the
  // buffer view; null for an element of zeros.
  const unsigned char* element(size_t i) const {
    if (!sparseAt_.empty()) {
      const auto at = std::lower_bound(sparseAt_.begin(), sparseAt_.end(), i);
      if (at != sparseAt_.end() && *at == i) {
        return sparseValues_ + static_cast<size_t>(at - sparseAt_.begin()) * sparseStride_;
      }
    }
    return data_ == nullptr ? nullptr : data_ + i * stride_;
  }

  // The bytes of `count` elements of `element` bytes at `offset` in buffer view `viewIndex`,
  // each one checked to lie inside the view and its buffer; `stride` set to the view's, or to
  // the element's when `tight` (sparse indices and values are tightly packed whatever the view
  // says, glTF 2.0, 3.6.2.3).
  static const unsigned char* elements(const tinygltf::Model& model, int viewIndex, size_t offset,
                                       size_t count, size_t element, bool tight, size_t& stride,
                                       const std::string& what, const std::string& name) {
    if (viewIndex < 0 || static_cast<size_t>(viewIndex) >= model.bufferViews.size()) {
      fail(what + ": " + name + " names buffer view " + std::to_string(viewIndex) +
           ", which does not exist");
    }
    const tinygltf::BufferView& view = model.bufferViews[static_cast<size_t>(viewIndex)];
    if (view.buffer < 0 || static_cast<size_t>(view.buffer) >= model.buffers.size()) {
      fail(what + ": buffer " + std::to_string(view.buffer) + " does not exist");
    }
    const std::vector<unsigned char>& buffer = model.buffers[static_cast<size_t>(view.buffer)].data;
    stride = view.byteStride != 0 && !tight ? view.byteStride : element;
    if (stride < element && count > 1) fail(what + ": a stride shorter than an element");
    if (view.byteOffset > buffer.size() || view.byteLength > buffer.size() - view.byteOffset) {
      fail(what + ": buffer view " + std::to_string(viewIndex) + " reaches past its buffer");
    }
    if (count > 0) {
      // offset + (count - 1) * stride + element <= byteLength, without overflowing.
      const size_t length = view.byteLength;
      if (offset > length || element > length - offset ||
          (count - 1) > (length - offset - element) / std::max<size_t>(stride, 1)) {
        fail(what + ": " + name + " reaches past its buffer view");
      }
    }
    return buffer.data() + view.byteOffset + offset;
  }

  // Sparse storage (glTF 2.0, 3.6.2.3): `count` elements given by index, replacing those of
  // the buffer view (or of zeros). The indices must rise strictly and stay below the count.
  void readSparse(const tinygltf::Model& model, const tinygltf::Accessor& a, size_t element,
                  const std::string& what, const std::string& name) {
    const auto& sparse = a.sparse;
    if (sparse.count < 1 || static_cast<size_t>(sparse.count) > count_) {
      fail(what + ": " + name + " count " + std::to_string(sparse.count) +
           " is not between 1 and the accessor's count, " + std::to_string(count_));
    }
    if (sparse.indices.byteOffset < 0 || sparse.values.byteOffset < 0) {
      fail(what + ": " + name + " has a negative byte offset");
    }
    const auto n = static_cast<size_t>(sparse.count);
    const int indexType = sparse.indices.componentType;
    if (indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
        indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) {
      fail(what + ": " + name + " indices are not unsigned integers");
    }
    const auto indexBytes =
        static_cast<size_t>(tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(indexType)));
    size_t indexStride = 0;
    const unsigned char* indices =
        elements(model, sparse.indices.bufferView, static_cast<size_t>(sparse.indices.byteOffset),
                 n, indexBytes, true, indexStride, what, name + " indices");
    sparseValues_ =
        elements(model, sparse.values.bufferView, static_cast<size_t>(sparse.values.byteOffset), n,
                 element, true, sparseStride_, what, name + " values");
    sparseAt_.resize(n);
    for (size_t k = 0; k < n; ++k) {
      const uint64_t at = unsignedAt(indices + k * indexStride, indexType);
      if (at >= count_) {
        fail(what + ": " + name + " index " + std::to_string(at) + " is not below the count, " +
             std::to_string(count_));
      }
      if (k > 0 && at <= sparseAt_[k - 1]) fail(what + ": " + name + " indices do not rise");
      sparseAt_[k] = static_cast<uint32_t>(at);
    }
  }

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
  std::vector<uint32_t> sparseAt_;  // the indices of the elements sparse values replace
  const unsigned char* sparseValues_ = nullptr;
  size_t sparseStride_ = 0;
  int components_ = 0, componentBytes_ = 0, type_ = 0;
  bool normalized_ = false;
};

}  // namespace prt
