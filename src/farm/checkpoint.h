#pragma once
// Checkpoints: the finished pixels of a render and which ones they are, so that a run that is
// killed — master included — resumes where it stopped. A checkpoint is the master's ledger's
// done set plus those pixels' colours (and who rendered them, for the ownership map), written
// atomically (a reader sees the previous checkpoint or the new one, never half of one).
//
// A checkpoint belongs to one render: the scene (its text as PRT writes it, without the output
// path), the image size, samples per pixel and DRT rate. Its key is a 64-bit FNV-1a hash of
// those; resuming with any other render is refused with a message saying which differs.
//
// File layout (little-endian): "PRTCKPT1", u64 key, u16-length description, i32 width,
// i32 height, the done set as runs (u64 count, then first/count/stride), 3 floats per done
// pixel in done order, an i16 owner per done pixel, and a trailing u64 FNV-1a of everything
// before it, so a truncated or damaged file is recognised.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/frame_sequence.h"
#include "core/task_set.h"
#include "image/image.h"
#include "trace/render_settings.h"
#include "trace/scene.h"

namespace prt {

struct CheckpointKey {
  uint64_t hash = 0;
  std::string description;  // "64x48, 2 spp, DRT 1, scene 1f3a...": for messages
  int width = 0, height = 0;
};

// For a sequence, the key covers its frames and their timing, and the checkpoint's image is
// the frames one above the other (height * frames rows).
CheckpointKey checkpointKey(const Scene& scene, const RenderSettings& settings,
                            const FrameSequence& frames = {});

struct Checkpoint {
  TaskSet done;                // pixels finished, ascending
  Image image{1, 1};           // the finished pixels' colours (others black)
  std::vector<int16_t> owner;  // per pixel: who rendered it, -1 where not done
};

// Writes `done`'s pixels of `image` (and `owner`, which may be empty) atomically to `path`.
// Throws InputError if the file cannot be written.
void writeCheckpoint(const std::string& path, const CheckpointKey& key, const TaskSet& done,
                     const Image& image, const std::vector<int16_t>& owner);

// Reads the checkpoint at `path` for the render `key`. Nothing when there is no file. Throws
// InputError (exit code 2) for a file that is not a checkpoint, is damaged, or belongs to
// another render.
std::optional<Checkpoint> readCheckpoint(const std::string& path, const CheckpointKey& key);

// The checks of readCheckpoint on a checkpoint's bytes, `path` naming them in messages:
// every run inside the image, ascending and disjoint, every colour finite, every owner -1 or
// a worker. Throws InputError as readCheckpoint does.
Checkpoint parseCheckpoint(const std::vector<uint8_t>& bytes, const CheckpointKey& key,
                           const std::string& path);

// The largest file a checkpoint of `key` can be: a larger one is refused unread.
uint64_t maxCheckpointBytes(const CheckpointKey& key);

// Removes the checkpoint once the image it would rebuild is written.
void removeCheckpoint(const std::string& path);

}  // namespace prt
