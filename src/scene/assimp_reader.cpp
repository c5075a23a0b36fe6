// readAssimpFile: OBJ+MTL, FBX, COLLADA, PLY, STL, 3DS, glTF 1.0 and the other formats assimp
// reads, translated: assimp's node tree with its transforms (a mesh referenced by several
// nodes is one TriangleMesh, placed by each), materials by mapPbrMaterial when the file has
// physically based keys and by mapCommonMaterial otherwise, diffuse and emissive textures
// (files found by findTextureFile, or embedded ones), cameras and lights.
//
// Only the post-processing steps PRT needs are asked for (triangulation, sorting primitives
// by type, and assimp's own validation of what it built); node transforms are applied here,
// not by assimp's pre-transform step, which keeps instances and has been seen to abort on
// valid files. assimp gives texture coordinates with v running up; they are turned over here
// to the glTF convention the tracer uses.

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <assimp/DefaultIOSystem.h>
#include <assimp/MemoryIOWrapper.h>
#include <assimp/ObjMaterial.h>
#include <assimp/Importer.hpp>
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <map>
#include <numbers>
#include <set>

#include "scene/material_mapping.h"
#include "scene/model_file.h"
#include "scene/model_mesh.h"
#include "scene/model_notes.h"
#include "scene/texture_file.h"

namespace prt {
namespace {

namespace fs = std::filesystem;

// assimp's light colours carry the exporter's intensity in the file's own units; Blender's
// FBX and COLLADA exporters write the light's colour times its power in watts divided by a
// factor that differs per format. Calibrated against Blender's render of the same scene
// (docs/scene-format.md): a Lambertian surface at distance d from a point light of P watts
// shows P / (4 pi^2 d^2) of its albedo.
constexpr double kPointLightScale = 1.0 / (4 * std::numbers::pi * std::numbers::pi);

Transform transformOf(const aiMatrix4x4& a) {
  Transform t;
  const double rows[3][4] = {{a.a1, a.a2, a.a3, a.a4}, {a.b1, a.b2, a.b3, a.b4}, {a.c1, a.c2, a.c3, a.c4}};
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 4; ++c) t.m[r][c] = rows[r][c];
  }
  return t;
}
Vec3 vec(const aiVector3D& v) { return {v.x, v.y, v.z}; }
Color color(const aiColor3D& c) { return {c.r, c.g, c.b}; }

// The files assimp opens itself (the model, an OBJ's MTL, the parts of multi-file formats),
// checked as PRT checks every file it reads: a regular file of at most 2 GiB. A FIFO would
// block assimp for ever, a device might never end. What is turned away (or missing) is
// remembered for the warnings. The model itself is read from `text` when that is given.
class BoundedFiles : public Assimp::DefaultIOSystem {
 public:
  BoundedFiles(const std::string& model, const std::string& text) : model_(model), text_(text) {}
  bool Exists(const char* file) const override { return !resolved(file).empty(); }
  Assimp::IOStream* Open(const char* file, const char* mode = "rb") override {
    if (!text_.empty() && fs::path(file).lexically_normal() == fs::path(model_).lexically_normal()) {
      return new Assimp::MemoryIOStream(reinterpret_cast<const uint8_t*>(text_.data()), text_.size());
    }
    const std::string path = resolved(file);
    if (path.empty()) {
      turnedAway.insert(file);
      return nullptr;
    }
    return DefaultIOSystem::Open(path.c_str(), mode);
  }
  std::set<std::string> turnedAway;

 private:
  const std::string& model_;
  const std::string& text_;  // empty: the model's own bytes
  // The file, or an absolute path that assimp joined onto the model's folder (an OBJ's
  // "mtllib /abs/path.mtl" asked for as "folder//abs/path.mtl"); empty when neither is usable.
  static std::string resolved(const char* file) {
    if (usable(file)) return file;
    const std::string text = file;
    const size_t joined = text.find("//");
    if (joined != std::string::npos && usable(text.c_str() + joined + 1)) {
      return text.substr(joined + 1);
    }
    return {};
  }
  static bool usable(const char* file) {
    std::error_code error;
    if (fs::status(file, error).type() != fs::file_type::regular) return false;
    const uintmax_t size = fs::file_size(file, error);
    return !error && size <= (uintmax_t{2} << 30);
  }
};

