#pragma once
// FrameSequence: the frames of an animation rendered as one job — frame numbers first, first +
// step, ..., up to last — and how frame numbers map to time (frame N is at N / fps seconds, as
// Blender and its glTF exporter count). The job's tasks are the pixels of every frame in
// turn: pixel p of the i-th frame is task i * pixelsPerFrame + p, so strategies, the ledger and
// checkpoints, which balance and keep tasks 0 .. n-1, carry a sequence as they carry a still
// (a still is a sequence of one frame).
// Plain value type; pure, thread-safe.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace prt {

struct FrameSequence {
  int64_t first = 0;
  int64_t last = 0;
  int64_t step = 1;
  double fps = 24;
  bool animated = false;  // whether frames differ: false for a still (one frame at time 0)

  // At most this many frames in one job; frame numbers stay within +-kMaxFrameNumber.
  static constexpr int64_t kMaxFrames = 1 << 20;
  static constexpr int64_t kMaxFrameNumber = 100'000'000;

  uint64_t count() const { return static_cast<uint64_t>((last - first) / step + 1); }
  int64_t number(uint64_t ordinal) const { return first + static_cast<int64_t>(ordinal) * step; }
  double seconds(uint64_t ordinal) const {
    return animated ? static_cast<double>(number(ordinal)) / fps : 0.0;
  }
  bool operator==(const FrameSequence&) const = default;
};

// Parses --frames "A-B" or "A-B:STEP" (A <= B, STEP >= 1; numbers may be negative: "-5--1")
// or --frame "N"; nullopt with `error` set to what is wrong.
std::optional<FrameSequence> parseFrames(std::string_view text, std::string& error);

// An output path for frame `number`: the run of '#' in `pattern` replaced by the number,
// zero-padded to the run's length (a negative number keeps its '-' in front). A pattern
// without '#' is returned as it is.
std::string framePath(const std::string& pattern, int64_t number);
// Whether `pattern` has exactly one run of '#' in its file name.
bool hasFramePattern(const std::string& pattern);

}  // namespace prt
