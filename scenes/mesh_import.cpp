#include "scenes/mesh_import.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <stdexcept>
#include <chrono>
#include <cstdint>
#include <type_traits>
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

#include "io/child_process.h"
#include "io/input_file.h"
#include "io/text_encoding.h"
#include "scenes/obj_material_names.h"
#include "scenes/scene_builder.h"

namespace rc {

namespace {

std::string format_colour(const aiColor3D& c) {
  char text[96];
  std::snprintf(text, sizeof text, "(%g, %g, %g)", c.r, c.g, c.b);
  return text;
}

// A material colour the text format would refuse (docs/scenes.md, Meshes): the child process sends
// its message to the parent as the reader's error.
class MaterialError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// Reflectance: finite, in [0, 1] (at or above max_reflectance it is clamped, with a warning).
// Emission: finite and not negative. NaN, negative and infinite components used to become 0 or
// pass silently.
void check_colour(const aiColor3D& c, const std::string& material, const char* what, bool reflectance) {
  for (const float x : {c.r, c.g, c.b}) {
    const bool bad = !std::isfinite(x) || x < 0 || (reflectance && x > 1);
    if (!bad) continue;
    throw MaterialError("material '" + material + "': " + what + " " + format_colour(c) + ": " +
                        (reflectance ? "a reflectance must be finite and within [0, 1] (0.99 and above are clamped to 0.99)"
                                     : "an emission must be finite and not negative") +
                        " (docs/scenes.md, Meshes)");
  }
}

// The solver's material from an Assimp material: diffuse -> reflectance (clamped below 1, with a
// warning), emissive -> emission. Names that are not UTF-8 (a Latin-1 MTL) are kept with their
// foreign bytes shown as \xNN: they reach report.json and the terminal.
Material material_from(const aiMaterial& m, unsigned index, const MeshImportOptions& o,
                       std::vector<std::string>& warnings, const std::string& path) {
  Material out;
  aiString name;
  out.name = m.Get(AI_MATKEY_NAME, name) == AI_SUCCESS && name.length > 0 ? io::printable_utf8(name.C_Str())
                                                                           : "material " + std::to_string(index);
  out.name += " #" + std::to_string(index);  // Assimp's names need not be unique; ours must be
  aiColor3D diffuse(o.default_reflectance, o.default_reflectance, o.default_reflectance);
  if (m.Get(AI_MATKEY_COLOR_DIFFUSE, diffuse) != AI_SUCCESS) {
    warnings.push_back(path + ": material '" + out.name + "' has no diffuse colour; reflectance " +
                       std::to_string(o.default_reflectance) + " (docs/scenes.md)");
  }
  check_colour(diffuse, out.name, "diffuse colour", true);
  const float rgb[3] = {diffuse.r, diffuse.g, diffuse.b};
  bool clamped = false;
  for (std::size_t b = 0; b < kBands; ++b) {
    double r = static_cast<double>(rgb[b]);
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
    check_colour(emissive, out.name, "emissive colour", false);
    const float e[3] = {emissive.r, emissive.g, emissive.b};
    for (std::size_t b = 0; b < kBands; ++b) out.emission.band[b] = static_cast<double>(e[b]);
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

// A binary glTF (GLB, any extension: it starts with the magic word "glTF") is checked against its
// own framing before Assimp sees it: Assimp answers a bad chunk length with "No suitable reader
// found" after trying every reader (9 s for one such file), naming neither the chunk nor the cause.
// glTF 2.0 (version 2): a 12-byte header (magic, version, total length = the file's size), then
// chunks of (length, type, data), the first of type JSON; glTF 1.0 (version 1): a 20-byte header
// whose content (JSON) length and format 0 follow. Every length must lie within the file.
void check_glb_header(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  char magic[4] = {};
  if (!in.read(magic, 4) || std::string(magic, 4) != "glTF") return;
  const std::uint64_t size = std::filesystem::file_size(path);
  const auto bad = [&](const std::string& why) {
    throw SceneFileError(path + ": a binary glTF (GLB) file with " + why + " (docs/scenes.md, Meshes)");
  };
  const auto word = [&](const char* what) {
    std::uint32_t v = 0;
    if (!in.read(reinterpret_cast<char*>(&v), 4)) bad("no " + std::string(what) + ": the file ends at byte " + std::to_string(size));
    return v;  // little-endian in the file; the hosts we build for are little-endian too
  };
  const std::uint32_t version = word("version");
  if (version != 1 && version != 2) bad("version " + std::to_string(version) + " (1 and 2 exist)");
  const std::uint32_t length = word("total length");
  if (length != size) {
    bad("a header that gives its length as " + std::to_string(length) + " bytes where the file has " + std::to_string(size));
  }
  if (version == 1) {
    const std::uint32_t content = word("content length");
    if (word("content format") != 0) bad("a content format other than 0 (JSON)");
    if (std::uint64_t(content) > size - 20) {
      bad("a content length of " + std::to_string(content) + " bytes where " + std::to_string(size - 20) + " follow the header");
    }
    return;
  }
  std::uint64_t at = 12;
  for (int chunk = 0; at < size; ++chunk) {
    if (size - at < 8) bad(std::to_string(size - at) + " bytes after chunk " + std::to_string(chunk - 1) + ", too few for a chunk header");
    const std::uint32_t chunk_length = word("chunk length");
    const std::uint32_t type = word("chunk type");
    at += 8;
    if (std::uint64_t(chunk_length) > size - at) {
      bad("chunk " + std::to_string(chunk) + " giving its length as " + std::to_string(chunk_length) + " bytes where " +
          std::to_string(size - at) + " remain");
    }
    if (chunk == 0 && type != 0x4E4F534Au) bad("a first chunk that is not JSON");
    at += chunk_length;
    in.seekg(static_cast<std::streamoff>(at));
  }
  if (at == 12) bad("no chunks");
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

// In the child: the cap stays until it exits. A std::bad_alloc escapes to read_isolated.
const aiScene* read_capped(Assimp::Importer& importer, const std::string& path, std::vector<char>& buffer) {
  AddressSpaceCap cap(kImportHeadroom);
  return read_file(importer, path, buffer);
}

std::string memory_note() {
  return " (reading it needs more than " + std::to_string(kImportHeadroom >> 30) +
         " GiB of memory: a malformed or enormous file)";
}

// What Assimp made of a file, in the solver's terms: the meshes' materials (converted, with their
// warnings) and each mesh's triangles. The child process that ran Assimp sends it as bytes.
struct RawMesh {
  std::string error;  // Assimp's reason for refusing the file (nothing else is set then)
  std::vector<Material> materials;
  std::vector<std::int64_t> material_of;  // per Assimp material: index in `materials`, or -1 (unused)
  std::vector<std::string> warnings;
  struct Part {
    std::string origin;  // "<path>: mesh 2 'name'"
    std::int64_t material = -1;
    std::vector<Vec3> corners;  // three per triangle, in face order
  };
  std::vector<Part> parts;
  std::uint64_t skipped = 0;  // faces that are not triangles
};

RawMesh raw_mesh(const aiScene& scene, const MeshImportOptions& o, const std::string& path) {
  RawMesh raw;
  if (scene.mNumMeshes == 0) {
    raw.error = "the file holds no meshes";
    return raw;
  }
  raw.material_of.assign(scene.mNumMaterials, -1);
  for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
    const aiMesh& mesh = *scene.mMeshes[m];
    const unsigned mat = mesh.mMaterialIndex;
    if (mat < raw.material_of.size() && raw.material_of[mat] < 0) {
      raw.material_of[mat] = static_cast<std::int64_t>(raw.materials.size());
      raw.materials.push_back(material_from(*scene.mMaterials[mat], mat, o, raw.warnings, path));
    }
    RawMesh::Part part;
    part.origin = io::printable_utf8(path) + ": mesh " + std::to_string(m) +
                  (mesh.mName.length ? " '" + io::printable_utf8(mesh.mName.C_Str()) + "'" : "");
    part.material = mat < raw.material_of.size() ? raw.material_of[mat] : -1;
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices != 3) {
        ++raw.skipped;
        continue;
      }
      for (unsigned k = 0; k < 3; ++k) {
        const aiVector3D& v = mesh.mVertices[face.mIndices[k]];
        part.corners.push_back({v.x, v.y, v.z});
      }
    }
    raw.parts.push_back(std::move(part));
  }
  return raw;
}

class ByteWriter {
 public:
  template <typename T>
  void put(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    out_.append(reinterpret_cast<const char*>(&v), sizeof v);
  }
  void text(const std::string& s) {
    put(static_cast<std::uint64_t>(s.size()));
    out_ += s;
  }
  std::string take() { return std::move(out_); }

