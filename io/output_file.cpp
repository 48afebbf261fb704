#include "io/output_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <sys/stat.h>
#include <unistd.h>

namespace rc::io {

namespace {

std::string reason() { return std::strerror(errno); }

}  // namespace

void write_file_atomically(const std::string& path, std::string_view bytes) {
  // A rename would replace a device (/dev/null, /dev/full) or a folder with a regular file.
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode))
    throw OutputFileError(path + ": exists and is not a regular file; not replaced");
  // The pid keeps two processes writing the same output (shards, parallel runs) off each other's
  // temporary file.
  const std::string temporary = path + ".partial-" + std::to_string(::getpid());
  std::FILE* file = std::fopen(temporary.c_str(), "wb");
  if (file == nullptr) throw OutputFileError(path + ": cannot open for writing (" + reason() + ")");
  const bool written = std::fwrite(bytes.data(), 1, bytes.size(), file) == bytes.size();
  const std::string write_reason = written ? "" : reason();
  const bool closed = std::fclose(file) == 0;
  if (!written || !closed) {
    const std::string why = written ? reason() : write_reason;
    std::remove(temporary.c_str());
    throw OutputFileError(path + ": write failed (" + why + ")");
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    const std::string why = reason();
    std::remove(temporary.c_str());
    throw OutputFileError(path + ": cannot rename " + temporary + " over it (" + why + ")");
  }
}

}  // namespace rc::io
