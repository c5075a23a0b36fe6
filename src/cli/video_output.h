#pragma once
// prt render --video FILE: a frame sequence made into a video by ffmpeg (Debian's package),
// once every frame is written, at the animation's speed (fps / step frames per second).
//
// The frames are fed to ffmpeg through a pipe in frame order (image2pipe), so no list or
// link files are made and frames of other runs beside them are never picked up. The video
// is written to a temporary file beside FILE and renamed onto it only when ffmpeg succeeds:
// FILE is never half-written, and nothing is left behind on a failure or a signal. For .mp4,
// .mov, .m4v and .mkv the video is H.264 in yuv420p (what players expect), the frame padded
// to even sizes; other containers take ffmpeg's default codec. $PRT_FFMPEG names another
// ffmpeg. Without --video, a sequence ends by printing the ffmpeg command that would make it.
//
// ffmpeg runs in a process group of its own, watched: one that makes no progress (takes no
// frame, and neither its video nor its log grows) for --video-timeout seconds is ended
// (SIGKILL to its group) and the run fails; a stop signal ends it at once. Either way its
// temporary files are removed and the frames stay.

#include <string>

#include "cli/render_options.h"
#include "core/frame_sequence.h"

namespace prt::cli {

// Before the render: --video needs a sequence, an ffmpeg to run and a file name with an
// extension ffmpeg can tell the container from. Throws InputError.
void checkVideo(const RenderOptions& o, const FrameSequence& frames);

// The ffmpeg command a user could run on the frames `pattern` names (printed by runs without
// --video).
std::string videoHint(const std::string& pattern, const FrameSequence& frames);

// After every frame is written: makes o.videoPath from them and prints where (unless quiet),
// or, without --video, prints videoHint (unless quiet). Throws std::runtime_error with
// ffmpeg's last lines if it fails, ProgramEnded (core/subprocess.h) if it stalled or a stop
// signal came; the frames stay.
void finishSequence(const RenderOptions& o, const std::string& pattern,
                    const FrameSequence& frames);

}  // namespace prt::cli
