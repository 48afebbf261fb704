// check_camera (scenes/camera.h): the one check of a camera, in scene files and after
// normalisation. A degenerate camera used to give an all-black picture and exit 0.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "scenes/camera.h"
#include "scenes/normalise.h"
#include "scenes/scene_file.h"

namespace rc {
namespace {

std::string problem(const Camera& c) {
  try {
    check_camera(c);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

Camera camera(Vec3 position, Vec3 look_at, Vec3 up, double fov = 45) { return {position, look_at, up, fov}; }

TEST(CameraCheck, TheDefaultAndOrdinaryCamerasPass) {
  EXPECT_EQ(problem(Camera{}), "");
  EXPECT_EQ(problem(camera({1, 1, -3}, {1, 1, 0}, {0, 1, 0})), "");
  EXPECT_EQ(problem(camera({1, 1, -3}, {1, 1, 0}, {0, 5, 1})), "");  // up need not be perpendicular
  EXPECT_EQ(problem(camera({0, 0, 0}, {0, 0, 1}, {0, 1, 0}, 179.9)), "");
}

TEST(CameraCheck, IsTheSameAtEveryScale) {
  for (double k : {1e-300, 1e-150, 1e150, 1e300}) {
    EXPECT_EQ(problem(camera(Vec3(1, 1, -3) * k, Vec3(1, 1, 0) * k, Vec3(0, 1, 0) * k)), "") << k;
    EXPECT_NE(problem(camera(Vec3(1, 1, -3) * k, Vec3(1, 1, 0) * k, Vec3(0, 0, 1) * k)), "") << k;
  }
}

TEST(CameraCheck, DegenerateCamerasAreNamed) {
  EXPECT_EQ(problem(camera({1, 1, -3}, {1, 1, 0}, {0, 0, 0})), "camera up vector is zero");
  EXPECT_EQ(problem(camera({1, 1, -3}, {1, 1, 0}, {0, 0, 1})),
            "camera up vector (0, 0, 1) is parallel to the view direction (0, 0, 3) (the picture would have no up); "
            "choose an up vector across the view");
  EXPECT_NE(problem(camera({1, 1, -3}, {1, 1, 0}, {0, 0, -2})).find("is parallel to the view direction"), std::string::npos);
  EXPECT_NE(problem(camera({1, 1, -3}, {1, 1, 0}, {0, 1e-7, 1})).find("is parallel"), std::string::npos);
  EXPECT_EQ(problem(camera({1, 1, -3}, {1, 1, 0}, {0, 1e-5, 1})), "");  // sine 1e-5 > kMinCameraUpSine
  EXPECT_EQ(problem(camera({1, 2, 3}, {1, 2, 3}, {0, 1, 0})), "camera looks at its own position (1, 2, 3) (no view direction)");
  EXPECT_EQ(problem(camera({1, 1, -3}, {1, 1, 0}, {0, 1, 0}, 0)),
            "camera vertical field of view 0 degrees is outside [0.001, 180) (kMinFieldOfViewDeg: narrower views leave "
            "the projection's range)");
  EXPECT_NE(problem(camera({1, 1, -3}, {1, 1, 0}, {0, 1, 0}, 180)).find("is outside [0.001, 180)"), std::string::npos);
  EXPECT_NE(problem(camera({1, 1, -3}, {1, 1, 0}, {0, 1, 0}, NAN)).find("is outside [0.001, 180)"), std::string::npos);
  EXPECT_EQ(problem(camera({1, NAN, -3}, {1, 1, 0}, {0, 1, 0})), "camera position (1, nan, -3) is not finite");
  EXPECT_EQ(problem(camera({1, 1, -3}, {1, 1, INFINITY}, {0, 1, 0})), "camera look-at point (1, 1, inf) is not finite");
  EXPECT_EQ(problem(camera({1, 1, -3}, {1, 1, 0}, {0, -INFINITY, 0})), "camera up vector (0, -inf, 0) is not finite");
}

// A field of view of 1e-300 degrees overflowed the projection and gave an all-black picture with
// exit 0 (issue 27): below kMinFieldOfViewDeg is refused, in a scene file with its file and line;
// at the limit the camera passes.
TEST(CameraCheck, FieldsOfViewNarrowerThanTheLimitAreRefused) {
  for (double fov : {1e-300, 1e-10, 9.99e-4}) {
    EXPECT_NE(problem(camera({1, 1, -3}, {1, 1, 0}, {0, 1, 0}, fov)).find("degrees is outside [0.001, 180)"),
              std::string::npos)
        << fov;
  }
  EXPECT_EQ(problem(camera({1, 1, -3}, {1, 1, 0}, {0, 1, 0}, kMinFieldOfViewDeg)), "");
  try {
    parse_scene_text("material w reflectance 0.5 0.5 0.5 emission 1 1 1\ntri a w 0 0 0 1 0 0 0 1 0\n"
                     "camera 1 1 -3  1 1 0  0 1 0  1e-300\n",
                     "narrow.scene");
    ADD_FAILURE() << "a field of view of 1e-300 degrees was accepted";
  } catch (const SceneFileError& e) {
    EXPECT_EQ(std::string(e.what()),
              "narrow.scene:3: camera vertical field of view 1e-300 degrees is outside [0.001, 180) "
              "(kMinFieldOfViewDeg: narrower views leave the projection's range)");
  }
}

TEST(CameraCheck, SceneFilesNameTheFileAndLine) {
  const std::string scene = "material w reflectance 0.5 0.5 0.5 emission 1 1 1\ntri a w 0 0 0 1 0 0 0 1 0\n";
  auto error_of = [&](const std::string& camera_line) {
    try {
      parse_scene_text(scene + camera_line, "cam.scene");
    } catch (const SceneFileError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(error_of("camera 1 1 -3  1 1 0  0 0 0  45\n"), "cam.scene:3: camera up vector is zero");
  EXPECT_NE(error_of("camera 1 1 -3  1 1 0  0 0 1  45\n").find("cam.scene:3: camera up vector (0, 0, 1) is parallel"),
            std::string::npos);
  EXPECT_NE(error_of("camera 1 1 -3  1 1 0  0 1 0  0\n")
                .find("cam.scene:3: camera vertical field of view 0 degrees is outside [0.001, 180)"),
            std::string::npos);
  EXPECT_EQ(error_of("camera 1 1 -3  1 1 0  0 1 0  45\n"), "");
}

// The eye and the point looked at differ in the file, but by less than normalisation resolves:
// once normalised they are one point, and normalise() says so instead of rendering nothing.
TEST(CameraCheck, NormaliseChecksTheCameraItMoves) {
  const LoadedScene s = parse_scene_text("material w reflectance 0.5 0.5 0.5 emission 1 1 1\n"
                                         "tri a w 0.3 0 0.3  1 0 0.3  0.3 1 0.3\n"
                                         "tri b w 0.3 0 1  1 0 1  0.3 1 1\n"
                                         "camera 0.5 0.5 1e-20  0.5 0.5 0  0 1 0  45\n",
                                         "near.scene");
  Scene scene = s.scene;
  try {
    normalise(scene);
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("scene 'near.scene', once normalised: camera looks at its own position"),
              std::string::npos)
        << e.what();
  }
}

// frame_bounds sees every corner of the box inside its field of view, whatever the box's size and place.
TEST(CameraFrame, EveryCornerOfTheBoxIsInView) {
  const Vec3 boxes[][2] = {{Vec3(0, 0, 0), Vec3(1, 1, 1)}, {Vec3(-5e3, 2, 7), Vec3(5e3, 3, 9)}, {Vec3(1e-9, 0, 0), Vec3(2e-9, 1e-9, 3e-9)}};
  for (const auto& b : boxes) {
    const Camera c = frame_bounds(b[0], b[1]);
    check_camera(c);
    const Vec3 view = glm::normalize(c.look_at - c.position);
    const double half = 0.5 * c.vertical_fov_deg * 3.14159265358979323846 / 180.0;
    for (int k = 0; k < 8; ++k) {
      const Vec3 corner((k & 1) ? b[1].x : b[0].x, (k & 2) ? b[1].y : b[0].y, (k & 4) ? b[1].z : b[0].z);
      const Vec3 to = corner - c.position;
      const double angle = std::acos(std::min(1.0, glm::dot(glm::normalize(to), view)));
      EXPECT_LE(angle, half * (1 + 1e-9)) << "corner " << k;
      EXPECT_GT(glm::dot(to, view), 0) << "corner " << k << " behind the camera";
    }
  }
  EXPECT_THROW(frame_bounds(Vec3(0), Vec3(0)), std::invalid_argument);
}

}  // namespace
}  // namespace rc