 private:
  std::string out_;
};

class ByteReader {
 public:
  explicit ByteReader(const std::string& in) : in_(in) {}
  template <typename T>
  T get() {
    T v{};
    need(sizeof v);
    std::memcpy(&v, in_.data() + at_, sizeof v);
    at_ += sizeof v;
    return v;
  }
  std::string text() {
    const auto n = get<std::uint64_t>();
    need(n);
    std::string s = in_.substr(at_, static_cast<std::size_t>(n));
    at_ += static_cast<std::size_t>(n);
    return s;
  }
  // A count of items of at least `item_bytes` each: more than the bytes left could hold is refused
  // before anything is allocated for them.
  std::uint64_t count(std::size_t item_bytes) {
    const auto n = get<std::uint64_t>();
    if (n > (in_.size() - at_) / item_bytes) throw std::length_error("the mesh reader's answer is malformed");
    return n;
  }
  bool done() const { return at_ == in_.size(); }

 private:
  void need(std::uint64_t n) const {
    if (n > in_.size() - at_) throw std::length_error("the mesh reader's answer is cut short");
  }
  const std::string& in_;
  std::size_t at_ = 0;
};

std::string encode(const RawMesh& m) {
  ByteWriter w;
  w.text(m.error);
  w.put(static_cast<std::uint64_t>(m.materials.size()));
  for (const Material& mat : m.materials) {
    w.text(mat.name);
    for (double x : mat.reflectance.band) w.put(x);
    for (double x : mat.emission.band) w.put(x);
  }
  w.put(static_cast<std::uint64_t>(m.material_of.size()));
  for (std::int64_t i : m.material_of) w.put(i);
  w.put(static_cast<std::uint64_t>(m.warnings.size()));
  for (const std::string& s : m.warnings) w.text(s);
  w.put(static_cast<std::uint64_t>(m.parts.size()));
  for (const RawMesh::Part& p : m.parts) {
    w.text(p.origin);
    w.put(p.material);
    w.put(static_cast<std::uint64_t>(p.corners.size()));
    for (const Vec3& v : p.corners) w.put(v);
  }
  w.put(m.skipped);
  return w.take();
}

RawMesh decode(const std::string& bytes) {
  ByteReader r(bytes);
  RawMesh m;
  m.error = r.text();
  for (std::uint64_t i = 0, n = r.count(8); i < n; ++i) {
    Material mat;
    mat.name = r.text();
    for (double& x : mat.reflectance.band) x = r.get<double>();
    for (double& x : mat.emission.band) x = r.get<double>();
    m.materials.push_back(std::move(mat));
  }
  for (std::uint64_t i = 0, n = r.count(8); i < n; ++i) m.material_of.push_back(r.get<std::int64_t>());
  for (std::uint64_t i = 0, n = r.count(8); i < n; ++i) m.warnings.push_back(r.text());
  for (std::uint64_t i = 0, n = r.count(8); i < n; ++i) {
    RawMesh::Part p;
    p.origin = r.text();
    p.material = r.get<std::int64_t>();
    const std::uint64_t corners = r.count(sizeof(Vec3));
    p.corners.reserve(static_cast<std::size_t>(corners));
    for (std::uint64_t k = 0; k < corners; ++k) p.corners.push_back(r.get<Vec3>());
    m.parts.push_back(std::move(p));
  }
  m.skipped = r.get<std::uint64_t>();
  if (!r.done()) throw std::length_error("the mesh reader's answer has bytes left over");
  return m;
}

// Assimp in a child process (io/child_process.h): whatever a malformed file does to it (an
// assertion, a wild read, a hang, an allocation of hundreds of gigabytes) ends the child, and the
// parent says so, naming the file. Fuzzing found each of those in Assimp 5.2 (fuzz/regressions/mesh).
RawMesh read_isolated(const std::string& path, const MeshImportOptions& o, std::uint64_t file_bytes) {
  const auto time_limit = o.reader_time_limit.value_or(std::chrono::seconds(60 + (file_bytes >> 20)));
  const io::ChildOutcome child = io::run_in_child(
      [&] {
        Assimp::Importer importer;
        // Points and lines are removed by the sort (they carry no area); node transforms are applied.
        importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
        std::vector<char> buffer;  // the file, when it is read from memory with a format hint
        RawMesh raw;
        try {
          const aiScene* scene = read_capped(importer, path, buffer);
          if (scene == nullptr) {
            raw.error = importer.GetErrorString();
            if (raw.error.find("bad_alloc") != std::string::npos) raw.error += memory_note();
          } else {
            raw = raw_mesh(*scene, o, path);
          }
        } catch (const std::bad_alloc&) {
          raw = RawMesh{};
          raw.error = std::string("reading it failed") + memory_note();
        } catch (const MaterialError& e) {
          raw = RawMesh{};
          raw.error = e.what();
        }
        return encode(raw);
      },
      time_limit);
  if (child.timed_out) {
    RawMesh raw;
    raw.error = "the mesh reader (Assimp) did not finish within " + std::to_string(time_limit.count()) +
                " s (a malformed file)";
    return raw;
  }
  if (!child.completed) {
    RawMesh raw;
    raw.error = "the mesh reader (Assimp) failed on it: " + child.how_it_ended() +
                " (a malformed file, or one that needs more than " + std::to_string(kImportHeadroom >> 30) +
                " GiB of memory)";
    return raw;
  }
  return decode(child.bytes);
}

// The scene from what Assimp read: our checks (SceneBuilder) and errors, in the parent.
LoadedScene build_scene(const std::string& path, const MeshImportOptions& o, const RawMesh& raw) {
  LoadedScene out;
  std::vector<std::string> warnings = raw.warnings;
  SceneBuilder builder(path);
  std::vector<int> material_index(raw.materials.size(), -1);
  for (std::size_t m = 0; m < raw.materials.size(); ++m) {
    try {
      material_index[m] = builder.add_material(raw.materials[m]);
    } catch (const std::invalid_argument& e) {
      throw SceneFileError(path + ": " + e.what());  // e.g. an emissive colour that is not finite
    }
  }
  for (const RawMesh::Part& part : raw.parts) {
    const int material = part.material >= 0 ? material_index[static_cast<std::size_t>(part.material)] : -1;
    for (std::size_t f = 0; f + 2 < part.corners.size(); f += 3) {
      const std::vector<Vec3> vertices(part.corners.begin() + static_cast<std::ptrdiff_t>(f),
                                       part.corners.begin() + static_cast<std::ptrdiff_t>(f + 3));
      try {
        builder.add_surface(part.origin + " face " + std::to_string(f / 3), material, vertices, part.origin);
      } catch (const std::invalid_argument& e) {
        throw SceneFileError(e.what());  // a coordinate that is not finite; starts with the file
      }
    }
  }
  if (raw.skipped > 0) warnings.push_back(path + ": " + std::to_string(raw.skipped) + " faces that are not triangles skipped");
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

bool is_obj_name(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".obj";
}

std::string read_mesh_text(const std::string& path) {
  try {
    return io::read_file(path, io::kSceneLimitBytes, "a mesh file");
  } catch (const io::InputFileError& e) {
    throw SceneFileError(e.what());
  }
}

}  // namespace

LoadedScene import_mesh_file(const std::string& path, const MeshImportOptions& o) {
  // Assimp opens the file itself and would read a device or a pipe without end.
  try {
    io::check_regular_file(path, io::kSceneLimitBytes, "a mesh file");
  } catch (const io::InputFileError& e) {
    throw SceneFileError(e.what());
  }
  if (!std::ifstream(path)) throw SceneFileError(path + ": cannot open");
  check_ply_header(path);
  check_glb_header(path);
  RawMesh raw = read_isolated(path, o, std::filesystem::file_size(path));
  if (!raw.error.empty()) throw SceneFileError(path + ": " + raw.error);
  if (is_obj_name(path)) {
    const std::vector<std::string> undefined = undefined_obj_materials(read_mesh_text(path), path);
    raw.warnings.insert(raw.warnings.end(), undefined.begin(), undefined.end());
  }
  return build_scene(path, o, raw);
}

}  // namespace rc
