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

std::string share_dir_of_program() {
  std::error_code unreadable;
  const std::filesystem::path program = std::filesystem::read_symlink("/proc/self/exe", unreadable);
  if (unreadable || program.parent_path().filename() != "bin") return "";
  const std::filesystem::path share = program.parent_path().parent_path() / "share" / "rc2000tlm";
  return std::filesystem::is_directory(share, unreadable) ? share.string() : "";
}

std::string installed_share_dir() {
  const std::string beside = share_dir_of_program();
  return beside.empty() ? std::string(RC_INSTALLED_SHARE_DIR) : beside;
}

std::string config_dir() {
  const char* env = std::getenv(kConfigDirVariable);
  const std::string beside = share_dir_of_program();
  if ((env == nullptr || *env == '\0') && !beside.empty()) return beside + "/configs";
  return choose_config_dir(env, RC_SOURCE_CONFIG_DIR, std::string(RC_INSTALLED_SHARE_DIR) + "/configs");
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
