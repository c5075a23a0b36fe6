// Meshes in scenes: `mesh` blocks reading OBJ and PLY files (ASCII and binary) written here,
// `triangle` blocks, the transform, and what bad mesh files give (a located error, or
// triangles skipped with a warning).

#include "scene/mesh_file.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>

#include "scene/asset_pack.h"
#include "scene/scene_file.h"

namespace prt {
namespace {

namespace fs = std::filesystem;

const std::string kMeshPreamble = "camera { eye 0 0 -5 look_at 0 0 0 }\nimage { width 4 height 3 }\n";

// A unit square in z = 0 as two triangles, counter-clockwise seen from +z.
const std::string kSquareObj = "# a square\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\n";

class MeshFile : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("prt-mesh-file-" + std::to_string(::getpid()) + "-" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "models");
  }
  void TearDown() override { fs::remove_all(dir_); }

  void write(const std::string& name, const std::string& bytes) const {
    std::ofstream(dir_ / name, std::ios::binary) << bytes;
  }
  // The scene `body` (after the preamble) saved in the test directory and loaded.
  Scene load(const std::string& body) const {
    write("test.scene", kMeshPreamble + body);
    return loadSceneFile((dir_ / "test.scene").string());
  }
  std::string errorOf(const std::string& body) const {
    try {
      load(body);
    } catch (const InputError& error) {
      return error.format();
    }
    ADD_FAILURE() << "no error for:\n" << body;
    return {};
  }
  static const TriangleMesh& meshOf(const Scene& scene, size_t object = 0) {
    return *std::get<MeshShape>(scene.objects.at(object).shape).mesh;
  }

  fs::path dir_;
};

TEST_F(MeshFile, ObjIsReadRelativeToTheSceneFile) {
  write("models/square.obj", kSquareObj);
  const Scene scene = load("mesh { file \"models/square.obj\" surface { color 1 0 0 } }\n");
  ASSERT_EQ(scene.objects.size(), 1u);
  const TriangleMesh& mesh = meshOf(scene);
  EXPECT_EQ(mesh.triangles.size(), 2u);
  EXPECT_EQ(mesh.vertices.size(), 4u);
  EXPECT_TRUE(mesh.normals.empty());
  EXPECT_EQ(scene.objects[0].material.color, Color(1, 0, 0));
  EXPECT_TRUE(scene.warnings.empty());
}

