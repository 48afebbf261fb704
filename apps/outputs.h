// What a command writes, and what a failure says about it (docs/outputs.md, "When a command fails").
//
// A command computes everything first, gathering its files in an Outputs, and writes them only at the
// end: a failure anywhere before leaves nothing behind (no file, no folder) and says so. Each file is
// written atomically (io/output_file.h: a temporary file, then a rename); a folder is created only
// when its first file is written. If writing itself fails part-way, the error lists the files that
// were written and those that were not. Pictures drawn by the plot scripts (apps/plot.h) come after
// the data they draw and are written by the scripts the same way (apps/plots/entry.py, save()).
//
//   Outputs out;
//   out.expect(dir + "/report.json");            // before any work: can it be written at all?
//   ... compute ...
//   out.add(dir + "/report.json", text);
//   out.write();                                  // folders, then each file atomically
#pragma once

#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace rc {

// A command that failed; what() is the whole message, ready to print:
// "rc2000sim run: failed: <reason>; nothing written to out/".
class CommandFailed : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Writing stopped at one file. what() is the reason; written() and not_written() name the files.
class OutputsNotWritten : public std::runtime_error {
 public:
  OutputsNotWritten(const std::string& reason, std::vector<std::string> written, std::vector<std::string> not_written)
      : std::runtime_error(reason), written_(std::move(written)), not_written_(std::move(not_written)) {}
  const std::vector<std::string>& written() const { return written_; }
  const std::vector<std::string>& not_written() const { return not_written_; }

 private:
  std::vector<std::string> written_, not_written_;
};

class Outputs {
 public:
  // Checks now, before any work, that `path` could be written: it is not a folder or a device, not
  // a path expected already (`--trace out/report.json`), and the nearest folder on its way that exists
  // takes a new file (a probe file is created there and removed; no folder is created). Throws
  // io::OutputFileError naming the path and the reason.
  void expect(const std::string& path);

  void add(const std::string& path, std::string bytes);
  // A file whose bytes are made now by `make`, after the work: if making them fails (an exception),
  // the other files are still written, and write() then throws OutputsNotWritten naming this one
  // and why. A failure after a finished solve keeps what can be written.
  void add_made(const std::string& path, const std::function<std::string()>& make);
  // A file another library has already written elsewhere (a VCD SystemC wrote to a temporary file),
  // moved to `path` with the others.
  void move_in(const std::string& path, const std::string& temporary);

  // The folder this command's outputs live in (its --out; docs/outputs.md, "Output folders own their
  // files"). write() then lists the files it writes under `folder` in `folder`/rc2000sim-outputs.txt
  // (kOutputListing), and removes the files an earlier command's listing there names that this
  // command does not write: never a file no listing names (a user's own). Commands of one `set` (the
  // shards of one study) add to the listing instead of replacing it. Pictures the plot scripts save
  // under the folder are added to the listing as they are saved (apps/plots/entry.py, save()).
  void own_folder(const std::string& folder, const std::string& command, const std::string& set = "");
  // A file of the owned folder this command reads and keeps (sweep merge's shards): not removed, and
  // listed again when the earlier listing named it.
  void keep(const std::string& path);

  // Creates each file's folder when its first file is written, and each file atomically, in the
  // order added. Throws OutputsNotWritten at the first failure to write, or after writing the
  // others when a file of add_made could not be made.
  void write();
  std::vector<std::string> paths() const;
  bool empty() const { return files_.empty(); }

 private:
  struct File {
    std::string path;
    std::string bytes;
    std::string temporary;  // move_in: the file to move
    std::string failure;    // add_made: why its bytes could not be made (it is not written)
  };
  void write_files();
  std::vector<File> files_;
  std::vector<std::string> expected_;  // absolute, normal
  std::string folder_, command_, set_;  // own_folder()
  std::vector<std::string> kept_;
};

// The listing of an output folder's files (Outputs::own_folder).
inline constexpr const char* kOutputListing = "rc2000sim-outputs.txt";

// What a folder's listing says: the command, its set, the files (relative to the folder). Lines that
// are not "file <relative path>" inside the folder (an absolute path, "..") are skipped: a listing
// never reaches outside its folder. A folder without a listing gives an empty one.
struct OutputListing {
  std::string command, set;
  std::vector<std::string> files;
};
OutputListing read_output_listing(const std::string& folder);

// A temporary file in the system's temporary folder, removed when it goes out of scope (unless it was
// moved away): where SystemC writes a VCD while the run simulates.
class TemporaryFile {
 public:
  explicit TemporaryFile(const std::string& suffix);
  ~TemporaryFile();
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

// Runs a command's body. Any exception but an option error (CLI::Error) becomes CommandFailed:
// "rc2000sim <command>: failed: <reason>; nothing written to <where>" when nothing was written, or
// "...; wrote A, B; not written: C, D" when writing stopped part-way.
int run_guarded(const std::string& command, const std::string& where, const std::function<int()>& body);

// "a, b and c" for messages.
std::string listed(const std::vector<std::string>& items);

}  // namespace rc
