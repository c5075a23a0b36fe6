// End-to-end tests of model files through the prt command: every file Blender wrote renders
// directly, textured and instanced scenes render bit for bit alike serially and under the
// thread driver, the flags that pick a camera and make missing textures errors, glTF 1.0
// files (read with assimp) with their textures, and the POV-Ray export with its texture
// images.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "image/image_compare.h"
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

// glTF 1.0, read with assimp, from Debian's assimp-testmodels. The milk truck renders with its
// texture: the logo's blue sky and green hills on the white body. BoxTextured's 1.0 file and
// its 2.0 version (read with tinygltf) hold the same box, texture coordinates and node
// transform; the 2.0 file mirrors its texture along u where the 1.0 file repeats it, so with
// its sampler set to repeat as well, the two readers' renders agree but for the highlight of
// the 1.0 file's Phong material: 45.5 dB at 80x60, no pixel off by more than 16 codes, the
// same pixels covered.
TEST_F(ModelCliTest, GltfOneFilesRenderWithTheirTextures) {
  const fs::path models = "/usr/share/assimp/models";
  if (!fs::exists(models / "glTF")) GTEST_SKIP() << "assimp-testmodels is not installed";
  const std::string size = " --width 80 --height 60 -q -o ";
  Result r = run("render " + (models / "glTF/CesiumMilkTruck/CesiumMilkTruck.gltf").string() + size +
                 path("truck.png"));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const Image truck = readImage(path("truck.png"));
  int covered = 0, white = 0, sky = 0, hills = 0;
  for (int y = 0; y < truck.height(); ++y) {
    for (int x = 0; x < truck.width(); ++x) {
      const Color c = truck.at(x, y);
      covered += maxComponent(c) > 0.06 ? 1 : 0;
      white += c.x > 0.4 && c.y > 0.4 && c.z > 0.4 ? 1 : 0;
      sky += c.z > 0.25 && c.z > 2 * c.x ? 1 : 0;
      hills += c.y > 0.06 && c.y > 2 * c.x && c.y > 2 * c.z ? 1 : 0;
    }
  }
  const int pixels = truck.width() * truck.height();
  EXPECT_GT(covered, pixels / 10);
  EXPECT_LT(covered, pixels * 6 / 10);
  EXPECT_GT(white, pixels / 20);
  EXPECT_GE(sky, 20);
  EXPECT_GE(hills, 20);

  const fs::path two = models / "glTF2/BoxTextured-glTF";
  for (const char* file : {"BoxTextured0.bin", "CesiumLogoFlat.png"}) fs::copy_file(two / file, path(file));
  std::string json = readAll((two / "BoxTextured.gltf").string());
  const size_t mirrored = json.find("33648");  // MIRRORED_REPEAT
  ASSERT_NE(mirrored, std::string::npos);
  json.replace(mirrored, 5, "10497");  // REPEAT
  std::ofstream(path("BoxTextured.gltf")) << json;
  // The paper's renderer, whose Phong surface both files' materials map onto (the path tracer
  // sees the 2.0 file's metallic-roughness surface, which a 1.0 common material does not have).
  const std::string hall = " --integrator hall" + size;
  ASSERT_EQ(run("render " + path("BoxTextured.gltf") + hall + path("two.png")).exitCode, 0);
  r = run("render " + (models / "glTF/BoxTextured-glTF-MaterialsCommon/BoxTextured.gltf").string() +
          hall + path("one.png"));
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const Image one = readImage(path("one.png")), other = readImage(path("two.png"));
  EXPECT_GT(psnr(one, other), 40.0);
  EXPECT_LT(differingPixelFraction(one, other, 16), 0.01);
  int onlyOne = 0;
  for (int y = 0; y < one.height(); ++y) {
    for (int x = 0; x < one.width(); ++x) {
      onlyOne += (maxComponent(one.at(x, y)) > 0.06) != (maxComponent(other.at(x, y)) > 0.06) ? 1 : 0;
    }
  }
  EXPECT_EQ(onlyOne, 0);
}

}  // namespace
}  // namespace prt
