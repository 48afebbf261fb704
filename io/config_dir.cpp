#include "io/config_dir.h"

#include <cstdlib>
#include <filesystem>
#include <system_error>

namespace rc::io {

std::string choose_config_dir(const char* env, const std::string& source_dir, const std::string& installed_dir) {
  if (env != nullptr && *env != '\0') return env;
  std::error_code unreadable;
  if (std::filesystem::is_directory(source_dir, unreadable)) return source_dir;
  return installed_dir;
}

std::string config_dir() {
  return choose_config_dir(std::getenv("RC2000SIM_CONFIGS"), RC_SOURCE_CONFIG_DIR, RC_INSTALLED_CONFIG_DIR);
}

}  // namespace rc::io
