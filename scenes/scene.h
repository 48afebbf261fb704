// A radiosity scene: materials, faces (triangles, what the hardware tests segments against) and
// patches (sub-triangles of faces, what radiosity solves for). Faces and patches are kept separate
// because the paper varies them independently (Table 2: 70 faces with 280, 1120 or 4480 patches).
#pragma once

#include <string>
#include <vector>

#include "scenes/camera.h"
#include "scenes/geometry.h"
#include "scenes/sheets.h"
#include "scenes/spectrum.h"

namespace rc {

struct Material {
  std::string name;
  Spectrum reflectance;  // diffuse albedo per band, in [0, 1)
  Spectrum emission;     // emitted radiosity per band (energy per unit area)

  bool emits() const {
    for (double e : emission.band) {
      if (e > 0) return true;
    }
    return false;
  }
};

struct Face {
  Triangle tri;
  int material = 0;
  int surface = 0;  // index of the source surface (quad/triangle of the scene file) it came from
};

struct Patch {
  Triangle tri;
  int face = 0;  // face the patch lies on (its segments exclude that face, see visibility.h)
  Vec3 centre;
  Vec3 normal;
  double area = 0;
};

// Uniform scale and offset that map the scene into [0, 1)^3 (paper sec 3.3).
struct Normalisation {
  Vec3 offset{0.0};
  double scale = 1.0;
  Vec3 apply(const Vec3& p) const { return (p - offset) * scale; }
};

struct Scene {
  std::string name;
  std::vector<std::string> surface_names;
  std::vector<Material> materials;
  std::vector<Face> faces;
  std::vector<Patch> patches;
  Camera camera;
  // Whether the scene's source chose the camera (a scene file's `camera` line, the Cornell Box's, a
  // composition's `camera` key or its room's). prepare_scene frames the scene's bounds otherwise
  // (frame_bounds, scenes/camera.h): the Cornell camera looks at nothing in a scene of other units.
  bool camera_given = false;
  Normalisation normalisation;  // identity until normalise() runs
  // Faces back to back that form one two-sided surface (scenes/sheets.h); set by find_sheets after
  // normalisation. Default: every face its own sheet.
  FaceSheets sheets;

  const Material& material_of(const Patch& p) const { return materials[faces[p.face].material]; }
  std::vector<Triangle> face_triangles() const;
  // The name of surface `surface`, or "" when the scene has none for it (scenes made by hand in tests).
  std::string surface_name(int surface) const;
  bool emits_light() const;  // some face's material emits
};

}  // namespace rc
