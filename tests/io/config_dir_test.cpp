// io/config_dir.h: the config folder is RC2000SIM_CONFIGS when set and not empty, else the build's;
// --configs (use_config_dir) accepts only a folder and sets the variable for child processes.
#include "io/config_dir.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <unistd.h>

#include "io/input_file.h"

namespace rc::io {
namespace {

TEST(ConfigDir, TheEnvironmentWinsOverTheBuildsFolderUnlessEmpty) {
  ::unsetenv(kConfigDirVariable);
  EXPECT_EQ(config_dir("/build/configs"), "/build/configs");
  ::setenv(kConfigDirVariable, "", 1);
  EXPECT_EQ(config_dir("/build/configs"), "/build/configs");
  ::setenv(kConfigDirVariable, "/elsewhere/configs", 1);
  EXPECT_EQ(config_dir("/build/configs"), "/elsewhere/configs");
  ::unsetenv(kConfigDirVariable);
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
  EXPECT_EQ(config_dir("/build/configs"), dir.string());
  ::unsetenv(kConfigDirVariable);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace rc::io