class AssimpReader {
 public:
  AssimpReader(const std::string& path, const ModelReadOptions& options, const std::string& text)
      : path_(path), text_(text), directory_(fs::path(path).parent_path()), budget_(options.textureBudgetBytes) {
    notes_.file = path;
    notes_.strict = options.strict;
  }

  ImportedModel read() {
    std::error_code error;
    if (fs::status(path_, error).type() != fs::file_type::regular) {
      throw ModelFileError("model file \"" + path_ + "\" is not a regular file");
    }
    Assimp::Importer importer;
    auto* files = new BoundedFiles(path_, text_);  // the importer owns it
    importer.SetIOHandler(files);
    // Points and lines come out as meshes of their own, which are skipped and counted.
    scene_ = importer.ReadFile(path_, aiProcess_Triangulate | aiProcess_SortByPType |
                                          aiProcess_JoinIdenticalVertices |
                                          aiProcess_ValidateDataStructure);
    if (scene_ == nullptr || scene_->mRootNode == nullptr) {
      std::string why = importer.GetErrorString();
      // assimp catches an allocation that failed and keeps only its name.
      if (why == "std::bad_alloc") throw std::bad_alloc();
      if (why.empty()) why = "not a model file assimp can read";
      throw ModelFileError("model file \"" + path_ + "\" could not be read: " + why);
    }
    for (const std::string& file : files->turnedAway) {
      if (fs::path(file) == fs::path(path_)) continue;
      std::error_code missing;
      const bool exists = fs::exists(file, missing);
      out_.warnings.push_back("model file \"" + path_ + "\" names \"" + file + "\", which " +
                              (exists ? "is not a regular file" : "is missing") +
                              "; rendered without it");
    }
    std::string extension = fs::path(path_).extension().string();
    for (char& ch : extension) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
    out_.format = (extension.empty() ? std::string("model") : extension.substr(1)) + " (assimp)";
    meshes_.assign(scene_->mNumMeshes, {});
    meshRead_.assign(scene_->mNumMeshes, 0);
    materials_.resize(scene_->mNumMaterials);
    materialRead_.assign(scene_->mNumMaterials, 0);
    nodeTransforms_.clear();
    visit(scene_->mRootNode, Transform::identity(), 0);
    addCameras();
    addLights();
    notes_.animations = scene_->mNumAnimations;
    notes_.warn(out_.warnings);
    if (out_.objects.empty()) {
      throw ModelFileError(noTrianglesMessage(path_, "", out_.warnings));
    }
    return std::move(out_);
  }

 private:
  void visit(const aiNode* node, const Transform& parent, int depth) {
    if (depth > kMaxModelNodeDepth) {
      throw ModelFileError("model file \"" + path_ + "\": the node tree is deeper than " +
                           std::to_string(kMaxModelNodeDepth));
    }
    const Transform world = parent * transformOf(node->mTransformation);
    nodeTransforms_.emplace(node->mName.C_Str(), world);
    if (!world.isUsable()) {
      ++notes_.hiddenNodes;
      return;
    }
    for (unsigned i = 0; i < node->mNumMeshes; ++i) {
      const unsigned m = node->mMeshes[i];
      if (m >= scene_->mNumMeshes) continue;  // assimp's validation refuses these
      std::shared_ptr<const TriangleMesh> mesh = meshAt(m);
      if (mesh == nullptr) continue;
      if (out_.objects.size() >= kMaxModelObjects) {
        throw ModelFileError("model file \"" + path_ + "\" places meshes more than " +
                             std::to_string(kMaxModelObjects) + " times");
      }
      out_.objects.push_back({InstanceShape{std::move(mesh), world},
                              material(scene_->mMeshes[m]->mMaterialIndex)});
    }
    for (unsigned c = 0; c < node->mNumChildren; ++c) visit(node->mChildren[c], world, depth + 1);
  }

