// Writing outputs atomically: the bytes go to a temporary file beside the target, which is then
// renamed over it. A reader (a plot script, a merge, a diff) never sees half a file, and a write
// that fails (disk full, unwritable folder) leaves no file and throws an error naming the path.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

namespace rc::io {

// What went wrong with an output; what() starts with the path.
class OutputFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Writes `bytes` to `path` atomically (temporary "<path>.partial-<pid>", then rename). Throws
// OutputFileError naming the path and the system's reason, and refuses (never replaces) a path that
// exists and is not a regular file (a folder, a device).
void write_file_atomically(const std::string& path, std::string_view bytes);

}  // namespace rc::io
