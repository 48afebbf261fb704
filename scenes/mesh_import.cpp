#include "scenes/mesh_import.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <cstring>
#include <filesystem>
#include <iterator>
#include <new>
#include <sstream>

#include <sys/resource.h>
#include <unistd.h>

#include <assimp/Importer.hpp>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include "io/input_file.h"
#include "scenes/scene_builder.h"

namespace rc {

namespace {

std::string format_colour(const aiColor3D& c) {
  char text[96];
  std::snprintf(text, sizeof text, "(%g, %g, %g)", c.r, c.g, c.b);
  return text;
}

// The solver's material from an Assimp material: diffuse -> reflectance (clamped below 1, with a
// warning), emissive -> emission.
Material material_from(const aiMaterial& m, unsigned index, const MeshImportOptions& o,
                       std::vector<std::string>& warnings, const std::string& path) {
  Material out;
  aiString name;
  out.name = m.Get(AI_MATKEY_NAME, name) == AI_SUCCESS && name.length > 0 ? std::string(name.C_Str())
                                                                           : "material " + std::to_string(index);
  out.name += " #" + std::to_string(index);  // Assimp's names need not be unique; ours must be
  aiColor3D diffuse(o.default_reflectance, o.default_reflectance, o.default_reflectance);
  if (m.Get(AI_MATKEY_COLOR_DIFFUSE, diffuse) != AI_SUCCESS) {
    warnings.push_back(path + ": material '" + out.name + "' has no diffuse colour; reflectance " +
                       std::to_string(o.default_reflectance) + " (docs/scenes.md)");
  }
  const float rgb[3] = {diffuse.r, diffuse.g, diffuse.b};
  bool clamped = false;
  for (std::size_t b = 0; b < kBands; ++b) {
    double r = std::max(0.0, static_cast<double>(rgb[b]));
    if (r > o.max_reflectance) {
      r = o.max_reflectance;
      clamped = true;
    }
    out.reflectance.band[b] = r;
  }
  if (clamped) {
    warnings.push_back(path + ": material '" + out.name + "' diffuse " + format_colour(diffuse) +
                       " clamped to reflectance " + std::to_string(o.max_reflectance) + " (a reflectance must be below 1)");
  }
  aiColor3D emissive(0, 0, 0);
  if (m.Get(AI_MATKEY_COLOR_EMISSIVE, emissive) == AI_SUCCESS) {
    const float e[3] = {emissive.r, emissive.g, emissive.b};
    for (std::size_t b = 0; b < kBands; ++b) out.emission.band[b] = std::max(0.0, static_cast<double>(e[b]));
  }
  return out;
}

// Some malformed files make Assimp allocate hundreds of gigabytes from a few hundred bytes
// (assimp-testmodels' invalid/OutOfMemory.off); with overcommit that ends in the OOM killer, not an
// exception. While a file is read, the process's address space is capped at what it uses plus
// kImportHeadroom, so such an allocation fails as std::bad_alloc, which becomes a clear error.
constexpr std::uint64_t kImportHeadroom = std::uint64_t{8} << 30;

std::uint64_t address_space_in_use() {
  std::ifstream status("/proc/self/statm");
  std::uint64_t pages = 0;
  status >> pages;
  return pages * static_cast<std::uint64_t>(::sysconf(_SC_PAGESIZE));
}

class AddressSpaceCap {
 public:
  explicit AddressSpaceCap(std::uint64_t headroom) {
    if (::getrlimit(RLIMIT_AS, &saved_) != 0) return;
    const rlim_t cap = static_cast<rlim_t>(address_space_in_use() + headroom);
    if (saved_.rlim_cur != RLIM_INFINITY && saved_.rlim_cur <= cap) return;
    rlimit capped = saved_;
    capped.rlim_cur = cap;
    active_ = ::setrlimit(RLIMIT_AS, &capped) == 0;
  }
  ~AddressSpaceCap() {
    if (active_) ::setrlimit(RLIMIT_AS, &saved_);
  }
  AddressSpaceCap(const AddressSpaceCap&) = delete;
  AddressSpaceCap& operator=(const AddressSpaceCap&) = delete;

 private:
  rlimit saved_{};
  bool active_ = false;
};

// ValidateDataStructure runs first and refuses a face whose index list is missing or points past
// the vertices (fuzz/regressions/mesh: Assimp's OFF and PLY readers build such faces from a short
// or out-of-range face list, and the steps after it would read out of bounds or assert).
constexpr unsigned kImportSteps = aiProcess_ValidateDataStructure | aiProcess_Triangulate |
                                  aiProcess_JoinIdenticalVertices | aiProcess_PreTransformVertices |
                                  aiProcess_SortByPType;

// Assimp 5.2's PLY reader never returns from a header without its end_header line (it reads the
// file again and again), so a PLY file (it starts with the magic word) must have one. The header
// is the file's first lines: the scan stops there, or at the end of a file that has none.
void check_ply_header(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  if (!std::getline(in, line) || (line.rfind("ply", 0) != 0 && line.rfind("PLY", 0) != 0)) return;
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.rfind("end_header", 0) == 0) return;
  }
  throw SceneFileError(path + ": a PLY header without its end_header line");
}

