#pragma once
// KeyFrames: the `key T { ... }` entries of one animated block (docs/scene-format.md): each
// gives some of the block's parameters their values at time T seconds. The block's own values
// hold at time 0; between keys a parameter moves linearly, and after its last key it stays.
// Each parameter keyed becomes one FieldTrack of the scene's animation (scene/animation.h).
// Used by the parser for the camera, light, sphere, box and import blocks; errors are
// InputErrors at the offending token.

#include <functional>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include "scene/animation.h"
#include "scene/token_stream.h"

namespace prt {

// Reads the value of the block's parameter `name` (with the block's own reader, so with its
// range) into out; returns how many numbers it has (1 or 3).
using ValueReader = std::function<int(const std::string& name, double* out)>;

class KeyFrames {
 public:
  // `fields`: the block's parameters that may be keyed; they must outlive the reader.
  KeyFrames(std::string title, FieldTrack::Target target,
            std::initializer_list<std::string_view> fields)
      : title_(std::move(title)), target_(target), fields_(fields) {}

  // Reads one entry after its 'key' token: the time, then '{' parameters '}'.
  void read(TokenStream& in, const Token& keyToken, const ValueReader& readValue);
  bool empty() const { return keys_.empty(); }

  // Adds a track per keyed parameter to the scene (target `index`), starting from the block's
  // own value at time 0 as `baseValue` gives it.
  void finish(Scene& scene, uint32_t index, const ValueReader& baseValue) const;

 private:
  struct Key {
    double time;
    std::string field;
    double value[3];
    int width;
  };
  std::string title_;
  FieldTrack::Target target_;
  std::vector<std::string_view> fields_;
  std::vector<Key> keys_;
  double lastTime_ = 0;
};

// The keys of the tracks of target (kind, index), grouped by time: for the writer, which
// writes each group as one `key T { ... }` entry.
struct KeyGroup {
  double time;
  std::vector<const FieldTrack*> tracks;  // the tracks with a key at `time`
  std::vector<size_t> keyIndex;           // that key's index in each track's curve
};
std::vector<KeyGroup> keyGroupsOf(const Scene& scene, FieldTrack::Target target, uint32_t index);

}  // namespace prt
