#include "io/input_file.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sys/stat.h>

namespace rc::io {

namespace {

std::string too_large(const std::string& path, std::uint64_t limit_bytes, const std::string& what) {
  return path + ": larger than the " + std::to_string(limit_bytes) + "-byte limit for " + what;
}

// stat() the path; a directory or a missing file is named here, before any read.
struct stat stat_or_throw(const std::string& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0)
    throw InputFileError(path + ": cannot open (" + std::strerror(errno) + ")");
  if (S_ISDIR(st.st_mode)) throw InputFileError(path + ": is a directory, not a file");
  return st;
}

}  // namespace

std::string read_file(const std::string& path, std::uint64_t limit_bytes, const std::string& what) {
  const struct stat st = stat_or_throw(path);
  if (S_ISREG(st.st_mode) && static_cast<std::uint64_t>(st.st_size) > limit_bytes)
    throw InputFileError(too_large(path, limit_bytes, what));
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputFileError(path + ": cannot open (" + std::strerror(errno) + ")");
  // A device or pipe has no size: read in chunks and stop one byte past the limit.
  std::string text;
  char chunk[1 << 16];
  while (in) {
    in.read(chunk, sizeof chunk);
    text.append(chunk, static_cast<std::size_t>(in.gcount()));
    if (text.size() > limit_bytes) throw InputFileError(too_large(path, limit_bytes, what));
  }
  if (in.bad()) throw InputFileError(path + ": read failed");
  return text;
}

void check_regular_file(const std::string& path, std::uint64_t limit_bytes, const std::string& what) {
  const struct stat st = stat_or_throw(path);
  if (!S_ISREG(st.st_mode)) throw InputFileError(path + ": not a regular file (" + what + " must be one)");
  if (static_cast<std::uint64_t>(st.st_size) > limit_bytes) throw InputFileError(too_large(path, limit_bytes, what));
}

}  // namespace rc::io
