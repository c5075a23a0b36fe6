#include "drive/checkpoint.h"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace prt
