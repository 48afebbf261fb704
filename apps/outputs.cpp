#include "apps/outputs.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <new>
#include <system_error>
#include <unistd.h>

#include "io/output_file.h"

namespace rc {

namespace fs = std::filesystem;

namespace {

std::string pid_text() { return std::to_string(::getpid()); }

// The nearest folder on the way to `path` that exists (".", for a bare file name), or the first thing
// on the way that exists and is not a folder.
fs::path nearest_existing(const std::string& path) {
  fs::path at = fs::path(path).parent_path();
  std::error_code error;
  while (!at.empty() && !fs::exists(at, error)) at = at.parent_path();
  return at.empty() ? fs::path(".") : at;
}

void refuse_non_file(const std::string& path) {
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  if (fs::exists(status) && !fs::is_regular_file(status))
    throw io::OutputFileError(path + ": exists and is not a regular file; not replaced");
}

// rename() when both are on one file system, else a copy beside the target renamed over it.
void move_file(const std::string& from, const std::string& to) {
  refuse_non_file(to);
  if (std::rename(from.c_str(), to.c_str()) == 0) return;
  if (errno != EXDEV) throw io::OutputFileError(to + ": cannot move " + from + " there (" + std::strerror(errno) + ")");
  const std::string partial = to + ".partial-" + pid_text();
  std::error_code error;
  fs::copy_file(from, partial, fs::copy_options::overwrite_existing, error);
  if (!error) fs::rename(partial, to, error);
  if (error) {
    fs::remove(partial);
    throw io::OutputFileError(to + ": cannot copy " + from + " there (" + error.message() + ")");
  }
  fs::remove(from);
}

}  // namespace

void Outputs::expect(const std::string& path) {
  const std::string normal = fs::absolute(path).lexically_normal().string();
  if (std::find(expected_.begin(), expected_.end(), normal) != expected_.end())
    throw io::OutputFileError(path + ": named twice among this command's outputs; each needs a path of its own");
  expected_.push_back(normal);
  refuse_non_file(path);
  const fs::path folder = nearest_existing(path);
  std::error_code error;
  if (!fs::is_directory(folder, error))
    throw io::OutputFileError(path + ": cannot be written: " + folder.string() + " is not a folder");
  // Permissions alone do not tell (root, read-only mounts, /proc): try.
  const std::string probe = (folder / (".rc2000sim-probe-" + pid_text())).string();
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0600);
  if (fd < 0) {
    throw io::OutputFileError(path + ": cannot be written: no new file can be made in " + folder.string() + " (" +
                              std::strerror(errno) + ")");
  }
  ::close(fd);
  ::unlink(probe.c_str());
}

void Outputs::add(const std::string& path, std::string bytes) { files_.push_back({path, std::move(bytes), {}, {}}); }

void Outputs::add_made(const std::string& path, const std::function<std::string()>& make) {
  try {
    files_.push_back({path, make(), {}, {}});
  } catch (const std::exception& e) {
    files_.push_back({path, {}, {}, e.what()});
  }
}

void Outputs::move_in(const std::string& path, const std::string& temporary) { files_.push_back({path, {}, temporary, {}}); }

std::vector<std::string> Outputs::paths() const {
  std::vector<std::string> paths;
  for (const File& f : files_) paths.push_back(f.path);
  return paths;
}

void Outputs::write() {
  std::vector<std::string> written, not_made;
  std::string first_failure;
  for (std::size_t i = 0; i < files_.size(); ++i) {
    const File& f = files_[i];
    if (!f.failure.empty()) {
      if (first_failure.empty()) first_failure = f.path + " could not be made: " + f.failure;
      not_made.push_back(f.path);
      continue;
    }
    try {
      const fs::path folder = fs::path(f.path).parent_path();
      std::error_code error;
      if (!folder.empty() && !fs::is_directory(folder, error)) {
        fs::create_directories(folder, error);
        if (error) throw io::OutputFileError(f.path + ": cannot create the folder " + folder.string() + " (" + error.message() + ")");
      }
      if (f.temporary.empty()) {
        io::write_file_atomically(f.path, f.bytes);
      } else {
        move_file(f.temporary, f.path);
      }
    } catch (const std::exception& e) {
      std::vector<std::string> rest = not_made;
      for (std::size_t j = i; j < files_.size(); ++j) rest.push_back(files_[j].path);
      throw OutputsNotWritten(e.what(), written, rest);
    }
    written.push_back(f.path);
  }
  if (!not_made.empty()) throw OutputsNotWritten(first_failure, written, not_made);
}

TemporaryFile::TemporaryFile(const std::string& suffix) {
  std::error_code error;
  fs::path folder = fs::temp_directory_path(error);
  if (error) folder = "/tmp";
  std::string name = (folder / ("rc2000sim-" + pid_text() + "-XXXXXX" + suffix)).string();
  const int fd = ::mkstemps(name.data(), static_cast<int>(suffix.size()));
  if (fd < 0) throw io::OutputFileError(name + ": cannot make a temporary file (" + std::strerror(errno) + ")");
  ::close(fd);
  path_ = name;
}

TemporaryFile::~TemporaryFile() { std::remove(path_.c_str()); }

std::string listed(const std::vector<std::string>& items) {
  std::string text;
  for (std::size_t i = 0; i < items.size(); ++i) {
    text += (i == 0 ? "" : i + 1 == items.size() ? " and " : ", ") + items[i];
  }
  return text;
}

int run_guarded(const std::string& command, const std::string& where, const std::function<int()>& body) {
  const std::string failed = "rc2000sim " + command + ": failed: ";
  try {
    return body();
  } catch (const CLI::Error&) {
    throw;  // an option refused: CLI11 prints it with its usage hint
  } catch (const CommandFailed&) {
    throw;
  } catch (const OutputsNotWritten& e) {
    throw CommandFailed(failed + e.what() + (e.written().empty() ? "; nothing written" : "; wrote " + listed(e.written())) +
                        "; not written: " + listed(e.not_written()));
  } catch (const std::bad_alloc&) {
    throw CommandFailed(failed + "out of memory (std::bad_alloc); nothing written to " + where);
  } catch (const std::exception& e) {
    throw CommandFailed(failed + e.what() + "; nothing written to " + where);
  }
}

}  // namespace rc
