#include "aapat/io/mesh_file.h"

#include <assimp/MemoryIOWrapper.h>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <fmt/format.h>
#include <assimp/IOSystem.hpp>
#include <assimp/Importer.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <map>
#include <mutex>
#include <optional>
#include <string_view>
#include <utility>

#include "aapat/analyze/color_image.h"
#include "aapat/core/hash.h"
#include "aapat/core/read_file.h"
#include "aapat/io/gltf_prescan.h"
#include "aapat/io/jpeg_image.h"
#include "aapat/io/ply_prescan.h"
#include "aapat/io/png_image.h"
#include "aapat/render/texture.h"

namespace aapat {
namespace {

// Nodes deeper than this are refused: a hierarchy that deep is a loop or an attack.
constexpr int kMaxNodeDepth = kMaxModelNodeDepth + 1;  // assimp adds a root above the model's own

std::array<std::shared_ptr<const TexturedSurface>, 3> channel_surfaces(const ColorImage& image,
                                                                       const std::string& name) {
  std::array<std::shared_ptr<const TexturedSurface>, 3> out;
  for (int c = 0; c < 3; ++c) {
    Texture t;
    t.name = name;
    t.width = image.width;
    t.height = image.height;
    t.texels.resize(image.pixels());
    // ColorImage rows run from the top; a texture's row 0 is at the bottom (t up).
    for (int j = 0; j < image.height; ++j)
      for (int i = 0; i < image.width; ++i)
        t.texels[static_cast<size_t>(image.height - 1 - j) * image.width + i] =
            image.rgb[3 * (static_cast<size_t>(j) * image.width + i) + c];
    validate(t, name);
    out[static_cast<size_t>(c)] = std::make_shared<const TexturedSurface>(std::move(t));
  }
  return out;
}

// Whether `file` lies inside `folder` once both are resolved (symbolic links
// followed, . and .. removed): a model's buffers, images and materials must,
// unless AAPAT_TRUST_MODELS=1 says its content is trusted (docs/limits.md).
bool trusted_models() {
  const char* v = std::getenv("AAPAT_TRUST_MODELS");
  return v && std::string_view(v) == "1";
}
bool inside(const std::filesystem::path& folder, const std::filesystem::path& file) {
  std::error_code e;
  const auto f = std::filesystem::weakly_canonical(std::filesystem::absolute(folder, e), e);
  const auto p = std::filesystem::weakly_canonical(std::filesystem::absolute(file, e), e);
  if (e) return false;
  const auto [end, rest] = std::mismatch(f.begin(), f.end(), p.begin(), p.end());
  return end == f.end() && rest != p.end();
}
// Throws Error naming a file a model refers to outside its folder.
void check_contained(const std::string& model, const std::string& file) {
  if (trusted_models()) return;
  if (!inside(std::filesystem::path(model).parent_path(), file))
    throw Error(fmt::format(
        "'{}' is outside the model's folder (an absolute path, or one that climbs out of it): "
        "refused; AAPAT_TRUST_MODELS=1 reads it for content you trust (docs/limits.md)",
        file));
}

// Every file a model read, by path: a checksum of its bytes, or none where it
// was missing or refused. The in-process cache keys a mesh by them, so that
// a rewritten .bin or texture is read again (Python renders in one process).
using FilesRead = std::map<std::string, std::optional<uint64_t>>;

// The bytes of a file a model reads, recorded in `read`.
std::string read_model_file(const std::string& file, const std::string& what, FilesRead& read) {
  try {
    std::string bytes = read_file(file, what, kMaxModelFileBytes);
    read[file] = checksum64(bytes);
    return bytes;
  } catch (...) {
    read[file] = std::nullopt;
    throw;
  }
}

// Whether every file still reads as it did (a missing one still missing).
bool unchanged(const FilesRead& read) {
  for (const auto& [file, sum] : read) {
    std::optional<uint64_t> now;
    try {
      now = checksum64(read_file(file, "model file", kMaxModelFileBytes));
    } catch (const Error&) {
    }
    if (now != sum) return false;
  }
  return true;
}

// Every file assimp opens (the model, its .bin buffers, .mtl libraries)
// passes through read_file: a regular file within the size limit, so that a
// FIFO or a device named by a model blocks nothing, and, but for the model
// itself, inside the model's folder. The first refusal is kept for the
// error message.
class CheckedFiles : public Assimp::IOSystem {
 public:
  CheckedFiles(std::string model, FilesRead& read) : model_(std::move(model)), read_(read) {}
  // Anything that exists (a FIFO too) is opened, so that Open refuses it by name.
  bool Exists(const char* file) const override {
    std::error_code e;
    return std::filesystem::exists(file, e);
  }
  char getOsSeparator() const override { return '/'; }
  Assimp::IOStream* Open(const char* file, const char* mode) override {
    if (std::string_view(mode).find_first_of("wa+") != std::string_view::npos) return nullptr;
    try {
      if (std::filesystem::path(file) != std::filesystem::path(model_))
        check_contained(model_, file);
      const std::string bytes = read_model_file(file, "model file", read_);
      // A glTF's node graph, a PLY's counts: checked before assimp recurses or allocates.
      if (std::filesystem::path(file) == std::filesystem::path(model_)) {
        if (looks_like_gltf(bytes, file)) prescan_gltf(bytes, model_);
        if (looks_like_ply(bytes)) prescan_ply(bytes, model_);
      }
      auto* copy = new uint8_t[bytes.size() + 1];
      std::copy(bytes.begin(), bytes.end(), copy);
      return new Assimp::MemoryIOStream(copy, bytes.size(), true);
    } catch (const Error& e) {
      if (refusal.empty()) refusal = e.what();
      return nullptr;
    }
  }
  void Close(Assimp::IOStream* stream) override { delete stream; }
  std::string refusal;

