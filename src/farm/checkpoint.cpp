#include "farm/checkpoint.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include "core/byte_codec.h"
#include "core/input_file.h"
#include "core/input_error.h"
#include "image/atomic_file.h"
#include "scene/number_text.h"
#include "scene/scene_file.h"

namespace prt {
namespace {

constexpr char kMagic[8] = {'P', 'R', 'T', 'C', 'K', 'P', 'T', '1'};

uint64_t fnv1a(const uint8_t* data, size_t size, uint64_t hash = 14695981039346656037ull) {
  for (size_t i = 0; i < size; ++i) {
    hash ^= data[i];
    hash *= 1099511628211ull;
  }
  return hash;
}

std::string hex(uint64_t v) {
  char text[20];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(v));
  return text;
}

}  // namespace

CheckpointKey checkpointKey(const Scene& scene, const RenderSettings& settings,
                            const FrameSequence& frames) {
  Scene keyed = scene;
  keyed.image.output.clear();  // the same render may be written anywhere
  const std::string text = writeScene(keyed);
  uint64_t hash = fnv1a(reinterpret_cast<const uint8_t*>(text.data()), text.size());
  // An import's text names its file, not what the file holds: its content is keyed too.
  if (!scene.imports.empty()) {
    const std::vector<uint8_t> assets = packAssets(scene);
    hash = fnv1a(assets.data(), assets.size(), hash);
  }
  const int32_t numbers[] = {scene.image.width, scene.image.height, settings.samplesPerPixel,
                             settings.drtRate};
  const uint64_t sceneHash = hash;
  hash = fnv1a(reinterpret_cast<const uint8_t*>(numbers), sizeof numbers, hash);
  const bool sequence = frames.count() > 1 || frames.animated;
  if (sequence) {  // a still's key is what it always was
    const std::string timing = std::to_string(frames.first) + "-" + std::to_string(frames.last) +
                               ":" + std::to_string(frames.step) + "@" + formatDouble(frames.fps);
    hash = fnv1a(reinterpret_cast<const uint8_t*>(timing.data()), timing.size(), hash);
  }
  CheckpointKey key;
  key.hash = hash;
  key.width = scene.image.width;
  key.height = scene.image.height * static_cast<int>(frames.count());
  key.description = std::to_string(scene.image.width) + "x" +
                    std::to_string(scene.image.height) + ", " +
                    std::to_string(settings.samplesPerPixel) + " spp, DRT " +
                    std::to_string(settings.drtRate) + ", scene " + hex(sceneHash);
  if (sequence) {
    key.description += ", frames " + std::to_string(frames.first) + "-" +
                       std::to_string(frames.last) + ":" + std::to_string(frames.step) + " at " +
                       formatDouble(frames.fps) + " fps";
  }
  return key;
}

void writeCheckpoint(const std::string& path, const CheckpointKey& key, const TaskSet& done,
                     const Image& image, const std::vector<int16_t>& owner) {
  ByteWriter w;
  // Its size, known before: a 4K image's checkpoint is over 100 MB, and growing the buffer as
  // it fills would copy it several times over while the master waits.
  w.out.reserve(sizeof kMagic + 8 + 2 + key.description.size() + 8 + 8 +
                24 * done.runs().size() + 14 * done.size() + 8);
  w.raw(kMagic, sizeof kMagic);
  w.pod(key.hash);
  w.text(key.description);
  w.pod(static_cast<int32_t>(key.width));
  w.pod(static_cast<int32_t>(key.height));
  w.pod(static_cast<uint64_t>(done.runs().size()));
  for (const TaskRun& r : done.runs()) {
    w.pod(r.first);
    w.pod(r.count);
    w.pod(r.stride);
  }
  const auto data = image.data();
  done.forEach([&](uint64_t p) { w.raw(&data[3 * p], 3 * sizeof(float)); });
  done.forEach([&](uint64_t p) {
    const int16_t o = p < owner.size() ? owner[p] : int16_t{-1};
    w.pod(o);
  });
  w.pod(fnv1a(w.out.data(), w.out.size()));
  writeFileAtomically(path, std::string_view(reinterpret_cast<const char*>(w.out.data()),
                                             w.out.size()));
}