// Assimp recognises a file by its extension first and sniffs text formats well, but a binary STL,
// PLY, glTF or OFF under an extension it does not know can be taken for something else. Their
// signatures: binary STL is 84 + 50 n bytes with n at offset 80; the others start with a magic word.
std::string binary_format_hint(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  char head[84] = {};
  in.read(head, sizeof head);
  const std::streamsize got = in.gcount();
  const std::string start(head, static_cast<std::size_t>(std::max<std::streamsize>(got, 0)));
  if (start.rfind("ply", 0) == 0) return "ply";
  if (start.rfind("glTF", 0) == 0) return "glb";
  if (start.rfind("OFF", 0) == 0) return "off";
  if (got == 84) {
    std::uint32_t n = 0;
    std::memcpy(&n, head + 80, 4);
    if (std::filesystem::file_size(path) == 84 + 50 * static_cast<std::uint64_t>(n)) return "stl";
  }
  return "";
}

const aiScene* read_file(Assimp::Importer& importer, const std::string& path, std::vector<char>& buffer) {
  const std::string extension = std::filesystem::path(path).extension().string();
  const std::string hint = importer.IsExtensionSupported(extension) ? "" : binary_format_hint(path);
  if (hint.empty()) return importer.ReadFile(path, kImportSteps);
  std::ifstream in(path, std::ios::binary);
  buffer.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  return importer.ReadFileFromMemory(buffer.data(), buffer.size(), kImportSteps, hint.c_str());
}

const aiScene* read_capped(Assimp::Importer& importer, const std::string& path, std::vector<char>& buffer) {
  AddressSpaceCap cap(kImportHeadroom);
  try {
    return read_file(importer, path, buffer);
  } catch (const std::bad_alloc&) {
    throw SceneFileError(path + ": reading it needs more than " + std::to_string(kImportHeadroom >> 30) +
                         " GiB of memory (a malformed or enormous file)");
  }
}

}  // namespace

bool is_text_scene_file(const std::string& path) {
  // The first keyword is looked for in the first kSniffBytes only: a device or a file without line
  // breaks (/dev/zero) must not be read to its end here.
  std::ifstream file(path, std::ios::binary);
  if (!file) return false;
  std::string head(kSniffBytes, '\0');
  file.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(file.gcount()));
  std::istringstream in(head);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string first;
    if (!(words >> first) || first[0] == '#') continue;
    return first == "material" || first == "quad" || first == "tri" || first == "camera";
  }
  // A whole text file of comments and blank lines (or an empty one) is ours too: the scene parser
  // says it has no faces, where Assimp would say it has no reader for it.
  return head.size() < kSniffBytes && head.find('\0') == std::string::npos;
}

LoadedScene import_mesh_file(const std::string& path, const MeshImportOptions& o) {
  // Assimp opens the file itself and would read a device or a pipe without end.
  try {
    io::check_regular_file(path, io::kSceneLimitBytes, "a mesh file");
  } catch (const io::InputFileError& e) {
    throw SceneFileError(e.what());
  }
  if (!std::ifstream(path)) throw SceneFileError(path + ": cannot open");
  check_ply_header(path);
  Assimp::Importer importer;
  // Points and lines are removed by the sort (they carry no area); node transforms are applied.
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  std::vector<char> buffer;  // the file, when it is read from memory with a format hint
  const aiScene* scene = read_capped(importer, path, buffer);
  if (scene == nullptr) {
    std::string reason = importer.GetErrorString();
    if (reason.find("bad_alloc") != std::string::npos) {
      reason += " (reading it needs more than " + std::to_string(kImportHeadroom >> 30) +
                " GiB of memory: a malformed or enormous file)";
    }
    throw SceneFileError(path + ": " + reason);
  }
  if (scene->mNumMeshes == 0) throw SceneFileError(path + ": the file holds no meshes");

  LoadedScene out;
  std::vector<std::string> warnings;
  SceneBuilder builder(path);
  std::vector<int> material_index(scene->mNumMaterials, -1);
  std::size_t skipped = 0;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh& mesh = *scene->mMeshes[m];
    const unsigned mat = mesh.mMaterialIndex;
    if (mat < material_index.size() && material_index[mat] < 0) {
      try {
        material_index[mat] = builder.add_material(material_from(*scene->mMaterials[mat], mat, o, warnings, path));
      } catch (const std::invalid_argument& e) {
        throw SceneFileError(path + ": " + e.what());  // e.g. an emissive colour that is not finite
      }
    }
    const std::string origin = path + ": mesh " + std::to_string(m) + (mesh.mName.length ? " '" + std::string(mesh.mName.C_Str()) + "'" : "");
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices != 3) {
        ++skipped;
        continue;
      }
      std::vector<Vec3> vertices;
      for (unsigned k = 0; k < 3; ++k) {
        const aiVector3D& v = mesh.mVertices[face.mIndices[k]];
        vertices.push_back({v.x, v.y, v.z});
      }
      try {
        builder.add_surface(origin + " face " + std::to_string(f), material_index[mat], vertices, origin);
      } catch (const std::invalid_argument& e) {
        throw SceneFileError(e.what());  // a coordinate that is not finite; starts with the file
      }
    }
  }
  if (skipped > 0) warnings.push_back(path + ": " + std::to_string(skipped) + " faces that are not triangles skipped");
  try {
    out.scene = builder.build();
  } catch (const std::invalid_argument& e) {
    throw SceneFileError(path + ": " + e.what());
  }
  if (o.require_emitter && !out.scene.emits_light()) {
    throw SceneFileError(path + ": no material emits light (an emissive colour); add an emitter, e.g. by composing "
                                "the mesh into the Cornell Box (docs/scenes.md)");
  }
  warnings.insert(warnings.end(), builder.warnings().begin(), builder.warnings().end());
  out.warnings = std::move(warnings);
  return out;
}

}  // namespace rc
