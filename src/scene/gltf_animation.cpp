#include "scene/gltf_animation.h"

#include <algorithm>
#include <cmath>

#include "scene/gltf_accessor.h"

namespace prt {
namespace {

// Numbers (times and values) of every curve of one file, in all: a real file's animation holds
// a few million at most, and a few bytes of a hostile file must not ask for gigabytes.
constexpr size_t kMaxNumbers = size_t{1} << 24;
// Lines of left-out channels, one per animation, before the rest are only counted.
constexpr size_t kMaxDropLines = 8;

const char* const kPaths[] = {"translation", "rotation", "scale"};

std::string animationName(const tinygltf::Model& model, size_t index) {
  const std::string& name = model.animations[index].name;
  return "animation " + std::to_string(index) + (name.empty() ? "" : " '" + name + "'");
}

}  // namespace

GltfAnimations::GltfAnimations(const tinygltf::Model& model, ModelNotes& notes)
    : model_(model), notes_(notes), numbersLeft_(kMaxNumbers) {
  const size_t n = model.animations.size();
  dropped_.resize(n);
  played_.assign(n, 0);
  noted_.assign(n, 0);
  for (size_t a = 0; a < n; ++a) {
    const tinygltf::Animation& animation = model.animations[a];
    bool weights = false;
    for (size_t c = 0; c < animation.channels.size(); ++c) {
      const tinygltf::AnimationChannel& channel = animation.channels[c];
      const std::string what = "channel " + std::to_string(c);
      if (channel.target_path == "weights") {
        if (!weights) ++notes_.morphAnimations;
        weights = true;
        noted_[a] = 1;
        continue;
      }
      int path = -1;
      for (int p = 0; p < 3; ++p) {
        if (channel.target_path == kPaths[p]) path = p;
      }
      if (path < 0) {
        drop(a, what + " animates '" + channel.target_path + "', which no node has");
        continue;
      }
      const int node = channel.target_node;
      if (node < 0 || static_cast<size_t>(node) >= model.nodes.size()) {
        drop(a, what + " animates node " + std::to_string(node) + ", which does not exist");
        continue;
      }
      if (model.nodes[static_cast<size_t>(node)].matrix.size() == 16) {
        drop(a, what + " animates node " + std::to_string(node) +
                    ", which has a matrix (glTF animates only translation, rotation and scale)");
        continue;
      }
      if (channel.sampler < 0 || static_cast<size_t>(channel.sampler) >= animation.samplers.size()) {
        drop(a, what + " names sampler " + std::to_string(channel.sampler) + ", which does not exist");
        continue;
      }
      if (!targets_.try_emplace({node, path}, Channel{a, channel.sampler}).second) {
        ++duplicates_;
        noted_[a] = 1;
      }
    }
  }
}

void GltfAnimations::drop(size_t animation, const std::string& why) {
  noted_[animation] = 1;
  Dropped& d = dropped_[animation];
  if (d.channels++ == 0) d.first = why;
}

std::vector<std::array<int32_t, 3>> GltfAnimations::read(const std::vector<int>& nodes,
                                                         std::vector<Curve>& curves) {
  std::vector<std::array<int32_t, 3>> out(nodes.size(), {-1, -1, -1});
  for (size_t i = 0; i < nodes.size(); ++i) {
    for (int path = 0; path < 3; ++path) {
      const auto found = targets_.find({nodes[i], path});
      if (found != targets_.end()) out[i][static_cast<size_t>(path)] = curveOf(found->second, path, curves);
    }
  }
  return out;
}

int32_t GltfAnimations::curveOf(const Channel& channel, int path, std::vector<Curve>& curves) {
  const auto key = std::make_tuple(channel.animation, channel.sampler, path);
  if (const auto found = read_.find(key); found != read_.end()) return found->second;
  Curve curve;
  int32_t index = -1;
  if (readCurve(channel, path, curve)) {
    index = static_cast<int32_t>(curves.size());
    curves.push_back(std::move(curve));
    played_[channel.animation] = 1;
  }
  read_[key] = index;
  return index;
}

bool GltfAnimations::readCurve(const Channel& channel, int path, Curve& curve) {
  const tinygltf::AnimationSampler& s =
      model_.animations[channel.animation].samplers[static_cast<size_t>(channel.sampler)];
  const std::string what = "sampler " + std::to_string(channel.sampler) + " (" + kPaths[path] + ")";
  if (s.interpolation == "STEP") {
    curve.interpolation = Interpolation::step;
  } else if (s.interpolation == "LINEAR" || s.interpolation.empty()) {
    curve.interpolation = Interpolation::linear;
  } else if (s.interpolation == "CUBICSPLINE") {
    curve.interpolation = Interpolation::cubicSpline;
  } else {
    drop(channel.animation, what + " interpolates by '" + s.interpolation + "', which glTF does not define");
    return false;
  }
  curve.rotation = path == 1;
  curve.width = curve.rotation ? 4 : 3;
  try {
    const GltfAccessor input(model_, s.input, what + " input");
    const GltfAccessor output(model_, s.output, what + " output");
    const size_t keys = input.count();
    const size_t perKey = curve.interpolation == Interpolation::cubicSpline ? 3 : 1;
    // Without data an accessor is all zeros, its count bounded by no buffer: no key could be
    // told from the next.
    if (!input.hasData() || !output.hasData()) throw ModelFileError(what + " has an accessor without data");
    if (input.components() != 1) throw ModelFileError(what + ": its times are not scalars");
    if (output.components() != curve.width) {
      throw ModelFileError(what + ": its values are not " + std::to_string(curve.width) + "-vectors");
    }
    if (keys == 0) throw ModelFileError(what + " has no keys");
    if (output.count() / perKey != keys || output.count() % perKey != 0) {
      throw ModelFileError(what + " has " + std::to_string(output.count()) + " values for " +
                           std::to_string(keys) + " keys");
    }
    const size_t numbers = keys + output.count() * curve.width;  // no overflow: both < 2^31 * 16
    if (numbers > numbersLeft_) {
      throw ModelFileError(what + ": the file's keys exceed " + std::to_string(kMaxNumbers) + " numbers in all");
    }
    numbersLeft_ -= numbers;
    curve.times.resize(keys);
    for (size_t k = 0; k < keys; ++k) {
      const double t = input.get(k, 0);
      if (!std::isfinite(t)) throw ModelFileError(what + ": a key's time is not finite");
      if (k > 0 && !(t > curve.times[k - 1])) throw ModelFileError(what + ": its times do not increase");
      curve.times[k] = t;
    }
    curve.values.resize(output.count() * curve.width);
    for (size_t v = 0; v < output.count(); ++v) {
      for (int c = 0; c < curve.width; ++c) {
        const double x = output.get(v, c);
        if (!std::isfinite(x)) throw ModelFileError(what + ": a value is not finite");
        curve.values[v * curve.width + static_cast<size_t>(c)] = x;
      }
    }
  } catch (const ModelFileError& e) {
    drop(channel.animation, e.what());
    return false;
  }
  return curve.wellFormed();
}

void GltfAnimations::warn(std::vector<std::string>& warnings) {
  const std::string head = "model file \"" + notes_.file + "\": ";
  size_t lines = 0, more = 0;
  for (size_t a = 0; a < dropped_.size(); ++a) {
    const Dropped& d = dropped_[a];
    if (d.channels == 0) continue;
    if (lines++ < kMaxDropLines) {
      warnings.push_back(head + animationName(model_, a) + ": " + std::to_string(d.channels) +
                         (d.channels == 1 ? " channel is" : " channels are") +
                         " not played (the first: " + d.first + ")");
    } else {
      ++more;
    }
  }
  if (more > 0) {
    warnings.push_back(head + std::to_string(more) + " more animations have channels that are not played");
  }
  if (duplicates_ > 0) {
    warnings.push_back(head + std::to_string(duplicates_) +
                       (duplicates_ == 1 ? " channel is" : " channels are") +
                       " ignored: an earlier channel animates the same node's translation, "
                       "rotation or scale");
  }
  // What the lines above do not already say: animations that move nothing rendered.
  for (size_t a = 0; a < played_.size(); ++a) {
    if (!played_[a] && !noted_[a]) ++notes_.animations;
  }
}

}  // namespace prt