  std::shared_ptr<const TriangleMesh> meshAt(unsigned index) {
    if (meshRead_[index]) return meshes_[index];
    meshRead_[index] = 1;
    const aiMesh& m = *scene_->mMeshes[index];
    if (m.mAnimMeshes != nullptr && m.mNumAnimMeshes > 0) ++notes_.morphed;
    if (m.HasBones()) ++notes_.skinned;
    RawMesh raw;
    raw.positions.resize(m.mNumVertices);
    for (unsigned v = 0; v < m.mNumVertices; ++v) raw.positions[v] = vec(m.mVertices[v]);
    if (m.HasNormals()) {
      raw.normals.resize(m.mNumVertices);
      for (unsigned v = 0; v < m.mNumVertices; ++v) raw.normals[v] = vec(m.mNormals[v]);
    }
    if (m.HasTextureCoords(0)) {
      raw.uvs.resize(m.mNumVertices);
      for (unsigned v = 0; v < m.mNumVertices; ++v) {
        const aiVector3D& t = m.mTextureCoords[0][v];
        raw.uvs[v] = {t.x, 1.0f - t.y};  // v up (assimp) to v down (glTF, the tracer)
      }
    }
    if (m.HasVertexColors(0)) {
      raw.colors.resize(m.mNumVertices);
      for (unsigned v = 0; v < m.mNumVertices; ++v) {
        const aiColor4D& c = m.mColors[0][v];
        raw.colors[v] = {c.r, c.g, c.b};
      }
    }
    for (unsigned f = 0; f < m.mNumFaces; ++f) {
      const aiFace& face = m.mFaces[f];
      if (face.mNumIndices != 3) {
        ++notes_.skips.notTriangles;
        continue;
      }
      raw.triangles.push_back({face.mIndices[0], face.mIndices[1], face.mIndices[2]});
    }
    meshes_[index] = cleanMesh(std::move(raw), notes_.skips);
    return meshes_[index];
  }

