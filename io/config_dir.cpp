#include "io/config_dir.h"

#include <cstdlib>
#include <sys/stat.h>

#include "io/input_file.h"

namespace rc::io {

std::string config_dir(const std::string& compiled_in) {
  const char* dir = std::getenv(kConfigDirVariable);
  return dir != nullptr && *dir != '\0' ? std::string(dir) : compiled_in;
}

void use_config_dir(const std::string& dir) {
  struct stat st {};
  if (dir.empty() || ::stat(dir.c_str(), &st) != 0 || !S_ISDIR(st.st_mode)) {
    throw InputFileError((dir.empty() ? std::string("''") : dir) + ": not a folder (the config folder must hold devices/, hosts/, "
                         "pipeline_resources.json, ...)");
  }
  ::setenv(kConfigDirVariable, dir.c_str(), 1);
}

}  // namespace rc::io
