#include "apps/outputs.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <new>
#include <system_error>
#include <unistd.h>

#include "io/output_file.h"

namespace rc {

namespace fs = std::filesystem;

namespace {

constexpr std::size_t kNameMax = 255;          // NAME_MAX of Linux's file systems: bytes in one name
constexpr std::size_t kPartialSuffixMax = 19;  // ".partial-" and a pid of up to 10 digits

std::string pid_text() { return std::to_string(::getpid()); }

// The nearest folder on the way to `path` that exists (".", for a bare file name), or the first thing
// on the way that exists and is not a folder. Each step is looked at without following a last
// symbolic link first (lstat), so a link whose target is missing, or a loop of links, is found here,
// where it would stop the write (creating the folder fails on it), and named: the check before the
// work must find every problem the write would hit.
fs::path nearest_existing(const std::string& path) {
  fs::path at = fs::path(path).parent_path();
  std::error_code error;
  while (!at.empty()) {
    const fs::file_status link = fs::symlink_status(at, error);
    if (fs::exists(link)) {
      if (fs::is_symlink(link)) {
        std::error_code followed;
        const fs::file_status target = fs::status(at, followed);
        if (!fs::exists(target)) {
          std::error_code unread;
          const fs::path to = fs::read_symlink(at, unread);
          throw io::OutputFileError(path + ": cannot be written: " + at.string() + " is a symbolic link to " +
                                    (unread ? std::string("a path that cannot be read") : to.string()) +
                                    ", which does not exist" + (followed.value() == ELOOP ? " (a loop of links)" : "") +
                                    "; a folder cannot be made there");
        }
      }
      return at;
    }
    at = at.parent_path();
  }
  return fs::path(".");
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
  // The probe below makes a short name; the write makes these, and the file's temporary name
  // "<name>.partial-<pid>" (io/output_file.h) is longer than the name by up to 19 bytes.
  const fs::path whole(path);
  for (auto part = whole.begin(); part != whole.end(); ++part) {
    const bool last = std::next(part) == whole.end();
    const std::size_t limit = last ? kNameMax - kPartialSuffixMax : kNameMax;
    if (part->string().size() > limit) {
      throw io::OutputFileError(path + ": cannot be written: the name " + part->string().substr(0, 40) + "... is " +
                                std::to_string(part->string().size()) + " bytes long, beyond the " +
                                std::to_string(limit) + " a file system takes" +
                                (last ? " for it with its temporary name's suffix (.partial-<pid>)" : ""));
    }
  }
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

OutputListing read_output_listing(const std::string& folder) {
  OutputListing listing;
  std::ifstream in(fs::path(folder) / kOutputListing);
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("command ", 0) == 0) listing.command = line.substr(8);
    if (line.rfind("set ", 0) == 0) listing.set = line.substr(4);
    if (line.rfind("file ", 0) != 0) continue;
    const fs::path file = fs::path(line.substr(5)).lexically_normal();
    if (file.empty() || file.is_absolute() || *file.begin() == ".." || file == "." || file == kOutputListing) continue;
    if (std::find(listing.files.begin(), listing.files.end(), file.string()) == listing.files.end())
      listing.files.push_back(file.string());
  }
  return listing;
}

namespace {

// `path` relative to `folder` when it lies inside it, else empty.
std::string inside(const std::string& folder, const std::string& path) {
  const fs::path relative = fs::absolute(path).lexically_normal().lexically_relative(fs::absolute(folder).lexically_normal());
  if (relative.empty() || *relative.begin() == ".." || relative == ".") return {};
  return relative.string();
}

void write_listing(const std::string& folder, const std::string& command, const std::string& set,
                   std::vector<std::string> files) {
  // Sorted, as the plot script keeps it (entry.py, _list): the listing does not depend on the order
  // of writing or of drawing (one machine and merged shards write the same listing).
  std::sort(files.begin(), files.end());
  std::string text =
      "# rc2000sim outputs: the files the commands that last wrote here wrote; the next command into this folder "
      "removes them unless it writes them again (docs/outputs.md, \"Output folders own their files\")\n";
  text += "command " + command + "\n";
  if (!set.empty()) text += "set " + set + "\n";
  for (const std::string& f : files) text += "file " + f + "\n";
  io::write_file_atomically((fs::path(folder) / kOutputListing).string(), text);
}

// Removes a listed file the command no longer writes (a regular file only: a folder or a link that
// now stands there is the user's), then the folders on its way that this left empty, up to `folder`.
void remove_listed(const std::string& folder, const std::string& file) {
  const fs::path path = fs::path(folder) / file;
  std::error_code error;
  if (!fs::is_regular_file(fs::symlink_status(path, error))) return;
  if (!fs::remove(path, error)) return;
  for (fs::path up = fs::path(file).parent_path(); !up.empty(); up = up.parent_path())
    if (!fs::remove(fs::path(folder) / up, error)) break;  // only an empty folder goes
}

}  // namespace

void Outputs::own_folder(const std::string& folder, const std::string& command, const std::string& set) {
  folder_ = folder;
  command_ = command;
  set_ = set;
  // The plot scripts this command starts add their pictures to the listing (apps/plots/entry.py).
  ::setenv("RC2000SIM_OUTPUT_FOLDER", fs::absolute(folder).lexically_normal().c_str(), 1);
}

void Outputs::keep(const std::string& path) { kept_.push_back(path); }

void Outputs::write() {
  if (folder_.empty()) return write_files();
  const OutputListing earlier = read_output_listing(folder_);
  std::vector<std::string> mine;
  auto add_mine = [&](const std::string& path) {
    const std::string relative = inside(folder_, path);
    if (!relative.empty() && std::find(mine.begin(), mine.end(), relative) == mine.end()) mine.push_back(relative);
  };
  for (const File& f : files_)
    if (f.failure.empty()) add_mine(f.path);
  // A kept input stays where the earlier listing named it; one it did not name is not this folder's
  // output (shards in a subfolder with a listing of their own) and is not listed here.
  for (const std::string& k : kept_) {
    const std::string relative = inside(folder_, k);
    if (std::find(earlier.files.begin(), earlier.files.end(), relative) != earlier.files.end()) add_mine(k);
  }
  const bool adds = !set_.empty() && earlier.set == set_;
  std::vector<std::string> stale, both = mine;
  for (const std::string& f : earlier.files) {
    if (std::find(mine.begin(), mine.end(), f) != mine.end()) continue;
    both.push_back(f);
    if (!adds) stale.push_back(f);
  }
  // While the files are written, the listing names the earlier ones and these: a write that stops
  // part-way leaves nothing unlisted.
  std::error_code error;
  if (!mine.empty()) {
    fs::create_directories(folder_, error);
    if (error) throw OutputsNotWritten(folder_ + ": cannot create the folder (" + error.message() + ")", {}, paths());
    try {
      write_listing(folder_, command_, set_, both);
    } catch (const std::exception& e) {
      throw OutputsNotWritten(e.what(), {}, paths());
    }
  }
  write_files();
  for (const std::string& f : stale) remove_listed(folder_, f);
  try {
    write_listing(folder_, command_, set_, adds ? both : mine);
  } catch (const std::exception& e) {
    throw OutputsNotWritten(e.what(), paths(), {(fs::path(folder_) / kOutputListing).string()});
  }
}

void Outputs::write_files() {
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
