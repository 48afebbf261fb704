#include "io/config_dir.h"

#include <cstdlib>
#include <filesystem>
#include <system_error>

#include <sys/stat.h>

#include "io/input_file.h"

namespace rc::io {

std::string choose_config_dir(const char* env, const std::string& source_dir, const std::string& installed_dir) {
  if (env != nullptr && *env != '\0') return env;
  std::error_code unreadable;
  if (std::filesystem::is_directory(source_dir, unreadable)) return source_dir;
  return installed_dir;
}

std::string config_dir() {
  return choose_config_dir(std::getenv(kConfigDirVariable), RC_SOURCE_CONFIG_DIR, RC_INSTALLED_CONFIG_DIR);
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