 private:
  std::string model_;
  FilesRead& read_;
};

// A texture file's bytes: JPEG or PNG, told apart by their first bytes.
// Each within a texture's size (kMaxTextureSide a side) and what is left of
// the model's texel budget, checked from its header.
ColorImage decode_image(std::string_view bytes, const std::string& path, const std::string& what,
                        size_t texels_left) {
  const ImageLimits limits{static_cast<uint32_t>(kMaxTextureSide), texels_left};
  return is_jpeg(bytes) ? decode_jpeg(bytes, path, what, limits)
                        : decode_png_color(bytes, path, what, limits).image;
}

class Reader {
 public:
  // gltf: a glTF file (linear colours, and its importer's camera conventions).
  Reader(const aiScene& scene, const std::string& path, bool gltf, FilesRead& read)
      : scene_(scene), path_(path), linear_(gltf), gltf_(gltf), read_(read) {}

  std::shared_ptr<Mesh> read() {
    auto mesh = std::make_shared<Mesh>();
    mesh_ = mesh.get();
    mesh_->name = path_;
    for (unsigned k = 0; k < scene_.mNumMaterials; ++k) mesh_->materials.push_back(material(k));
    if (mesh_->materials.empty()) mesh_->materials.push_back({"default", {1, 1, 1}, {}, ""});
    if (!scene_.mRootNode) throw Error(fmt::format("model '{}': it has no root node", path_));
    node(*scene_.mRootNode, aiMatrix4x4(), 0);
    if (mesh_->triangles.empty())
      throw Error(
          fmt::format("model '{}': it has no triangles (only points, lines or nothing)", path_));
    if (!any_uv_) mesh_->uv.clear();
    if (!any_colour_) mesh_->colours.clear();
    if (scene_.mNumCameras > 0) camera(*scene_.mCameras[0]);
    return mesh;
  }

 private:
  double colour(double v) const {
    v = std::clamp(std::isfinite(v) ? v : 0.0, 0.0, 1.0);
    return linear_ ? static_cast<double>(linear_to_srgb(static_cast<float>(v))) : v;
  }