TEST_F(MeshFile, AsciiAndBinaryPlyGiveTheSameMesh) {
  const std::string header =
      "element vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 2\nproperty list uchar int vertex_indices\nend_header\n";
  write("models/a.ply",
        "ply\nformat ascii 1.0\n" + header + "0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n");
  std::string binary = "ply\nformat binary_little_endian 1.0\n" + header;
  const float xyz[4][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  binary.append(reinterpret_cast<const char*>(xyz), sizeof xyz);
  const int32_t faces[2][3] = {{0, 1, 2}, {0, 2, 3}};
  for (const auto& face : faces) {
    binary.push_back(3);
    binary.append(reinterpret_cast<const char*>(face), sizeof face);
  }
  write("models/b.ply", binary);
  const Scene scene = load("mesh { file \"models/a.ply\" }\nmesh { file \"models/b.ply\" }\n");
  EXPECT_EQ(meshOf(scene, 0).triangles.size(), 2u);
  EXPECT_EQ(meshOf(scene, 0), meshOf(scene, 1));
}

TEST_F(MeshFile, TransformScalesThenRotatesThenTranslates) {
  write("models/square.obj", kSquareObj);
  const Scene scene =
      load("mesh { file \"models/square.obj\" scale 2 rotate 0 0 90 translate 10 0 0 }\n");
  const TriangleMesh& mesh = meshOf(scene);
  // (1, 0, 0) -> (2, 0, 0) -> (0, 2, 0) -> (10, 2, 0)
  const Vec3 v = mesh.vertices[mesh.triangles[0][1]];
  EXPECT_NEAR(v.x, 10, 1e-12);
  EXPECT_NEAR(v.y, 2, 1e-12);
  EXPECT_NEAR(v.z, 0, 1e-12);
}

TEST_F(MeshFile, MirroringScaleKeepsTheTrianglesFacingOut) {
  write("models/square.obj", kSquareObj);
  const Scene scene = load("mesh { file \"models/square.obj\" scale -1 1 1 }\n");
  const TriangleMesh& mesh = meshOf(scene);
  const auto& t = mesh.triangles[0];
  const Vec3 n =
      cross(mesh.vertices[t[1]] - mesh.vertices[t[0]], mesh.vertices[t[2]] - mesh.vertices[t[0]]);
  EXPECT_GT(n.z, 0);
}

TEST_F(MeshFile, SmoothComputesUnitVertexNormals) {
  // A tent: two faces meeting at a ridge; the ridge's normals point straight up.
  write("models/tent.obj", "v -1 0 0\nv 0 1 -1\nv 0 1 1\nv 1 0 0\nf 1 3 2\nf 2 3 4\n");
  const Scene scene = load("mesh { file \"models/tent.obj\" smooth }\n");
  const TriangleMesh& mesh = meshOf(scene);
  ASSERT_EQ(mesh.normals.size(), mesh.vertices.size());
  for (const Vec3& n : mesh.normals) EXPECT_NEAR(length(n), 1, 1e-12);
  bool ridge = false;
  for (size_t v = 0; v < mesh.vertices.size(); ++v) {
    if (mesh.vertices[v].y == 1) {
      ridge = true;
      EXPECT_NEAR(mesh.normals[v].y, 1, 1e-12);
    }
  }
  EXPECT_TRUE(ridge);
}

// Normals given in the file are kept, turned with the mesh and scaled by its inverse
// (a normal stays perpendicular to a surface stretched along x).
TEST_F(MeshFile, NormalsFromTheFileAreTurnedWithTheMesh) {
  write("models/n.obj",
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 1 0 1\nvn 1 0 1\nvn 1 0 1\nf 1//1 2//2 3//3\n");
  const Scene scene = load("mesh { file \"models/n.obj\" scale 2 1 1 rotate 0 0 90 }\n");
  const TriangleMesh& mesh = meshOf(scene);
  ASSERT_EQ(mesh.normals.size(), 3u);
  // (1, 0, 1) scaled by (1/2, 1, 1): (0.5, 0, 1); turned 90 degrees about z: (0, 0.5, 1).
  const Vec3 expected = normalize(Vec3(0, 0.5, 1));
  for (const Vec3& n : mesh.normals) {
    EXPECT_NEAR(n.x, expected.x, 1e-12);
    EXPECT_NEAR(n.y, expected.y, 1e-12);
    EXPECT_NEAR(n.z, expected.z, 1e-12);
  }
}

TEST_F(MeshFile, TriangleBlocksAndTheirWrittenFormRoundTrip) {
  write("models/square.obj", kSquareObj);
  const Scene scene = load(
      "triangle { vertices 0 0 0  1 0 0  0 1 0 surface { color 0 1 0 } }\n"
      "mesh { file \"models/square.obj\" scale 1 2 3 rotate 10 20 30 translate 1 2 3 smooth }\n");
  ASSERT_EQ(scene.objects.size(), 2u);
  EXPECT_EQ(meshOf(scene, 0).triangles.size(), 1u);
  const Scene again = parseScene(writeScene(scene), "again.scene");
  ASSERT_EQ(again.objects.size(), 2u);
  EXPECT_EQ(again.objects[0], scene.objects[0]);
  EXPECT_EQ(again.objects[1], scene.objects[1]);
}

TEST_F(MeshFile, MissingFileNamesTheMeshAndTheSceneLine) {
  const std::string message = errorOf("\nmesh { file \"models/none.obj\" }\n");
  EXPECT_NE(message.find("test.scene:4:"), std::string::npos) << message;
  EXPECT_NE(message.find("none.obj"), std::string::npos) << message;
  EXPECT_NE(message.find("does not exist"), std::string::npos) << message;
}

TEST_F(MeshFile, AMissingBunnySaysWhichScriptFetchesIt) {
  const std::string message = errorOf("mesh { file \"models/bunny.ply\" }\n");
  EXPECT_NE(message.find("does not exist"), std::string::npos) << message;
  EXPECT_NE(message.find("scripts/fetch-bunny.sh"), std::string::npos) << message;
  EXPECT_EQ(errorOf("mesh { file \"models/none.ply\" }\n").find("fetch-bunny"), std::string::npos);
}

TEST_F(MeshFile, MalformedObjLineIsReportedWithItsLineAndColumn) {
  write("models/bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 x 2\nf 1 2 3\n");
  const std::string message = errorOf("mesh { file \"models/bad.obj\" }\n");
  EXPECT_NE(message.find("test.scene:3:"), std::string::npos) << message;
  EXPECT_NE(message.find("bad.obj:4:5: expected a number"), std::string::npos) << message;
}

TEST_F(MeshFile, OutOfRangeIndexInTextFilesIsReportedWithItsLineAndColumn) {
  write("models/far.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 9\n");
  std::string message = errorOf("mesh { file \"models/far.obj\" }\n");
  EXPECT_NE(message.find("far.obj:5:7: a vertex index '9' is out of range"), std::string::npos)
      << message;
  write("models/line.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nl 1 2\nl 1 -4\n");
  message = errorOf("mesh { file \"models/line.obj\" }\n");
  EXPECT_NE(message.find("line.obj:6:5: a vertex index '-4' is out of range"), std::string::npos)
      << message;
  write("models/far.ply",
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
        "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
        "0 0 0\n1 0 0\n0 1 0\n3 0 1 5\n");
  message = errorOf("mesh { file \"models/far.ply\" }\n");
  EXPECT_NE(message.find("far.ply:13:7: vertex index '5' is out of range"), std::string::npos)
      << message;
}

TEST_F(MeshFile, NonFiniteNumbersInTextFilesAreRefused) {
  write("models/nan.obj", "v 0 0 0\nv 1 0 0\nv nan 1 0\nf 1 2 3\n");
  const std::string message = errorOf("mesh { file \"models/nan.obj\" }\n");
  EXPECT_NE(message.find("nan.obj:3:3:"), std::string::npos) << message;
  EXPECT_NE(message.find("not a finite number"), std::string::npos) << message;
}

TEST_F(MeshFile, TruncatedAndGarbageFilesAreRefused) {
  write("models/short.ply",
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
        "property float z\nend_header\n0 0 0\n1 0 0\n");
  EXPECT_NE(errorOf("mesh { file \"models/short.ply\" }\n").find("short.ply:10: the file ends"),
            std::string::npos);
  write("models/junk.ply", "this is no mesh");
  EXPECT_NE(errorOf("mesh { file \"models/junk.ply\" }\n").find("could not be read"),
            std::string::npos);
  write("models/empty.obj", "");
  EXPECT_NE(errorOf("mesh { file \"models/empty.obj\" }\n").find("is empty"), std::string::npos);
}

// Binary PLY files that assimp would crash on are refused first, naming the record.
TEST_F(MeshFile, BrokenBinaryPlyIsRefusedBeforeItIsRead) {
  const std::string header =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
      "property float y\nproperty float z\nelement face 1\n"
      "property list uchar int vertex_indices\nend_header\n";
  const float xyz[3][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  std::string body(reinterpret_cast<const char*>(xyz), sizeof xyz);
  auto face = [](int32_t a, int32_t b, int32_t c, uint8_t n = 3) {
    const int32_t corners[3] = {a, b, c};
    return std::string(1, static_cast<char>(n)) +
           std::string(reinterpret_cast<const char*>(corners), sizeof corners);
  };
  write("models/short.ply", header + body.substr(0, 20));
  EXPECT_NE(errorOf("mesh { file \"models/short.ply\" }\n").find("vertex 2 of 3"),
            std::string::npos);
  write("models/far.ply", header + body + face(0, 1, 7));
  EXPECT_NE(errorOf("mesh { file \"models/far.ply\" }\n").find("face 1 of 1"), std::string::npos);
  EXPECT_NE(errorOf("mesh { file \"models/far.ply\" }\n").find("vertex index 7 is out of range"),
            std::string::npos);
  write("models/long.ply", header + body + face(0, 1, 2, 200));
  EXPECT_NE(errorOf("mesh { file \"models/long.ply\" }\n").find("list of 200"), std::string::npos);
  write("models/good.ply", header + body + face(0, 1, 2));
  EXPECT_EQ(meshOf(load("mesh { file \"models/good.ply\" }\n")).triangles.size(), 1u);
}

TEST_F(MeshFile, DegenerateTrianglesAreSkippedWithAWarning) {
  write("models/some.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\nf 1 2 3\nf 1 2 4\n");
  const Scene scene = load("mesh { file \"models/some.obj\" }\n");
  EXPECT_EQ(meshOf(scene).triangles.size(), 1u);
  ASSERT_EQ(scene.warnings.size(), 1u);
  EXPECT_NE(scene.warnings[0].find("test.scene:3: mesh file"), std::string::npos)
      << scene.warnings[0];
  EXPECT_NE(scene.warnings[0].find("skipped 1 triangle of zero area"), std::string::npos)
      << scene.warnings[0];
  // Only degenerate ones: nothing left to trace.
  write("models/flat.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n");
  EXPECT_NE(errorOf("mesh { file \"models/flat.obj\" }\n").find("no triangle that can be traced"),
            std::string::npos);
}

TEST_F(MeshFile, BinaryNonFiniteVerticesAreSkippedWithAWarning) {
  std::string binary =
      "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\n"
      "property float y\nproperty float z\nelement face 2\n"
      "property list uchar int vertex_indices\nend_header\n";
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float xyz[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {nan, 1, 1}};
  binary.append(reinterpret_cast<const char*>(xyz), sizeof xyz);
  const int32_t faces[2][3] = {{0, 1, 2}, {0, 1, 3}};
  for (const auto& face : faces) {
    binary.push_back(3);
    binary.append(reinterpret_cast<const char*>(face), sizeof face);
  }
  write("models/nan.ply", binary);
  const Scene scene = load("mesh { file \"models/nan.ply\" }\n");
  EXPECT_EQ(meshOf(scene).triangles.size(), 1u);
  ASSERT_EQ(scene.warnings.size(), 1u);
  EXPECT_NE(scene.warnings[0].find("not finite"), std::string::npos) << scene.warnings[0];
}

TEST_F(MeshFile, BadBlockValuesArePointedAt) {
  write("models/square.obj", kSquareObj);
  EXPECT_NE(errorOf("mesh { file \"models/square.obj\" scale 1 0 1 }\n").find("3:41: error"),
            std::string::npos);
  EXPECT_NE(errorOf("triangle { vertices 0 0 0  1 1 1  2 2 2 }\n").find("no area"),
            std::string::npos);
  EXPECT_NE(errorOf("mesh { scale 2 }\n").find("file"), std::string::npos);
}

// What a worker does with the scene its master sent: the text and the packed meshes give the
// same scene, bit for bit, with the mesh files gone.
TEST_F(MeshFile, ShippedMeshesNeedNoFiles) {
  write("models/tent.obj", "v -1 0 0\nv 0 1 -1\nv 0 1 1\nv 1 0 0\nf 1 3 2\nf 2 3 4\n");
  write("models/square.obj", kSquareObj);
  const Scene scene = load(
      "mesh { file \"models/tent.obj\" smooth rotate 10 20 30 surface { color 1 0 0 } }\n"
      "triangle { vertices 0 0 0  1 0 0  0 1 0 }\n"
      "sphere { center 0 0 0 radius 1 }\n"
      "mesh { file \"models/square.obj\" scale 3 }\n");
  const std::string text = writeScene(scene);
  const std::vector<uint8_t> bytes = packAssets(scene);
  fs::remove_all(dir_ / "models");
  const Scene again = parseScene(text, "<sent>", unpackAssets(bytes));
  ASSERT_EQ(again.objects.size(), scene.objects.size());
  for (size_t i = 0; i < scene.objects.size(); ++i) EXPECT_EQ(again.objects[i], scene.objects[i]);
  // Vertices, indices and normals, nothing more: 4 + 4 vertices, 2 + 2 triangles, 4 normals,
  // after the tag, the counts (meshes; six arrays per mesh; images, blocks, imports), the
  // two blocks' mesh indices, the empty rig (five counts and the duration) and no environment
  // map (its width and height, zero).
  EXPECT_EQ(bytes.size(),
            8 + 8 + 2 * 6 * 8 + 8 + 8 + 2 * 4 + 8 + 8 * 24 + 4 * 12 + 4 * 24 + 6 * 8 + 2 * 4);
  // Without them, the files are looked for (and are gone).
  EXPECT_THROW(parseScene(text, "<sent>"), InputError);
  EXPECT_THROW(parseScene(text, "<sent>", ShippedAssets{}), InputError);
}

TEST_F(MeshFile, MalformedPackedMeshesAreRefused) {
  write("models/square.obj", kSquareObj);
  const std::vector<uint8_t> bytes = packAssets(load("mesh { file \"models/square.obj\" }\n"));
  for (size_t size : {size_t{7}, size_t{30}, bytes.size() - 1}) {
    EXPECT_THROW(unpackAssets(std::vector<uint8_t>(
                     bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(size))),
                 std::runtime_error)
        << size;
  }
  std::vector<uint8_t> longer = bytes;
  longer.push_back(0);
  EXPECT_THROW(unpackAssets(longer), std::runtime_error);
  std::vector<uint8_t> badIndex = bytes;
  // The last triangle's last index: before the colours', uvs' and normals' counts, the images'
  // count, the block (count and index) and the imports' count.
  badIndex[bytes.size() - 1 - 8 * 3 - 8 - 12 - 8] = 0x7f;
  EXPECT_THROW(unpackAssets(badIndex), std::runtime_error);
  EXPECT_EQ(unpackAssets(bytes).meshBlocks.size(), 1u);
  EXPECT_TRUE(unpackAssets({}).meshBlocks.empty());  // a scene with nothing to ship
}

}  // namespace
}  // namespace prt
