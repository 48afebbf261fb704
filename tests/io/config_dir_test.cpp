// io/config_dir.h: RC2000SIM_CONFIGS first, then the share folder of the prefix the program runs from
// (tests/scripts/install_test.sh moves an installed rc2000sim and checks it), then the source tree's
// configs while they exist, then the configured installed share folder.
#include "io/config_dir.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include "io/input_file.h"

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

// This test binary is build/tests/test_io: not <prefix>/bin, so no prefix of its own, and the
// installed share folder is the configured prefix's.
TEST(ConfigDir, ABuildTreeProgramHasNoPrefixOfItsOwn) {
  EXPECT_EQ(share_dir_of_program(), "");
  const std::string share = installed_share_dir();
  EXPECT_EQ(share.substr(share.size() - std::string("/share/rc2000tlm").size()), "/share/rc2000tlm");
  if (std::getenv("RC2000SIM_CONFIGS") == nullptr) {
    EXPECT_EQ(config_dir(), std::string(RC_SOURCE_DIR) + "/configs");
  }
}

TEST(ConfigDir, UseConfigDirTakesAFolderAndSetsTheVariable) {
  ::unsetenv(kConfigDirVariable);
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("rc_configs_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string file = (dir / "a.json").string();
  std::ofstream(file) << "{}";
  for (const std::string& bad : {file, (dir / "missing").string(), std::string()}) {
    try {
      use_config_dir(bad);
      ADD_FAILURE() << "accepted " << bad;
    } catch (const InputFileError& e) {
      EXPECT_NE(std::string(e.what()).find("not a folder"), std::string::npos) << e.what();
      if (!bad.empty()) {
        EXPECT_EQ(std::string(e.what()).rfind(bad, 0), 0u) << e.what();
      }
    }
    EXPECT_EQ(std::getenv(kConfigDirVariable), nullptr) << "a refused folder must not be used";
  }
  use_config_dir(dir.string());
  EXPECT_EQ(config_dir(), dir.string());
  ::unsetenv(kConfigDirVariable);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace rc::io