  MeshMaterial material(unsigned k) {
    const aiMaterial& m = *scene_.mMaterials[k];
    MeshMaterial out;
    aiString name;
    if (m.Get(AI_MATKEY_NAME, name) == AI_SUCCESS) out.name = name.C_Str();
    aiColor4D c;
    if (m.Get(AI_MATKEY_BASE_COLOR, c) == AI_SUCCESS ||
        m.Get(AI_MATKEY_COLOR_DIFFUSE, c) == AI_SUCCESS)
      out.base = {colour(c.r), colour(c.g), colour(c.b)};
    aiString file;
    if (m.GetTexture(aiTextureType_BASE_COLOR, 0, &file) == AI_SUCCESS ||
        m.GetTexture(aiTextureType_DIFFUSE, 0, &file) == AI_SUCCESS) {
      std::string ref = file.C_Str();
      std::replace(ref.begin(), ref.end(), '\\', '/');  // OBJ files written on Windows
      out.texture_name = ref;
      try {
        out.texture =
            channel_surfaces(texture(ref), fmt::format("model '{}': texture '{}'", path_, ref));
      } catch (const Error& e) {
        mesh_->warnings.push_back(
            fmt::format("material '{}': its texture is not used, its base colour stands in ({})",
                        out.name, e.what()));
      }
    }
    return out;
  }

  const ColorImage& texture(const std::string& ref) {
    const std::string what = fmt::format("model '{}': texture", path_);
    if (auto it = cache_.find(ref); it != cache_.end()) return it->second;
    const aiTexture* embedded = scene_.GetEmbeddedTexture(ref.c_str());
    ColorImage image;
    if (embedded) {
      if (embedded->mHeight == 0) {  // compressed bytes: a PNG or a JPEG
        image = decode_image(
            std::string_view(reinterpret_cast<const char*>(embedded->pcData), embedded->mWidth),
            ref, what, texels_left());
      } else {
        const size_t pixels = size_t{embedded->mWidth} * embedded->mHeight;
        if (embedded->mWidth > static_cast<unsigned>(kMaxTextureSide) ||
            embedded->mHeight > static_cast<unsigned>(kMaxTextureSide) || pixels > texels_left())
          throw Error(
              fmt::format("{} '{}': {}x{} texels; at most {} per side and {} in all the "
                          "model's textures (docs/limits.md)",
                          what, ref, embedded->mWidth, embedded->mHeight, kMaxTextureSide,
                          kMaxMeshTextureTexels));
        image = {static_cast<int>(embedded->mWidth), static_cast<int>(embedded->mHeight),
                 std::vector<float>(3 * pixels)};
        for (size_t p = 0; p < pixels; ++p) {
          const aiTexel& t = embedded->pcData[p];
          image.rgb[3 * p] = t.r / 255.0f;
          image.rgb[3 * p + 1] = t.g / 255.0f;
          image.rgb[3 * p + 2] = t.b / 255.0f;
        }
      }
    } else {
      const std::filesystem::path file =
          std::filesystem::path(path_).parent_path() / std::filesystem::path(ref);
      try {
        check_contained(path_, file.string());
      } catch (const Error& e) {
        throw Error(fmt::format("{} '{}': {}", what, ref, e.what()));
      }
      image = decode_image(read_model_file(file.string(), what, read_), file.string(), what,
                           texels_left());
    }
    texels_ += image.rgb.size() / 3;
    return cache_.emplace(ref, std::move(image)).first->second;
  }

  void node(const aiNode& n, const aiMatrix4x4& parent, int depth) {
    if (depth > kMaxNodeDepth)
      throw Error(
          fmt::format("model '{}': nodes nest deeper than {} (a loop?)", path_, kMaxNodeDepth));
    const aiMatrix4x4 world = parent * n.mTransformation;
    if (n.mName.length > 0) transforms_[n.mName.C_Str()] = world;
    for (unsigned k = 0; k < n.mNumMeshes; ++k) {
      if (n.mMeshes[k] >= scene_.mNumMeshes)
        throw Error(fmt::format("model '{}': node '{}' names mesh {} of {}", path_, n.mName.C_Str(),
                                n.mMeshes[k], scene_.mNumMeshes));
      add(*scene_.mMeshes[n.mMeshes[k]], world);
    }
    for (unsigned k = 0; k < n.mNumChildren; ++k) node(*n.mChildren[k], world, depth + 1);
  }

