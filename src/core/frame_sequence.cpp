#include "core/frame_sequence.h"

#include <charconv>
#include <cstdlib>

namespace prt {
namespace {

// A whole number with an optional leading '-', within +-kMaxFrameNumber.
std::optional<int64_t> frameNumber(std::string_view text) {
  int64_t value = 0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (text.empty() || ec != std::errc() || ptr != end || text.front() == '+') return std::nullopt;
  if (value < -FrameSequence::kMaxFrameNumber || value > FrameSequence::kMaxFrameNumber) {
    return std::nullopt;
  }
  return value;
}

}  // namespace

std::optional<FrameSequence> parseFrames(std::string_view text, std::string& error) {
  FrameSequence s;
  s.animated = true;
  std::string_view range = text;
  if (const size_t colon = text.find(':'); colon != std::string_view::npos) {
    range = text.substr(0, colon);
    const auto step = frameNumber(text.substr(colon + 1));
    if (!step || *step < 1) {
      error = "the STEP after ':' must be a whole number from 1";
      return std::nullopt;
    }
    s.step = *step;
  }
  // The '-' between A and B is the first '-' that is not a sign (not at the start).
  const size_t dash = range.size() > 1 ? range.find('-', 1) : std::string_view::npos;
  const auto first = frameNumber(dash == std::string_view::npos ? range : range.substr(0, dash));
  const auto last = dash == std::string_view::npos ? first : frameNumber(range.substr(dash + 1));
  if (!first || !last) {
    error = "frame numbers must be whole numbers within +-" +
            std::to_string(FrameSequence::kMaxFrameNumber) + ", as A-B or A-B:STEP (e.g. 1-48)";
    return std::nullopt;
  }
  if (*last < *first) {
    error = "the last frame " + std::to_string(*last) + " comes before the first " +
            std::to_string(*first);
    return std::nullopt;
  }
  s.first = *first;
  s.last = *last;
  if (s.count() > static_cast<uint64_t>(FrameSequence::kMaxFrames)) {
    error = std::to_string(s.count()) + " frames exceed the " +
            std::to_string(FrameSequence::kMaxFrames) + " one job may hold";
    return std::nullopt;
  }
  s.last = s.number(s.count() - 1);  // the last frame the step reaches
  return s;
}

std::string framePath(const std::string& pattern, int64_t number) {
  const size_t slash = pattern.find_last_of('/');
  const size_t start = pattern.find('#', slash == std::string::npos ? 0 : slash + 1);
  if (start == std::string::npos) return pattern;
  size_t end = start;
  while (end < pattern.size() && pattern[end] == '#') ++end;
  std::string digits = std::to_string(number < 0 ? -number : number);
  const size_t width = end - start - (number < 0 ? 1 : 0);
  if (digits.size() < width) digits.insert(0, width - digits.size(), '0');
  if (number < 0) digits.insert(0, 1, '-');
  return pattern.substr(0, start) + digits + pattern.substr(end);
}

bool hasFramePattern(const std::string& pattern) {
  const size_t slash = pattern.find_last_of('/');
  const size_t start = pattern.find('#', slash == std::string::npos ? 0 : slash + 1);
  if (start == std::string::npos) return false;
  size_t end = start;
  while (end < pattern.size() && pattern[end] == '#') ++end;
  return pattern.find('#', end) == std::string::npos;
}

}  // namespace prt
