#include "scene/key_frames.h"

#include <algorithm>
#include <map>

#include "scene/block_reader.h"
#include "scene/number_text.h"
#include "scene/value_reader.h"

namespace prt {

namespace {
// Long enough for any animation (about eleven days), short enough that times stay exact.
constexpr double kMaxKeyTime = 1e6;
}  // namespace

void KeyFrames::read(TokenStream& in, const Token& keyToken, const ValueReader& readValue) {
  const size_t timeIndex = in.position();
  const double time = readNumber(in, "key", Range::closed(0, kMaxKeyTime));
  if (!(time > lastTime_)) {
    in.fail(in.at(timeIndex),
            "the keys of the '" + title_ + "' block must come in increasing time after 0 (the "
            "block's own values): " + formatDouble(time) + " is not after " +
            formatDouble(lastTime_));
  }
  lastTime_ = time;
  const std::string title = title_ + " key " + formatDouble(time);
  BlockReader block(in, keyToken, title, {});
  // BlockReader takes its names as a list fixed at compile time; the keyed ones vary by block,
  // so they are checked here and the reader only finds the braces.
  size_t given = 0;
  while (true) {
    const Token& name = in.next();
    if (name.kind == TokenKind::RightBrace) break;
    if (name.kind != TokenKind::Word ||
        std::find(fields_.begin(), fields_.end(), name.text) == fields_.end()) {
      std::string list;
      for (std::string_view f : fields_) list += (list.empty() ? "" : ", ") + std::string(f);
      in.fail(name, "expected a parameter that can be keyed in the '" + title_ +
                        "' block or '}', found " + describe(name) + "; keyed parameters: " + list);
    }
    for (size_t k = keys_.size() - given; k < keys_.size(); ++k) {
      if (keys_[k].field == name.text) {
        in.fail(name, "duplicate parameter '" + name.text + "' in the '" + title + "' entry");
      }
    }
    Key key{time, name.text, {0, 0, 0}, 0};
    key.width = readValue(name.text, key.value);
    keys_.push_back(key);
    ++given;
  }
  if (given == 0) in.fail(keyToken, "the '" + title + "' entry gives no parameter");
  (void)block;
}

void KeyFrames::finish(Scene& scene, uint32_t index, const ValueReader& baseValue) const {
  if (keys_.empty()) return;
  std::map<std::string, FieldTrack> tracks;  // by field, so their order is fixed
  for (const Key& key : keys_) {
    auto [it, fresh] = tracks.try_emplace(key.field);
    FieldTrack& track = it->second;
    if (fresh) {
      track.target = target_;
      track.index = index;
      track.field = key.field;
      double base[3] = {0, 0, 0};
      track.curve.width = static_cast<uint8_t>(baseValue(key.field, base));
      track.curve.times.push_back(0);
      track.curve.values.insert(track.curve.values.end(), base, base + track.curve.width);
    }
    track.curve.times.push_back(key.time);
    track.curve.values.insert(track.curve.values.end(), key.value, key.value + key.width);
  }
  SceneAnimation& animation = editAnimation(scene);
  for (auto& [field, track] : tracks) {
    animation.duration = std::max(animation.duration, track.curve.times.back());
    animation.fields.push_back(std::move(track));
  }
}

std::vector<KeyGroup> keyGroupsOf(const Scene& scene, FieldTrack::Target target, uint32_t index) {
  std::map<double, KeyGroup> groups;
  if (scene.animation) {
    for (const FieldTrack& track : scene.animation->fields) {
      if (track.target != target || track.index != index) continue;
      for (size_t k = 1; k < track.curve.times.size(); ++k) {  // key 0 is the block's value
        KeyGroup& g = groups[track.curve.times[k]];
        g.time = track.curve.times[k];
        g.tracks.push_back(&track);
        g.keyIndex.push_back(k);
      }
    }
  }
  std::vector<KeyGroup> out;
  for (auto& [time, group] : groups) out.push_back(std::move(group));
  return out;
}

}  // namespace prt
