// Scenes as text, transformed the way a user could write them (tests/host_sw/visibility/invariance_test.cpp):
// the surfaces of a scene file (docs/scenes.md, "Scene file format") or of a loaded scene, moved by an
// affine map (rotation, translation, uniform scale, mirror: a mirror also reverses each surface's
// vertex order, so that fronts stay fronts), reordered, and two-sided surfaces declared with
// 'two-sided' or written as their two surfaces by hand (the back as v0 v3 v2 v1 or v0 v2 v1, as the
// scene builder writes it). Coordinates are printed with 17 significant digits: they read back exactly.
#pragma once

#include <algorithm>
#include <cstdio>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scenes/scene.h"

namespace rc::test {

// x -> linear x + offset. linear = s R with R orthogonal; det < 0 mirrors.
struct Affine {
  glm::dmat3 linear{1.0};
  Vec3 offset{0.0};

  Vec3 apply(const Vec3& p) const { return linear * p + offset; }
  bool mirrors() const { return glm::determinant(linear) < 0; }
  // The image of a surface's unit normal when a mirror also reverses its winding (transformed()):
  // (M u) x (M v) = det(M) M^-T (u x v), and the reversal cancels the sign of a negative det(M).
  Vec3 normal(const Vec3& n) const { return glm::normalize(glm::transpose(glm::inverse(linear)) * n); }
  // This map after `first`.
  Affine after(const Affine& first) const { return {linear * first.linear, linear * first.offset + offset}; }
};

// Rotation by `degrees` about `axis` (Rodrigues), in double precision.
inline Affine rotation(Vec3 axis, double degrees) {
  axis = glm::normalize(axis);
  const double a = degrees * M_PI / 180, c = std::cos(a), s = std::sin(a);
  glm::dmat3 m(1.0);
  for (int col = 0; col < 3; ++col) {
    for (int row = 0; row < 3; ++row) {
      const double k = row == col ? c : 0.0;
      const double cross = (row == 0 && col == 1) ? -axis.z : (row == 0 && col == 2) ? axis.y
                         : (row == 1 && col == 0) ? axis.z : (row == 1 && col == 2) ? -axis.x
                         : (row == 2 && col == 0) ? -axis.y : (row == 2 && col == 1) ? axis.x : 0.0;
      m[col][row] = k + (1 - c) * axis[row] * axis[col] + s * cross;
    }
  }
  return {m, Vec3(0.0)};
}

inline Affine translation(const Vec3& t) { return {glm::dmat3(1.0), t}; }
inline Affine scaling(double s) { return {glm::dmat3(s), Vec3(0.0)}; }
// Reflection in the plane through the origin with normal `n`: I - 2 n n^T.
inline Affine mirror(Vec3 n) {
  n = glm::normalize(n);
  glm::dmat3 m(1.0);
  for (int col = 0; col < 3; ++col) {
    for (int row = 0; row < 3; ++row) m[col][row] -= 2 * n[row] * n[col];
  }
  return {m, Vec3(0.0)};
}

struct TextSurface {
  std::string shape;  // "quad" or "tri"
  std::string name, material;
  std::vector<Vec3> vertices;
  bool two_sided = false;
};

struct SceneText {
  std::vector<std::string> materials;  // material lines, verbatim
  std::vector<TextSurface> surfaces;
  bool has_camera = false;
  Camera camera;

  // Parses the surfaces, materials and camera of a scene file (no error handling beyond a throw:
  // the inputs are the project's own example scenes).
  static SceneText parse(const std::string& text) {
    SceneText out;
    std::istringstream lines(text);
    std::string line;
    while (std::getline(lines, line)) {
      line = line.substr(0, line.find('#'));
      std::istringstream words(line);
      std::string keyword;
      if (!(words >> keyword)) continue;
      if (keyword == "material") {
        out.materials.push_back(line);
        continue;
      }
      if (keyword == "camera") {
        Camera& c = out.camera;
        words >> c.position.x >> c.position.y >> c.position.z >> c.look_at.x >> c.look_at.y >> c.look_at.z >> c.up.x >>
            c.up.y >> c.up.z >> c.vertical_fov_deg;
        out.has_camera = true;
        continue;
      }
      TextSurface s;
      if (keyword == "two-sided") {
        s.two_sided = true;
        words >> keyword;
      }
      if (keyword != "quad" && keyword != "tri") throw std::invalid_argument("scene_text: unknown line: " + line);
      s.shape = keyword;
      words >> s.name >> s.material;
      s.vertices.resize(keyword == "quad" ? 4 : 3);
      for (Vec3& v : s.vertices) words >> v.x >> v.y >> v.z;
      if (!words) throw std::invalid_argument("scene_text: short line: " + line);
      out.surfaces.push_back(s);
    }
    return out;
  }

