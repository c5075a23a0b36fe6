// The node tree's placement of a mesh file's meshes (placed_meshes.h), on scenes built here
// and on files other tools wrote (the assimp-testmodels package): order, transforms, normals,
// and the trees that are refused.

#include "scene/placed_meshes.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <memory>

#include "scene/mesh_file.h"

namespace prt {
namespace {

// A mesh of one triangle whose first vertex is (tag, 0, 0), with normals along +z.
aiMesh* triangleMesh(float tag, unsigned material) {
  auto* mesh = new aiMesh();
  mesh->mPrimitiveTypes = aiPrimitiveType_TRIANGLE;
  mesh->mMaterialIndex = material;
  mesh->mNumVertices = 3;
  mesh->mVertices = new aiVector3D[3]{{tag, 0, 0}, {tag + 1, 0, 0}, {tag, 1, 0}};
  mesh->mNormals = new aiVector3D[3]{{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
  mesh->mNumFaces = 1;
  mesh->mFaces = new aiFace[1];
  mesh->mFaces[0].mNumIndices = 3;
  mesh->mFaces[0].mIndices = new unsigned[3]{0, 1, 2};
  return mesh;
}

aiNode* node(const char* name, std::initializer_list<unsigned> meshes,
             std::initializer_list<aiNode*> children = {}) {
  auto* n = new aiNode(name);
  n->mNumMeshes = static_cast<unsigned>(meshes.size());
  n->mMeshes = new unsigned[meshes.size() + 1];
  std::copy(meshes.begin(), meshes.end(), n->mMeshes);
  if (children.size() > 0) n->addChildren(static_cast<unsigned>(children.size()),
                                          const_cast<aiNode**>(children.begin()));
  return n;
}

// Three meshes (materials 1, 0, 0) placed by a tree: root{mesh 0, child a{mesh 1}, child b{mesh 2, mesh 1}}.
std::unique_ptr<aiScene> treeScene() {
  auto scene = std::make_unique<aiScene>();
  scene->mNumMeshes = 3;
  scene->mMeshes = new aiMesh*[3]{triangleMesh(10, 1), triangleMesh(20, 0), triangleMesh(30, 0)};
  scene->mNumMaterials = 2;
  scene->mMaterials = new aiMaterial*[2]{new aiMaterial(), new aiMaterial()};
  aiNode* a = node("a", {1});
  aiNode* b = node("b", {2, 1});
  scene->mRootNode = node("root", {0}, {a, b});
  return scene;
}

TEST(PlacedMeshes, AreInTheOrderOfMaterialThenTree) {
  const auto scene = treeScene();
  const auto placed = placedMeshes(*scene, "tree");
  ASSERT_EQ(placed.size(), 4u);
  // Material 0: mesh 1 under a, then mesh 2 and mesh 1 under b; then material 1: mesh 0.
  EXPECT_EQ(placed[0].mesh, scene->mMeshes[1]);
  EXPECT_EQ(placed[1].mesh, scene->mMeshes[2]);
  EXPECT_EQ(placed[2].mesh, scene->mMeshes[1]);
  EXPECT_EQ(placed[3].mesh, scene->mMeshes[0]);
  for (const auto& p : placed) EXPECT_TRUE(p.identity);
}

TEST(PlacedMeshes, TransformsOfTheTreeAreComposed) {
  auto scene = treeScene();
  aiMatrix4x4::Translation(aiVector3D(0, 0, 5), scene->mRootNode->mTransformation);
  aiNode* b = scene->mRootNode->mChildren[1];
  aiMatrix4x4::Scaling(aiVector3D(2, 2, 2), b->mTransformation);
  // A translation of 5 mm is kept (assimp's own identity test would drop it).
  aiMatrix4x4::Translation(aiVector3D(0.005f, 0, 0), scene->mRootNode->mChildren[0]->mTransformation);
  const auto placed = placedMeshes(*scene, "tree");
  ASSERT_EQ(placed.size(), 4u);
  EXPECT_FALSE(placed[0].identity);
  EXPECT_FLOAT_EQ(placedVertex(placed[0], 0).x, 20.005f);  // under a: root then a
  EXPECT_FLOAT_EQ(placedVertex(placed[0], 0).z, 5.0f);
  EXPECT_FLOAT_EQ(placedVertex(placed[1], 0).x, 60.0f);  // under b: scaled by 2
  EXPECT_FLOAT_EQ(placedVertex(placed[1], 0).z, 5.0f);
  const aiVector3D n = placedNormal(placed[1], 0);
  EXPECT_FLOAT_EQ(n.z, 1.0f);  // normals stay unit length under a scale
  EXPECT_FLOAT_EQ(placedVertex(placed[3], 0).z, 5.0f);  // the root's own
}

TEST(PlacedMeshes, ANonUniformScaleTurnsNormalsByTheInverseTranspose) {
  auto scene = treeScene();
  aiMatrix4x4::Scaling(aiVector3D(1, 4, 1), scene->mRootNode->mTransformation);
  scene->mMeshes[0]->mNormals[0] = aiVector3D(0, 1, 1).Normalize();
  const auto placed = placedMeshes(*scene, "tree");
  const aiVector3D n = placedNormal(placed[3], 0);
  EXPECT_NEAR(n.y / n.z, 0.25, 1e-6);  // scaling y by 4 tilts the normal towards z
  EXPECT_NEAR(n.Length(), 1.0, 1e-6);
}

TEST(PlacedMeshes, ANodeNamingAMissingMeshIsRefused) {
  auto scene = treeScene();
  scene->mRootNode->mMeshes[0] = 7;
  try {
    placedMeshes(*scene, "tree.dae");
    FAIL() << "accepted a node naming mesh 7 of 3";
  } catch (const MeshFileError& e) {
    EXPECT_NE(std::string(e.what()).find("\"tree.dae\": node \"root\" refers to mesh 7"),
              std::string::npos)
        << e.what();
  }
}

TEST(PlacedMeshes, ATreeTooDeepIsRefusedWithoutRecursing) {
  auto scene = treeScene();
  aiNode* chain = scene->mRootNode->mChildren[0];
  for (unsigned i = 0; i < kMaxNodeDepth + 5; ++i) {
    aiNode* child = node("deeper", {});
    chain->addChildren(1, &child);
    chain = child;
  }
  EXPECT_THROW(placedMeshes(*scene, "deep"), MeshFileError);
}

TEST(PlacedMeshes, NullChildrenAndNoRootArePassedOver) {
  auto scene = treeScene();
  scene->mRootNode->mChildren[1]->mParent = nullptr;
  delete scene->mRootNode->mChildren[1];
  scene->mRootNode->mChildren[1] = nullptr;  // as assimp's RAW reader leaves some trees
  EXPECT_EQ(placedMeshes(*scene, "tree").size(), 2u);
  aiScene empty;
  EXPECT_TRUE(placedMeshes(empty, "empty").empty());
}

// Files from the assimp-testmodels package (scripts/install-deps.sh installs it) on which
// assimp's own pre-transform step aborted (a camera or light without a node) or crashed (a
// RAW file's tree with a null node): read in this process, they now load or give a
// MeshFileError.
TEST(PlacedMeshes, FilesOnWhichAssimpsPreTransformCrashedAreRead) {
  const std::filesystem::path models = "/usr/share/assimp/models";
  if (!std::filesystem::exists(models)) GTEST_SKIP() << "assimp-testmodels is not installed";
  for (const char* file : {"OpenGEX/camera.ogex", "OpenGEX/collada.ogex", "RAW/WithColor.raw",
                           "RAW/WithTexture.raw"}) {
    MeshSource source;
    source.file = (models / file).string();
    try {
      const LoadedMesh loaded = loadMeshFileHere(source);
      EXPECT_GT(loaded.mesh->triangles.size(), 0u) << file;
    } catch (const MeshFileError& e) {
      ADD_FAILURE() << file << ": " << e.what();
    }
  }
}

}  // namespace
}  // namespace prt