  void add(const aiMesh& m, const aiMatrix4x4& world) {
    const size_t base = mesh_->positions.size();
    if (base + m.mNumVertices > kMaxMeshVertices)
      throw Error(fmt::format("model '{}': more than {} vertices, the limit (docs/limits.md)",
                              path_, kMaxMeshVertices));
    for (unsigned v = 0; v < m.mNumVertices; ++v) {
      const aiVector3D p = world * m.mVertices[v];
      mesh_->positions.push_back({p.x, p.y, p.z});
      if (m.HasTextureCoords(0)) {
        mesh_->uv.push_back({m.mTextureCoords[0][v].x, m.mTextureCoords[0][v].y});
        any_uv_ = true;
      } else {
        mesh_->uv.push_back({0, 0});
      }
      if (m.HasVertexColors(0)) {
        const aiColor4D c = m.mColors[0][v];
        mesh_->colours.push_back({colour(c.r), colour(c.g), colour(c.b)});
        any_colour_ = true;
      } else {
        mesh_->colours.push_back({1, 1, 1});
      }
    }
    if (m.mMaterialIndex >= std::max(1u, scene_.mNumMaterials))
      throw Error(fmt::format("model '{}': mesh '{}' names material {} of {}", path_,
                              m.mName.C_Str(), m.mMaterialIndex, scene_.mNumMaterials));
    for (unsigned f = 0; f < m.mNumFaces; ++f) {
      const aiFace& face = m.mFaces[f];
      if (face.mNumIndices != 3) continue;  // points and lines
      std::array<uint32_t, 3> t;
      for (int k = 0; k < 3; ++k) {
        if (face.mIndices[k] >= m.mNumVertices)
          throw Error(fmt::format("model '{}': mesh '{}' face {} names vertex {} of {}", path_,
                                  m.mName.C_Str(), f, face.mIndices[k], m.mNumVertices));
        t[static_cast<size_t>(k)] = static_cast<uint32_t>(base + face.mIndices[k]);
      }
      if (mesh_->triangles.size() >= kMaxMeshTriangles)
        throw Error(fmt::format("model '{}': more than {} triangles, the limit (docs/limits.md)",
                                path_, kMaxMeshTriangles));
      mesh_->triangles.push_back(t);
      mesh_->material.push_back(m.mMaterialIndex);
    }
  }

  void camera(const aiCamera& c) {
    aiMatrix4x4 world;
    if (auto it = transforms_.find(c.mName.C_Str()); it != transforms_.end()) world = it->second;
    // assimp 5.2's glTF importers copy the camera node's translation into
    // mPosition as well as leaving it in the node: taken once.
    aiVector3D local = c.mPosition;
    if (gltf_ && std::abs(local.x - world.a4) < 1e-6 && std::abs(local.y - world.b4) < 1e-6 &&
        std::abs(local.z - world.c4) < 1e-6)
      local = aiVector3D(0, 0, 0);
    const aiVector3D eye = world * local;
    const aiVector3D target = world * (local + c.mLookAt);
    aiMatrix3x3 rotation(world);
    const aiVector3D up = rotation * c.mUp;
    // mHorizontalFOV is half the horizontal angle (assimp's documentation),
    // but its glTF importers store the whole angle (yfov x aspect); the
    // vertical angle follows from the aspect ratio (1 when the file gives none).
    const double aspect = c.mAspect > 0 ? c.mAspect : 1.0;
    const double half = gltf_ ? double(c.mHorizontalFOV) / 2 : double(c.mHorizontalFOV);
    const double fov = 2 * std::atan(std::tan(half) / aspect) * 180 / kPi;
    MeshCamera cam{{eye.x, eye.y, eye.z}, {target.x, target.y, target.z}, {up.x, up.y, up.z}, fov};
    try {
      validate(cam, "camera");
      mesh_->camera = cam;
    } catch (const Error& e) {
      mesh_->warnings.push_back(fmt::format("its camera is not used ({})", e.what()));
    }
  }