  // Every face of a loaded (not yet normalised) scene as a 'tri', every material by its values.
  static SceneText of(const Scene& scene) {
    SceneText out;
    for (std::size_t m = 0; m < scene.materials.size(); ++m) {
      const Material& mat = scene.materials[m];
      out.materials.push_back("material m" + std::to_string(m) + " reflectance " + numbers(mat.reflectance.band) +
                              " emission " + numbers(mat.emission.band));
    }
    for (std::size_t f = 0; f < scene.faces.size(); ++f) {
      const Face& face = scene.faces[f];
      out.surfaces.push_back({"tri", "f" + std::to_string(f), "m" + std::to_string(face.material),
                              {face.tri.v0, face.tri.v1, face.tri.v2}, false});
    }
    out.has_camera = true;
    out.camera = scene.camera;
    return out;
  }

  std::string text() const {
    std::string out;
    for (const std::string& m : materials) out += m + "\n";
    for (const TextSurface& s : surfaces) {
      out += (s.two_sided ? "two-sided " : "") + s.shape + " " + s.name + " " + s.material;
      for (const Vec3& v : s.vertices) out += " " + numbers(std::vector<double>{v.x, v.y, v.z});
      out += "\n";
    }
    if (has_camera) {
      const Camera& c = camera;
      out += "camera " + numbers(std::vector<double>{c.position.x, c.position.y, c.position.z, c.look_at.x, c.look_at.y,
                                                     c.look_at.z, c.up.x, c.up.y, c.up.z, c.vertical_fov_deg}) + "\n";
    }
    return out;
  }

  // Every vertex through `t`; a mirror also reverses each surface's vertex order after v0 (the same
  // split diagonal v0-v2, fronts still fronts). The camera moves with the scene.
  SceneText transformed(const Affine& t) const {
    SceneText out = *this;
    for (TextSurface& s : out.surfaces) {
      for (Vec3& v : s.vertices) v = t.apply(v);
      if (t.mirrors()) std::reverse(s.vertices.begin() + 1, s.vertices.end());
    }
    out.camera.position = t.apply(camera.position);
    out.camera.look_at = t.apply(camera.look_at);
    out.camera.up = t.linear * camera.up;
    return out;
  }

  // The surfaces in a shuffled order (fixed seed).
  SceneText reordered(unsigned seed) const {
    SceneText out = *this;
    std::mt19937 random(seed);
    std::shuffle(out.surfaces.begin(), out.surfaces.end(), random);
    return out;
  }

  // Each 'two-sided' surface written as the surface and its back (v0 then the rest reversed).
  SceneText two_sided_by_hand() const {
    SceneText out = *this;
    out.surfaces.clear();
    for (const TextSurface& s : surfaces) {
      if (!s.two_sided) {
        out.surfaces.push_back(s);
        continue;
      }
      TextSurface front = s, back = s;
      front.two_sided = back.two_sided = false;
      back.name = s.name + "_back";
      std::reverse(back.vertices.begin() + 1, back.vertices.end());
      out.surfaces.push_back(front);
      out.surfaces.push_back(back);
    }
    return out;
  }

  // The reverse: a surface followed by its back written by hand (same shape and material, v0 then the
  // rest reversed) becomes one 'two-sided' surface.
  SceneText two_sided_declared() const {
    SceneText out = *this;
    out.surfaces.clear();
    for (std::size_t i = 0; i < surfaces.size(); ++i) {
      const TextSurface& s = surfaces[i];
      if (i + 1 < surfaces.size() && is_back_of(surfaces[i + 1], s)) {
        TextSurface both = s;
        both.two_sided = true;
        out.surfaces.push_back(both);
        ++i;
        continue;
      }
      out.surfaces.push_back(s);
    }
    return out;
  }

  std::size_t two_sided_count() const {
    return static_cast<std::size_t>(std::count_if(surfaces.begin(), surfaces.end(), [](const TextSurface& s) { return s.two_sided; }));
  }

 private:
  static bool is_back_of(const TextSurface& back, const TextSurface& front) {
    if (back.shape != front.shape || back.material != front.material || back.two_sided || front.two_sided) return false;
    std::vector<Vec3> expected = front.vertices;
    std::reverse(expected.begin() + 1, expected.end());
    return back.vertices == expected;
  }

  template <class Values>
  static std::string numbers(const Values& values) {
    std::string out;
    char buffer[40];
    for (double v : values) {
      std::snprintf(buffer, sizeof buffer, "%.17g", v);
      out += (out.empty() ? "" : " ") + std::string(buffer);
    }
    return out;
  }
};

}  // namespace rc::test