  Material material(unsigned index) {
    if (index >= materials_.size()) return mapCommonMaterial({});
    if (materialRead_[index]) return materials_[index];
    materialRead_[index] = 1;
    const aiMaterial& m = *scene_->mMaterials[index];
    aiString aiName;
    const std::string name =
        m.Get(AI_MATKEY_NAME, aiName) == AI_SUCCESS && aiName.length > 0
            ? "'" + std::string(aiName.C_Str()) + "'"
            : "material " + std::to_string(index);
    float value = 0;
    aiColor3D c;
    int shading = 0;
    m.Get(AI_MATKEY_SHADING_MODEL, shading);
    float metallic = 0, roughness = 0;
    const bool hasMetallic = m.Get(AI_MATKEY_METALLIC_FACTOR, metallic) == AI_SUCCESS;
    const bool hasRoughness = m.Get(AI_MATKEY_ROUGHNESS_FACTOR, roughness) == AI_SUCCESS;
    // assimp gives some Phong materials a roughness of their own (FBX): only a metallic factor
    // or the PBR shading model says the file meant metallic-roughness.
    const bool pbr = shading == aiShadingMode_PBR_BRDF || hasMetallic;
    Material result;
    if (pbr) {
      PbrMaterialInputs in;
      in.metallic = hasMetallic ? metallic : 0;
      in.roughness = hasRoughness ? roughness : 0.5;
      aiColor4D base;
      if (m.Get(AI_MATKEY_BASE_COLOR, base) == AI_SUCCESS) {
        in.baseColor = {base.r, base.g, base.b};
        in.alpha = base.a;
      } else if (m.Get(AI_MATKEY_COLOR_DIFFUSE, c) == AI_SUCCESS) {
        in.baseColor = color(c);
      }
      if (m.Get(AI_MATKEY_OPACITY, value) == AI_SUCCESS && value < 1) {
        in.alpha = value;
        in.alphaMode = PbrMaterialInputs::AlphaMode::blend;
      }
      in.baseColorTexture = textureRef(m, aiTextureType_BASE_COLOR, name);
      if (in.baseColorTexture.texture < 0) in.baseColorTexture = textureRef(m, aiTextureType_DIFFUSE, name);
      if (m.Get(AI_MATKEY_COLOR_EMISSIVE, c) == AI_SUCCESS) in.emissive = color(c);
      if (m.Get(AI_MATKEY_EMISSIVE_INTENSITY, value) == AI_SUCCESS) in.emissiveStrength = value;
      in.emissiveTexture = textureRef(m, aiTextureType_EMISSIVE, name);
      if (m.Get(AI_MATKEY_TRANSMISSION_FACTOR, value) == AI_SUCCESS) in.transmission = value;
      if (m.Get(AI_MATKEY_REFRACTI, value) == AI_SUCCESS && value >= 1) in.ior = value;
      for (const std::string& v : pbrValuesOutOfRange(in)) notes_.outOfRange.insert(name + ": " + v);
      result = mapPbrMaterial(in);
    } else {
      CommonMaterialInputs in;
      const bool hasDiffuse = m.Get(AI_MATKEY_COLOR_DIFFUSE, c) == AI_SUCCESS;
      if (hasDiffuse) in.diffuse = color(c);
      in.diffuseTexture = textureRef(m, aiTextureType_DIFFUSE, name);
      // A texture with no colour beside it is the colour: glTF 1.0's common materials give the
      // diffuse as a colour or as a texture, and assimp then sets no colour.
      if (!hasDiffuse && in.diffuseTexture.texture >= 0) in.diffuse = {1, 1, 1};
      if (m.Get(AI_MATKEY_COLOR_SPECULAR, c) == AI_SUCCESS) in.specular = color(c);
      float strength = 1;
      if (m.Get(AI_MATKEY_SHININESS_STRENGTH, strength) == AI_SUCCESS && strength >= 0) {
        in.specular = in.specular * static_cast<double>(strength);
      }
      if (m.Get(AI_MATKEY_SHININESS, value) == AI_SUCCESS) in.shininess = value;
      if (m.Get(AI_MATKEY_COLOR_EMISSIVE, c) == AI_SUCCESS) in.emissive = color(c);
      in.emissiveTexture = textureRef(m, aiTextureType_EMISSIVE, name);
      if (m.Get(AI_MATKEY_OPACITY, value) == AI_SUCCESS) in.opacity = value;
      // FBX's transparency is TransparentColor x TransparencyFactor: Maya and 3ds Max write a
      // factor of 1 with a black colour (and Opacity 1) for an opaque surface.
      float transparency = 0;
      if (m.Get(AI_MATKEY_TRANSPARENCYFACTOR, transparency) == AI_SUCCESS && transparency > 0 &&
          in.opacity == 1) {
        aiColor3D filter(1, 1, 1);
        if (m.Get(AI_MATKEY_COLOR_TRANSPARENT, filter) == AI_SUCCESS) {
          transparency *= static_cast<float>(maxComponent(color(filter)));
        }
        if (transparency > 0) in.opacity = 1 - std::min(transparency, 1.0f);
      }
      if (m.Get(AI_MATKEY_REFRACTI, value) == AI_SUCCESS) in.ior = value;
      int illum = -1;
      if (m.Get(AI_MATKEY_OBJ_ILLUM, illum) == AI_SUCCESS) in.illum = illum;
      else in.illum = -1;
      if (shading == aiShadingMode_NoShading) in.illum = 0;
      float reflectivity = 0;
      aiColor3D reflective(1, 1, 1);
      if (m.Get(AI_MATKEY_REFLECTIVITY, reflectivity) == AI_SUCCESS && reflectivity > 0) {
        m.Get(AI_MATKEY_COLOR_REFLECTIVE, reflective);
        in.reflectivity = reflectivity * maxComponent(color(reflective));
      }
      result = mapCommonMaterial(in);
    }
    if (m.GetTextureCount(aiTextureType_NORMALS) > 0 || m.GetTextureCount(aiTextureType_HEIGHT) > 0) {
      notes_.notUsed.insert("normal and bump maps (" + name + ")");
    }
    if (m.GetTextureCount(aiTextureType_OPACITY) > 0) notes_.notUsed.insert("opacity maps (" + name + ")");
    if (m.GetTextureCount(aiTextureType_SPECULAR) > 0) notes_.notUsed.insert("specular maps (" + name + ")");
    materials_[index] = result;
    return result;
  }

