#include "farm/checkpoint.h"

#include <gtest/gtest.h>

#include <signal.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "core/input_error.h"
#include "scene/scene_file.h"

namespace prt {
namespace {

Scene scene(int width, int height) {
  Scene s;
  s.image.width = width;
  s.image.height = height;
  s.image.output = "out.png";
  s.objects.push_back({SphereShape{{0, 1, 0}, 1}, Material{}});
  return s;
}

std::string tempPath(const std::string& name) {
  return (std::filesystem::temp_directory_path() /
          ("prt-checkpoint-" + std::to_string(::getpid()) + "-" + name))
      .string();
}

TEST(CheckpointTest, RoundTripsTheDonePixelsAndTheirOwners) {
  const CheckpointKey key = checkpointKey(scene(8, 4), RenderSettings{2, 1});
  Image image(8, 4);
  std::vector<int16_t> owner(32, -1);
  TaskSet done = TaskSet::range(3, 5);
  done.append(TaskSet::strided(20, 3, 4));
  done.forEach([&](uint64_t p) {
    image.set(p, Color(0.1 * static_cast<double>(p), 1.0 / static_cast<double>(p + 1), -0.0));
    owner[p] = static_cast<int16_t>(p % 3);
  });
  image.set(0, Color(9));  // not done: not kept
  const std::string path = tempPath("roundtrip");
  writeCheckpoint(path, key, done, image, owner);
  const std::optional<Checkpoint> c = readCheckpoint(path, key);
  ASSERT_TRUE(c.has_value());
  EXPECT_EQ(c->done, done);
  done.forEach([&](uint64_t p) {
    EXPECT_EQ(c->image.at(p).x, image.at(p).x);
    EXPECT_EQ(c->image.at(p).y, image.at(p).y);
    EXPECT_EQ(c->owner[p], owner[p]);
  });
  EXPECT_EQ(c->image.at(0).x, 0.0);
  EXPECT_EQ(c->owner[0], -1);
  removeCheckpoint(path);
  EXPECT_FALSE(readCheckpoint(path, key).has_value());
}

TEST(CheckpointTest, TheOutputPathIsNotPartOfTheRender) {
  Scene a = scene(8, 4);
  Scene b = a;
  b.image.output = "elsewhere.pfm";
  EXPECT_EQ(checkpointKey(a, {2, 1}).hash, checkpointKey(b, {2, 1}).hash);
  EXPECT_NE(checkpointKey(a, {2, 1}).hash, checkpointKey(a, {3, 1}).hash);
  EXPECT_NE(checkpointKey(a, {2, 1}).hash, checkpointKey(a, {2, 2}).hash);
  EXPECT_NE(checkpointKey(a, {2, 1}).hash, checkpointKey(scene(8, 5), {2, 1}).hash);
  b.objects[0].material.diffuse = 0.25;
  EXPECT_NE(checkpointKey(a, {2, 1}).hash, checkpointKey(b, {2, 1}).hash);
}

// An import's text names its file, not what the file holds: a checkpoint of a model that has
// changed since must not be taken for this render's.
TEST(CheckpointTest, ImportedModelsAreKeyedByWhatTheyHold) {
  namespace fs = std::filesystem;
  const fs::path dir = tempPath("models");
  fs::create_directories(dir);
  const fs::path models = fs::path(PRT_SOURCE_DIR) / "tests" / "models";
  fs::copy_file(models / "blender-cube.glb", dir / "model.glb", fs::copy_options::overwrite_existing);
  const std::string text = "image { width 8 height 6 }\nimport { file \"model.glb\" }\n";
  std::ofstream(dir / "s.scene") << text;
  const uint64_t before = checkpointKey(loadSceneFile((dir / "s.scene").string()), {1, 1}).hash;
  EXPECT_EQ(checkpointKey(loadSceneFile((dir / "s.scene").string()), {1, 1}).hash, before);
  fs::copy_file(models / "blender-ortho.glb", dir / "model.glb", fs::copy_options::overwrite_existing);
  Scene changed = loadSceneFile((dir / "s.scene").string());
  changed.camera = loadSceneFile((dir / "s.scene").string()).camera;
  EXPECT_NE(checkpointKey(changed, {1, 1}).hash, before);
  fs::remove_all(dir);
}

TEST(CheckpointTest, AnotherRendersOrADamagedCheckpointIsRefused) {
  const CheckpointKey key = checkpointKey(scene(8, 4), RenderSettings{2, 1});
  const std::string path = tempPath("refused");
  writeCheckpoint(path, key, TaskSet::range(0, 10), Image(8, 4), {});
  try {
    readCheckpoint(path, checkpointKey(scene(8, 4), RenderSettings{4, 1}));
    FAIL() << "a checkpoint of another render was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("belongs to another render (8x4, 2 spp"),
              std::string::npos)
        << e.what();
  }
  // Flip one byte in the middle: the checksum catches it.
  {
    std::fstream f(path, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(60);
    f.put('\x7f');
  }
  EXPECT_THROW(readCheckpoint(path, key), InputError);
  // Truncated.
  std::filesystem::resize_file(path, 30);
  EXPECT_THROW(readCheckpoint(path, key), InputError);
  // Not a checkpoint at all.
  {
    std::ofstream f(path, std::ios::binary | std::ios::trunc);
    f << "P6\n8 4\n255\n";
  }
  EXPECT_THROW(readCheckpoint(path, key), InputError);
  removeCheckpoint(path);
}

// A checkpoint made by hand, with a valid checksum: runs and pixels as given.
struct HandMade {
  std::vector<TaskRun> runs;
  std::vector<float> colours;  // 3 per pixel of the runs
  std::vector<int16_t> owners;
};

std::vector<uint8_t> handMade(const CheckpointKey& key, const HandMade& made) {
  std::vector<uint8_t> out;
  auto put = [&](const void* data, size_t size) {
    const auto* bytes = static_cast<const uint8_t*>(data);
    out.insert(out.end(), bytes, bytes + size);
  };
  put("PRTCKPT1", 8);
  put(&key.hash, 8);
  const auto length = static_cast<uint16_t>(key.description.size());
  put(&length, 2);
  put(key.description.data(), key.description.size());
  const int32_t size[] = {key.width, key.height};
  put(size, sizeof size);
  const uint64_t runs = made.runs.size();
  put(&runs, 8);
  for (const TaskRun& r : made.runs) {
    put(&r.first, 8);
    put(&r.count, 8);
    put(&r.stride, 8);
  }
  put(made.colours.data(), made.colours.size() * sizeof(float));
  put(made.owners.data(), made.owners.size() * sizeof(int16_t));
  uint64_t hash = 14695981039346656037ull;
  for (const uint8_t b : out) {
    hash ^= b;
    hash *= 1099511628211ull;
  }
  put(&hash, 8);
  return out;
}

std::string refusal(const CheckpointKey& key, const HandMade& made) {
  try {
    parseCheckpoint(handMade(key, made), key, "hand.ckpt");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(accepted)";
}

// Runs whose last pixel overflows 64 bits, and the like: refused, never written outside the
// image.
TEST(CheckpointTest, HandMadeRunsOutsideTheImageAreRefusedWithoutOverflow) {
  const CheckpointKey key = checkpointKey(scene(8, 4), RenderSettings{1, 1});
  const HandMade good{{{0, 2, 1}, {5, 2, 3}}, std::vector<float>(12, 0.5f), {0, 1, 0, -1}};
  const Checkpoint c = parseCheckpoint(handMade(key, good), key, "hand.ckpt");
  EXPECT_EQ(c.done.toVector(), (std::vector<uint64_t>{0, 1, 5, 8}));
  EXPECT_EQ(c.owner[1], 1);
  // 1 + 2^63 * 2 wraps to 1: inside the image by naive arithmetic.
  const HandMade wraps{{{1, 3, uint64_t{1} << 63}}, std::vector<float>(9, 0.5f), {0, 0, 0}};
  EXPECT_NE(refusal(key, wraps).find("a pixel outside the image"), std::string::npos);
  const HandMade huge{{{0, 2, ~uint64_t{0}}}, std::vector<float>(6, 0.5f), {0, 0}};
  EXPECT_NE(refusal(key, huge).find("a pixel outside the image"), std::string::npos);
  const HandMade past{{{31, 2, 1}}, std::vector<float>(6, 0.5f), {0, 0}};
  EXPECT_NE(refusal(key, past).find("a pixel outside the image"), std::string::npos);
  const HandMade empty{{{3, 0, 1}}, {}, {}};
  EXPECT_NE(refusal(key, empty).find("an empty run"), std::string::npos);
  const HandMade still{{{3, 2, 0}}, std::vector<float>(6, 0.5f), {0, 0}};
  EXPECT_NE(refusal(key, still).find("an empty run"), std::string::npos);
}

TEST(CheckpointTest, HandMadeRunsOutOfOrderOrOverlappingAreRefused) {
  const CheckpointKey key = checkpointKey(scene(8, 4), RenderSettings{1, 1});
  const HandMade backwards{{{10, 2, 1}, {3, 2, 1}}, std::vector<float>(12, 0.5f), {0, 0, 0, 0}};
  EXPECT_NE(refusal(key, backwards).find("runs out of order or overlapping"), std::string::npos);
  const HandMade overlapping{{{3, 4, 1}, {5, 2, 1}}, std::vector<float>(18, 0.5f),
                             {0, 0, 0, 0, 0, 0}};
  EXPECT_NE(refusal(key, overlapping).find("runs out of order or overlapping"),
            std::string::npos);
  const HandMade twice{{{3, 1, 1}, {3, 1, 1}}, std::vector<float>(6, 0.5f), {0, 0}};
  EXPECT_NE(refusal(key, twice).find("runs out of order or overlapping"), std::string::npos);
}

TEST(CheckpointTest, HandMadePixelsThatAreNotColoursAreRefused) {
  const CheckpointKey key = checkpointKey(scene(8, 4), RenderSettings{1, 1});
  for (const float bad : {std::nanf(""), INFINITY, -INFINITY}) {
    HandMade made{{{0, 2, 1}}, std::vector<float>(6, 0.5f), {0, 0}};
    made.colours[4] = bad;
    EXPECT_NE(refusal(key, made).find("a pixel that is not a finite colour"), std::string::npos);
  }
  const HandMade owner{{{0, 2, 1}}, std::vector<float>(6, 0.5f), {0, -7}};
  EXPECT_NE(refusal(key, owner).find("a pixel owner below -1"), std::string::npos);
  // Pixels promised and not there, and bytes beyond them.
  const HandMade shortOf{{{0, 2, 1}}, std::vector<float>(3, 0.5f), {0}};
  EXPECT_NE(refusal(key, shortOf).find("truncated"), std::string::npos);
  const HandMade beyond{{{0, 1, 1}}, std::vector<float>(3, 0.5f), {0, 0}};
  EXPECT_NE(refusal(key, beyond).find("trailing bytes"), std::string::npos);
}

// A run killed while writing its checkpoint leaves the temporary file; the run that resumes
// and finishes removes it even when it never writes a checkpoint itself.
TEST(CheckpointTest, StaleTemporariesOfADeadRunGoWithTheCheckpoint) {
  const std::string path = tempPath("stale");
  pid_t gone = 4194000;
  while (::kill(gone, 0) == 0 || errno != ESRCH) --gone;
  const std::string stale = path + ".tmp-" + std::to_string(gone) + "-0";
  const std::string ours = path + ".tmp-" + std::to_string(::getpid()) + "-7";
  std::ofstream(stale) << "half";
  std::ofstream(ours) << "live";
  removeCheckpoint(path);
  EXPECT_FALSE(std::filesystem::exists(stale));
  EXPECT_TRUE(std::filesystem::exists(ours));
  std::filesystem::remove(ours);
}

// A checkpoint larger than any of this render's could be is refused before it is read.
TEST(CheckpointTest, AFileLargerThanTheRendersCheckpointIsRefusedUnread) {
  const CheckpointKey key = checkpointKey(scene(8, 4), RenderSettings{1, 1});
  const std::string path = tempPath("large");
  {
    std::ofstream f(path, std::ios::binary);
    f << "PRTCKPT1" << std::string(maxCheckpointBytes(key), '\0');
  }
  try {
    readCheckpoint(path, key);
    ADD_FAILURE() << "read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("more than the"), std::string::npos) << e.what();
  }
  removeCheckpoint(path);
}

}  // namespace
}  // namespace prt
