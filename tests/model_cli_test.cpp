// End-to-end tests of model files through the prt command: every file Blender wrote renders
// directly, textured and instanced scenes render bit for bit alike serially and under the
// thread driver, the flags that pick a camera and make missing textures errors, and the
// POV-Ray export with its texture images.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "image/image_io.h"
#include "prt_command.h"

namespace prt {
namespace {

namespace fs = std::filesystem;

using prt::e2e::Result;
using prt::e2e::run;
using ModelCliTest = prt::e2e::ScratchDirTest;

const fs::path kSource(PRT_SOURCE_DIR);

std::string readAll(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST_F(ModelCliTest, EveryBlenderFileRendersDirectlyAndShowsSomething) {
  int files = 0;
  for (const auto& entry : fs::directory_iterator(kSource / "tests" / "models")) {
    const std::string ext = entry.path().extension().string();
    if (ext != ".glb" && ext != ".gltf" && ext != ".obj" && ext != ".fbx" && ext != ".dae") continue;
    ++files;
    const std::string out = path(entry.path().stem().string() + ".png");
    const Result r = run("render \"" + entry.path().string() + "\" --width 32 --height 24 -q -o " + out);
    ASSERT_EQ(r.exitCode, 0) << entry.path() << "\n" << r.output;
    // Lit pixels, well above the dim grey background of a direct render (0.05).
    const Image image = readImage(out);
    int lit = 0;
    for (int y = 0; y < image.height(); ++y) {
      for (int x = 0; x < image.width(); ++x) lit += maxComponent(image.at(x, y)) > 0.2 ? 1 : 0;
    }
    EXPECT_GT(lit, image.width() * image.height() / 50) << entry.path() << ": nothing lit to see";
  }
  EXPECT_GE(files, 10);
}

// The pawns (instances of shared meshes, textures, glass) and the street (textures, vertex
// colours, several imports of one file, PRT primitives): the workers get the models from the
// master and render each pixel as the serial render does.
TEST_F(ModelCliTest, TexturedInstancedScenesRenderInParallelAsSerially) {
  for (const char* name : {"chess", "street"}) {
    const std::string scene = (kSource / "scenes" / (std::string(name) + ".scene")).string();
    const std::string size = " --width 40 --height 30 --spp 2 -q";
    const std::string serial = path(std::string(name) + "-serial.pfm");
    ASSERT_EQ(run("render " + scene + size + " -o " + serial).exitCode, 0);
    for (const char* strategy : {"adaptive", "hybrid", "reservoir", "stealing"}) {
      const std::string out = path(std::string(name) + "-" + strategy + ".pfm");
      const Result r = run("render " + scene + size + " --workers 3 --strategy " + strategy + " -o " + out);
      ASSERT_EQ(r.exitCode, 0) << r.output;
      EXPECT_EQ(readAll(out), readAll(serial)) << name << " with " << strategy;
    }
  }
}

TEST_F(ModelCliTest, CameraAndStrictFlags) {
  const std::string model = (kSource / "tests/models/blender-lights.glb").string();
  Result r = run("render " + model + " --camera Nowhere -q -o " + path("a.png"));
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("no imported camera has that name or index"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("0 'Camera'"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(path("a.png")));
  r = run("render " + model + " --camera 0 --width 16 --height 12 -q -o " + path("a.png"));
  EXPECT_EQ(r.exitCode, 0) << r.output;
  // An OBJ whose texture is missing: a warning, or with --strict an error.
  for (const char* f : {"blender-cube.obj", "blender-cube.mtl"}) {
    fs::copy_file(kSource / "tests/models" / f, path(f));
  }
  r = run("render " + path("blender-cube.obj") + " --width 16 --height 12 -o " + path("b.png"));
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("was not found; rendered without it"), std::string::npos) << r.output;
  r = run("render " + path("blender-cube.obj") + " --strict --width 16 --height 12 -o " + path("c.png"));
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("blender-cube.png"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(path("c.png")));
  // A file that is not a model at all.
  const std::string bad = write("bad.glb", "this is not glTF");
  r = run("render " + bad + " -q -o " + path("d.png"));
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("bad.glb"), std::string::npos) << r.output;
  r = run("render " + path("missing.fbx") + " -q -o " + path("d.png"));
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("does not exist"), std::string::npos) << r.output;
}

TEST_F(ModelCliTest, ExportWritesTheTextureImagesBesideThePovFile) {
  const std::string scene = (kSource / "scenes/chess.scene").string();
  const Result r = run("export " + scene + " --width 64 --height 48 -o " + path("chess.pov"));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const std::string pov = readAll(path("chess.pov"));
  EXPECT_NE(pov.find("#declare PRT_mesh_"), std::string::npos);
  EXPECT_NE(pov.find("image_map { png \"chess_texture0.png\""), std::string::npos);
  EXPECT_NE(pov.find("spotlight"), std::string::npos);
  EXPECT_NE(pov.find("fade_power 2"), std::string::npos);
  EXPECT_TRUE(fs::exists(path("chess_texture0.png")));
  EXPECT_TRUE(fs::exists(path("chess_texture1.png")));
}

}  // namespace
}  // namespace prt