  TextureRef textureRef(const aiMaterial& m, aiTextureType type, const std::string& material) {
    TextureRef ref;
    aiString written;
    aiTextureMapMode modes[2] = {aiTextureMapMode_Wrap, aiTextureMapMode_Wrap};
    unsigned uvIndex = 0;
    if (m.GetTexture(type, 0, &written, nullptr, &uvIndex, nullptr, nullptr, modes) != AI_SUCCESS) {
      return ref;
    }
    if (uvIndex != 0) notes_.notUsed.insert("texture coordinate sets other than the first (" + material + ")");
    int mode = 0;
    if (m.Get(AI_MATKEY_MAPPINGMODE_U(type, 0), mode) == AI_SUCCESS) modes[0] = static_cast<aiTextureMapMode>(mode);
    if (m.Get(AI_MATKEY_MAPPINGMODE_V(type, 0), mode) == AI_SUCCESS) modes[1] = static_cast<aiTextureMapMode>(mode);
    auto image = textureImage(written.C_Str(), material);
    if (image == nullptr) return ref;
    Texture texture;
    texture.image = std::move(image);
    auto wrap = [](aiTextureMapMode how) {
      return how == aiTextureMapMode_Clamp || how == aiTextureMapMode_Decal ? TextureWrap::clamp
             : how == aiTextureMapMode_Mirror ? TextureWrap::mirror
                                                                       : TextureWrap::repeat;
    };
    texture.wrapU = wrap(modes[0]);
    texture.wrapV = wrap(modes[1]);
    aiUVTransform uv;
    if (m.Get(AI_MATKEY_UVTRANSFORM(type, 0), uv) == AI_SUCCESS) {
      // In assimp's coordinates (v up): u' = s u + t; turned over to v down.
      const double su = uv.mScaling.x, sv = uv.mScaling.y;
      ref.uv.m = {su, 0, uv.mTranslation.x, 0, sv, 1 - sv - uv.mTranslation.y};
      if (uv.mRotation != 0) notes_.notUsed.insert("rotated texture coordinates (" + material + ")");
      for (const double v : ref.uv.m) {
        if (!std::isfinite(v)) ref.uv = {};
      }
    }
    ref.texture = static_cast<int>(out_.textures.size());
    out_.textures.push_back(std::move(texture));
    return ref;
  }

  // The image a material names: embedded ("*N", or a name matching an embedded texture) or a
  // file found beside the model; null (after a warning) if there is none.
  std::shared_ptr<const TextureImage> textureImage(const std::string& written,
                                                   const std::string& material) {
    if (const auto found = images_.find(written); found != images_.end()) return found->second;
    std::shared_ptr<const TextureImage> result;
    try {
      if (const aiTexture* embedded = scene_->GetEmbeddedTexture(written.c_str())) {
        result = decodeEmbedded(*embedded, written);
      } else {
        const fs::path file = findTextureFile(directory_, written);
        if (file.empty()) {
          notes_.problem(out_.warnings, "texture \"" + written + "\" of material " + material + " was not found");
        } else {
          const std::vector<uint8_t> bytes = readTextureFile(file);
          result = decodeTextureImage(bytes.data(), bytes.size(), file.string(), budget_);
        }
      }
    } catch (const TextureError& e) {
      notes_.problem(out_.warnings, e.what());
    }
    images_[written] = result;
    return result;
  }

  std::shared_ptr<const TextureImage> decodeEmbedded(const aiTexture& t, const std::string& name) {
    if (t.mHeight == 0) {  // compressed (PNG, JPEG): mWidth bytes
      return decodeTextureImage(reinterpret_cast<const uint8_t*>(t.pcData), t.mWidth,
                                "embedded " + name, budget_);
    }
    // Raw ARGB8888 texels.
    const size_t texels = static_cast<size_t>(t.mWidth) * t.mHeight;
    if (t.mWidth > static_cast<unsigned>(kMaxTextureSide) ||
        t.mHeight > static_cast<unsigned>(kMaxTextureSide) || texels * 4 > budget_) {
      throw TextureError("embedded texture " + name + " is too large");
    }
    auto image = std::make_shared<TextureImage>();
    image->width = static_cast<int>(t.mWidth);
    image->height = static_cast<int>(t.mHeight);
    image->channels = 4;
    image->name = "embedded " + name;
    image->texels.resize(texels * 4);
    for (size_t i = 0; i < texels; ++i) {
      const aiTexel& p = t.pcData[i];
      image->texels[4 * i] = p.r, image->texels[4 * i + 1] = p.g;
      image->texels[4 * i + 2] = p.b, image->texels[4 * i + 3] = p.a;
    }
    budget_ -= texels * 4;
    return image;
  }

  // A camera or light's node by name: its world transform (identity when no node has it).
  Transform placementOf(const aiString& name) const {
    const auto found = nodeTransforms_.find(name.C_Str());
    return found == nodeTransforms_.end() ? Transform::identity() : found->second;
  }

