// io/config_dir.h: RC2000SIM_CONFIGS first, then the source tree's configs while they exist, then the
// installed share folder.
#include "io/config_dir.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace rc::io {
namespace {

namespace fs = std::filesystem;

TEST(ConfigDir, TheEnvironmentVariableWinsWhenSetAndNotEmpty) {
  const std::string here = fs::temp_directory_path().string();
  EXPECT_EQ(choose_config_dir("/somewhere/else", here, "/installed"), "/somewhere/else");
  EXPECT_EQ(choose_config_dir("", here, "/installed"), here);
  EXPECT_EQ(choose_config_dir(nullptr, here, "/installed"), here);
}

TEST(ConfigDir, AnInstalledLibraryFallsBackToItsShareFolderWhenTheSourceTreeIsGone) {
  EXPECT_EQ(choose_config_dir(nullptr, "/no/such/source/tree/configs", "/prefix/share/rc2000tlm/configs"),
            "/prefix/share/rc2000tlm/configs");
  // A file where the source folder was is not a folder of configs either.
  const fs::path file = fs::temp_directory_path() / "rc-config-dir-test-file";
  { std::ofstream(file.string()) << "x"; }
  EXPECT_EQ(choose_config_dir(nullptr, file.string(), "/installed"), "/installed");
  fs::remove(file);
}

TEST(ConfigDir, ThisBuildFindsItsSourceTreeConfigs) {
  // RC_SOURCE_DIR: this tree (tests/CMakeLists.txt); ctest does not set RC2000SIM_CONFIGS.
  if (std::getenv("RC2000SIM_CONFIGS") != nullptr) GTEST_SKIP() << "RC2000SIM_CONFIGS is set";
  EXPECT_EQ(config_dir(), std::string(RC_SOURCE_DIR) + "/configs");
}

}  // namespace
}  // namespace rc::io