  const aiScene& scene_;
  std::string path_;
  bool linear_, gltf_;
  Mesh* mesh_ = nullptr;
  bool any_uv_ = false, any_colour_ = false;
  size_t texels_left() const {
    return kMaxMeshTextureTexels - std::min(texels_, kMaxMeshTextureTexels);
  }
  FilesRead& read_;
  std::map<std::string, ColorImage> cache_;
  size_t texels_ = 0;  // in the textures decoded so far
  std::map<std::string, aiMatrix4x4> transforms_;
};

}  // namespace

namespace {

std::shared_ptr<const Mesh> load_mesh(const std::string& path, FilesRead& read);

}  // namespace

std::shared_ptr<const Mesh> read_mesh(const std::string& path) {
  std::error_code missing;
  if (!std::filesystem::exists(path, missing))
    throw Error(fmt::format("model '{}': no such file", path));
  // The meshes read last, by path and the contents of every file each read
  // (the model, its buffers, materials and textures; a few are kept, so that
  // a study's check of its scenes and its run share them). Each file is read
  // again to be compared, which also binds a checkpoint to it
  // (core/read_file.h); only the parsing is saved.
  struct Kept {
    std::string path;
    FilesRead read;
    std::shared_ptr<const Mesh> mesh;
  };
  constexpr size_t kKept = 4;
  static std::mutex lock;
  static std::vector<Kept> kept;
  // The entry is copied under the lock and its files read outside it: a
  // large model's re-read does not hold up other threads' lookups.
  std::optional<Kept> candidate;
  {
    std::lock_guard<std::mutex> hold(lock);
    for (const Kept& k : kept)
      if (k.path == path) candidate = k;
  }
  if (candidate && unchanged(candidate->read)) return candidate->mesh;
  FilesRead read;
  std::shared_ptr<const Mesh> mesh = load_mesh(path, read);
  std::lock_guard<std::mutex> hold(lock);
  std::erase_if(kept, [&](const Kept& k) { return k.path == path; });
  kept.push_back({path, std::move(read), mesh});
  if (kept.size() > kKept) kept.erase(kept.begin());
  return mesh;
}

namespace {

std::shared_ptr<const Mesh> load_mesh(const std::string& path, FilesRead& read) {
  Assimp::Importer importer;
  auto* files = new CheckedFiles(path, read);  // the importer owns it
  importer.SetIOHandler(files);
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE,
                              aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  const aiScene* scene = importer.ReadFile(
      path, aiProcess_Triangulate | aiProcess_SortByPType | aiProcess_ValidateDataStructure);
  if (!scene) {
    const std::string why = importer.GetErrorString();
    if (!files->refusal.empty()) {
      const std::string named = fmt::format("model '{}': ", path);  // the prescan names it already
      throw Error(files->refusal.starts_with(named) ? files->refusal : named + files->refusal);
    }
    if (why.find("No meshes remaining") != std::string::npos)  // points and lines were dropped
      throw Error(
          fmt::format("model '{}': it has no triangles (only points, lines or nothing)", path));
    throw Error(fmt::format("model '{}': assimp cannot read it ({})", path, why));
  }
  if (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE)
    throw Error(fmt::format("model '{}': incomplete (assimp read no complete scene)", path));
  const std::string ext = std::filesystem::path(path).extension().string();
  const bool gltf = ext == ".gltf" || ext == ".glb" || ext == ".GLTF" || ext == ".GLB";
  std::shared_ptr<Mesh> mesh;
  try {
    mesh = Reader(*scene, path, gltf, read).read();
  } catch (const std::bad_alloc&) {
    throw Error(fmt::format("model '{}': too large to hold in memory", path));
  }
  // A file the model names that was refused (a device as its material
  // library, a file too large) and that the model could do without.
  if (!files->refusal.empty())
    mesh->warnings.push_back(fmt::format("a file it names was not read: {}", files->refusal));
  validate(*mesh, fmt::format("model '{}'", path));
  mesh->hash = content_hash(*mesh);
  return mesh;
}

}  // namespace

}  // namespace aapat