  void addCameras() {
    for (unsigned i = 0; i < scene_->mNumCameras; ++i) {
      const aiCamera& c = *scene_->mCameras[i];
      const Transform world = placementOf(c.mName);
      if (!world.isUsable()) continue;
      ModelCamera camera;
      camera.name = c.mName.length > 0 ? c.mName.C_Str() : "camera " + std::to_string(i);
      Camera& view = camera.camera;
      view.eye = world.point(vec(c.mPosition));
      const Vec3 forward = world.vector(vec(c.mLookAt));
      view.up = world.vector(vec(c.mUp));
      if (!(length(forward) > 0) || !(length(cross(forward, view.up)) > 0) || !isFinite(view.eye)) {
        continue;
      }
      view.lookAt = view.eye + normalize(forward);
      const double aspect = c.mAspect > 0 && std::isfinite(c.mAspect) ? c.mAspect : 0.0;
      camera.aspectRatio = aspect;
      if (c.mOrthographicWidth > 0) {
        // Half the width of the view: the height is the width over the aspect.
        view.orthoHeight = 2 * c.mOrthographicWidth / (aspect > 0 ? aspect : 1.0) *
                           length(world.vector({0, 1, 0}));
      } else {
        // The whole horizontal angle, whatever assimp's header says (its FBX and COLLADA
        // readers give 0.95 for a 35 mm lens on a 36 mm film, a whole angle of 54.4 degrees).
        const double half = 0.5 * c.mHorizontalFOV;
        const double vertical =
            2 * std::atan(std::tan(half) / (aspect > 0 ? aspect : 4.0 / 3.0)) * 180 / std::numbers::pi;
        view.fovDegrees = vertical > 0 && vertical < 180 ? vertical : 45;
      }
      out_.cameras.push_back(std::move(camera));
    }
  }

  void addLights() {
    for (unsigned i = 0; i < scene_->mNumLights; ++i) {
      const aiLight& l = *scene_->mLights[i];
      const Transform world = placementOf(l.mName);
      if (!world.isUsable()) continue;
      Light light;
      light.color = color(l.mColorDiffuse);
      const Vec3 position = world.point(vec(l.mPosition));
      Vec3 axis = world.vector(vec(l.mDirection));
      const bool aimed = length(axis) > 0;
      if (aimed) axis = normalize(axis);
      // A light that weakens with distance (quadratic attenuation) follows the inverse-square
      // law; one with only constant attenuation does not.
      const bool falls = l.mAttenuationQuadratic > 0 || l.mAttenuationLinear > 0;
      switch (l.mType) {
        case aiLightSource_DIRECTIONAL:
          if (!aimed) continue;
          light.shape = DirectionalLight{axis};
          light.color = light.color / std::numbers::pi;
          break;
        case aiLightSource_SPOT: {
          if (!aimed) continue;
          const double outer = std::clamp(0.5 * l.mAngleOuterCone * 180 / std::numbers::pi, 0.0, 90.0);
          const double inner = std::clamp(0.5 * l.mAngleInnerCone * 180 / std::numbers::pi, 0.0, outer);
          light.shape = SpotLight{position, axis, inner, outer};
          break;
        }
        case aiLightSource_POINT:
          light.shape = PointLight{position};
          break;
        default:
          ++notes_.unusedLights;
          continue;
      }
      if (!std::holds_alternative<DirectionalLight>(light.shape)) {
        if (falls) {
          // A light node scaled with its file's units (FBX in centimetres: 100) sees every
          // distance so scaled: its intensity is too, by the square.
          const double size = std::cbrt(std::abs(world.determinant()));
          light.falloff = Falloff::inverseSquare;
          light.color = light.color * (kPointLightScale * size * size);
        }
      }
      if (!isFinite(light.color) || !isFinite(position)) continue;
      out_.lights.push_back(light);
    }
  }

  const std::string path_;
  const std::string& text_;
  const fs::path directory_;
  size_t budget_;
  const aiScene* scene_ = nullptr;
  ImportedModel out_;
  std::vector<std::shared_ptr<const TriangleMesh>> meshes_;
  std::vector<char> meshRead_;
  std::vector<Material> materials_;
  std::vector<char> materialRead_;
  std::map<std::string, std::shared_ptr<const TextureImage>> images_;
  std::map<std::string, Transform> nodeTransforms_;
  ModelNotes notes_;
};

}  // namespace

ImportedModel readAssimpFile(const std::string& path, const ModelReadOptions& options,
                             const std::string& text) {
  return AssimpReader(path, options, text).read();
}

}  // namespace prt
