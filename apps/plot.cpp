#include "apps/plot.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>

namespace rc {

bool plot(const std::string& script, const std::string& csv_path, const std::string& png_path) {
  const std::string path = std::string(RC_SOURCE_DIR) + "/apps/plots/" + script;
  if (!std::filesystem::exists(path)) {
    std::fprintf(stderr, "warning: %s not found; %s not drawn\n", path.c_str(), png_path.c_str());
    return false;
  }
  // Debian's interpreter, which has python3-matplotlib, even when another python3 is first on PATH.
  const std::string python = std::filesystem::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
  const std::string command = python + " '" + path + "' '" + csv_path + "' '" + png_path + "'";
  if (std::system(command.c_str()) != 0) {
    std::fprintf(stderr, "warning: plotting failed (%s); the CSV is complete\n", command.c_str());
    return false;
  }
  return true;
}

}  // namespace rc