uint64_t maxCheckpointBytes(const CheckpointKey& key) {
  // Header and description (at most 64 KiB, a u16 length), then at worst one run of 24 bytes,
  // 12 bytes of colour and 2 of owner per pixel, and the checksum.
  const uint64_t pixels = static_cast<uint64_t>(std::max(key.width, 0)) *
                          static_cast<uint64_t>(std::max(key.height, 0));
  return sizeof kMagic + 8 + 2 + 65535 + 8 + 8 + pixels * (24 + 12 + 2) + 8;
}

Checkpoint parseCheckpoint(const std::vector<uint8_t>& bytes, const CheckpointKey& key,
                           const std::string& path) {
  auto damaged = [&](const std::string& why) {
    return InputError("checkpoint '" + path + "' is damaged (" + why +
                      "); remove it to render from the start");
  };
  if (bytes.size() < sizeof kMagic + 8 ||
      !std::equal(std::begin(kMagic), std::end(kMagic), bytes.begin())) {
    throw InputError("'" + path + "' is not a PRT checkpoint");
  }
  uint64_t stored = 0;
  std::memcpy(&stored, bytes.data() + bytes.size() - 8, 8);
  if (fnv1a(bytes.data(), bytes.size() - 8) != stored) throw damaged("checksum mismatch");
  try {
    ByteReader r(bytes.data() + sizeof kMagic, bytes.size() - sizeof kMagic - 8, "checkpoint");
    const auto hash = r.pod<uint64_t>();
    const std::string description = r.text();
    if (hash != key.hash) {
      throw InputError("checkpoint '" + path + "' belongs to another render (" + description +
                       "); this run is " + key.description +
                       ". Remove it, or choose another --checkpoint file");
    }
    const auto width = r.pod<int32_t>();
    const auto height = r.pod<int32_t>();
    if (width != key.width || height != key.height || width <= 0 || height <= 0) {
      throw damaged("size mismatch");
    }
    Checkpoint c;
    c.image = Image(width, height);
    const uint64_t pixels = c.image.pixelCount();
    c.owner.assign(pixels, -1);
    const auto runs = r.pod<uint64_t>();
    r.needItems(runs, 24);
    // Runs as the ledger writes them: ascending and disjoint, every pixel inside the image.
    // Checked without overflow whatever the fields hold (a file made by hand).
    uint64_t next = 0;  // the first pixel the next run may start at
    for (uint64_t i = 0; i < runs; ++i) {
      TaskRun run;
      run.first = r.pod<uint64_t>();
      run.count = r.pod<uint64_t>();
      run.stride = r.pod<uint64_t>();
      if (run.count == 0 || (run.count > 1 && run.stride == 0)) throw damaged("an empty run");
      if (!run.endsBefore(pixels)) throw damaged("a pixel outside the image");
      if (run.first < next) throw damaged("runs out of order or overlapping");
      next = run.last() + 1;
      c.done.append(run);
    }
    r.needItems(c.done.size(), 3 * sizeof(float) + sizeof(int16_t));
    auto data = c.image.data();
    bool finite = true;
    c.done.forEach([&](uint64_t p) {
      r.raw(&data[3 * p], 3 * sizeof(float));
      finite = finite && std::isfinite(data[3 * p]) && std::isfinite(data[3 * p + 1]) &&
               std::isfinite(data[3 * p + 2]);
    });
    if (!finite) throw damaged("a pixel that is not a finite colour");
    bool owners = true;
    c.done.forEach([&](uint64_t p) {
      c.owner[p] = r.pod<int16_t>();
      owners = owners && c.owner[p] >= -1;
    });
    if (!owners) throw damaged("a pixel owner below -1");
    r.finish();
    return c;
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw damaged(e.what());
  }
}

std::optional<Checkpoint> readCheckpoint(const std::string& path, const CheckpointKey& key) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return std::nullopt;
  const std::string bytes = readInputFile(path, "checkpoint", maxCheckpointBytes(key));
  return parseCheckpoint(std::vector<uint8_t>(bytes.begin(), bytes.end()), key, path);
}

void removeCheckpoint(const std::string& path) {
  std::error_code ec;
  std::filesystem::remove(path, ec);
  removeStaleTemporaries(path);
}

}  // namespace prt
