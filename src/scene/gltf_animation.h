#pragma once
// The animations of a glTF 2.0 file as curves (animation.h) for the nodes they move: every
// animation of the file plays at once, each channel on a node's translation, rotation or scale
// with its sampler's STEP, LINEAR or CUBICSPLINE keys. Used by the glTF reader
// (gltf_reader.cpp), which builds the file's ModelRig from them.
//
// Read in two steps, so that channels moving only what is never rendered (a skin's bones) cost
// nothing: the channels are listed first (their targets checked), and their samplers are read
// only for the nodes the reader asks for. Nothing in a channel can fail the file: a channel
// that cannot be played (a missing node or sampler, an accessor of the wrong type or count,
// times that are not finite or not increasing, keys beyond what a file may hold) is left out
// with a warning naming its animation, a second channel for one node's path is ignored, and
// morph weights are counted for the one line that says morph targets are not applied.

#include <array>
#include <cstdint>
#include <map>
#include <tuple>
#include <string>
#include <vector>

#include "scene/animation.h"
#include "scene/model_notes.h"

namespace tinygltf {
class Model;
}

namespace prt {

class GltfAnimations {
 public:
  // Lists the channels of every animation of `model` (which must outlive this).
  GltfAnimations(const tinygltf::Model& model, ModelNotes& notes);

  // Whether any channel may move a node's translation, rotation or scale.
  bool any() const { return !targets_.empty(); }
  // Reads the curves driving `nodes` (glTF node indices) into `curves`; returns per node its
  // translation, rotation and scale curves (indices into `curves`, -1: none).
  std::vector<std::array<int32_t, 3>> read(const std::vector<int>& nodes, std::vector<Curve>& curves);
  // The warning lines of what was left out, and the count of animations that moved nothing
  // rendered into notes.animations; after read.
  void warn(std::vector<std::string>& warnings);

 private:
  struct Channel {
    size_t animation;
    int sampler;
  };
  // Why channels of one animation were left out: how many, and the first reason.
  struct Dropped {
    size_t channels = 0;
    std::string first;
  };
  void drop(size_t animation, const std::string& why);
  // The curve of one sampler for one path (0 translation, 1 rotation, 2 scale), read once.
  int32_t curveOf(const Channel& channel, int path, std::vector<Curve>& curves);
  bool readCurve(const Channel& channel, int path, Curve& curve);

  const tinygltf::Model& model_;
  ModelNotes& notes_;
  std::map<std::pair<int, int>, Channel> targets_;  // (node, path) -> its channel
  std::map<std::tuple<size_t, int, int>, int32_t> read_;  // (animation, sampler, path) -> curve
  std::vector<Dropped> dropped_;                          // per animation
  // Per animation: whether a curve of it is played, and whether a line says something of it.
  std::vector<char> played_, noted_;
  size_t duplicates_ = 0;
  size_t numbersLeft_;
};

}  // namespace prt
