#include "cli/video_output.h"

#include <unistd.h>

#include <array>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <vector>

#include "core/input_error.h"
#include "core/stop_signals.h"
#include "core/subprocess.h"
#include "core/text.h"
#include "image/atomic_file.h"

namespace prt::cli {
namespace {

namespace fs = std::filesystem;

std::string ffmpegProgram() {
  const char* chosen = std::getenv("PRT_FFMPEG");
  return findProgram(chosen != nullptr && *chosen != '\0' ? chosen : "ffmpeg");
}

// Containers whose players expect H.264 in yuv420p.
bool wantsH264(const std::string& ext) {
  return ext == ".mp4" || ext == ".mov" || ext == ".m4v" || ext == ".mkv";
}

std::string rateOf(const FrameSequence& frames) {
  char rate[32];
  std::snprintf(rate, sizeof rate, "%.6g", frames.fps / static_cast<double>(frames.step));
  return rate;
}

// Writes the whole file to `fd`; false if the reader went away (EPIPE) or the file cannot be
// read, with `problem` saying which.
bool copyFileTo(const std::string& path, int fd, std::string& problem,
                std::atomic<uint64_t>& fed) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    problem = "cannot read the frame '" + path + "'";
    return false;
  }
  std::array<char, 1 << 16> buffer;
  while (in) {
    in.read(buffer.data(), buffer.size());
    const char* at = buffer.data();
    auto left = static_cast<size_t>(in.gcount());
    while (left > 0) {
      const ssize_t n = ::write(fd, at, left);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) {
        problem = "ffmpeg stopped reading the frames";
        return false;
      }
      at += n;
      left -= static_cast<size_t>(n);
      fed += static_cast<uint64_t>(n);
    }
  }
  return true;
}

}  // namespace

void checkVideo(const RenderOptions& o, const FrameSequence& frames) {
  if (o.videoPath.empty()) return;
  if (frames.count() < 2) {
    throw InputError("--video makes a video of a frame sequence: add --frames A-B");
  }
  if (fs::path(o.videoPath).extension().empty()) {
    throw InputError("--video '" + o.videoPath +
                     "' has no extension: ffmpeg picks the container from it (.mp4, .mkv, "
                     ".webm, .gif, ...)");
  }
  if (ffmpegProgram().empty()) {
    throw InputError(
        "--video needs ffmpeg, which was not found on PATH (Debian: apt-get install ffmpeg; "
        "or set PRT_FFMPEG to its path)");
  }
}

std::string videoHint(const std::string& pattern, const FrameSequence& frames) {
  const size_t slash = pattern.find_last_of('/');
  const size_t start = pattern.find('#', slash == std::string::npos ? 0 : slash + 1);
  size_t end = start;
  while (end < pattern.size() && pattern[end] == '#') ++end;
  const std::string glob = pattern.substr(0, start) + "*" + pattern.substr(end);
  // Single quotes keep the shell from expanding the glob: ffmpeg does, in name order, which
  // the zero-padded numbers keep in frame order.
  return "to make a video of the frames (Debian's ffmpeg), add --video video.mp4 or run:\n"
         "  ffmpeg -framerate " +
         rateOf(frames) + " -pattern_type glob -i '" + glob +
         "' -c:v libx264 -pix_fmt yuv420p video.mp4\n";
}

void finishSequence(const RenderOptions& o, const std::string& pattern,
                    const FrameSequence& frames) {
  if (o.videoPath.empty()) {
    if (!o.quiet) std::printf("%s", videoHint(pattern, frames).c_str());
    return;
  }
  const std::string ffmpeg = ffmpegProgram();
  if (ffmpeg.empty()) throw std::runtime_error("ffmpeg is gone: no video made; the frames stay");
  const std::string ext = lowerExtension(o.videoPath);
  TemporaryFile video(o.videoPath, fs::path(o.videoPath).extension().string());
  const TemporaryFile log(o.videoPath, ".log");
  std::vector<std::string> args = {"-nostdin", "-hide_banner", "-loglevel", "error", "-y",
                                   "-f", "image2pipe", "-framerate", rateOf(frames), "-i", "-"};
  if (wantsH264(ext)) {
    args.insert(args.end(), {"-c:v", "libx264", "-pix_fmt", "yuv420p", "-vf",
                             "pad=ceil(iw/2)*2:ceil(ih/2)*2"});
  }
  args.push_back(video.path());
  std::string problem;
  std::atomic<uint64_t> fed{0};  // bytes ffmpeg took: its progress, with its files' growth
  ProgramWatch watch;
  watch.stallSeconds = o.videoTimeoutSeconds;
  watch.progress = &fed;
  watch.progressFiles = {video.path(), log.path()};
  watch.stopSignal = pendingStopSignal;
  int status = 0;
  try {
    status = runProgram(
        ffmpeg, args, fs::current_path(), log.path(),
        [&](int fd) {
          for (uint64_t i = 0; i < frames.count(); ++i) {
            if (!copyFileTo(framePath(pattern, frames.number(i)), fd, problem, fed)) return;
          }
        },
        watch);
  } catch (const ProgramEnded& e) {
    const std::string said = lastLines(readWholeFile(log.path()), 6);
    throw ProgramEnded(std::string(e.what()) + "; no video was made, the frames are written" +
                           (said.empty() ? std::string() : "; ffmpeg said:\n" + said) +
                           (e.signal() == 0 ? "\n(--video-timeout sets how long ffmpeg may go "
                                              "without progress)"
                                            : std::string()),
                       e.signal());
  }
  const std::string exit = describeExit(status);
  if (!exit.empty() || !problem.empty()) {
    const std::string said = lastLines(readWholeFile(log.path()), 6);
    throw std::runtime_error("ffmpeg could not make the video '" + o.videoPath + "' (" +
                             (exit.empty() ? problem : "ffmpeg " + exit) + ")" +
                             (said.empty() ? std::string() : ":\n" + said) +
                             "\nthe frames are written; no video was made");
  }
  std::error_code sizeError;
  if (fs::file_size(video.path(), sizeError) == 0 || sizeError) {
    throw std::runtime_error("ffmpeg ended without writing the video '" + o.videoPath +
                             "'\nthe frames are written; no video was made");
  }
  video.commit();
  if (!o.quiet) {
    std::printf("%s: video of %llu frames at %s frames per second\n", o.videoPath.c_str(),
                static_cast<unsigned long long>(frames.count()), rateOf(frames).c_str());
  }
}

}  // namespace prt::cli
