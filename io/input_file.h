// Reading a user's file with a bound on its size. Every text input of the model (scene files,
// compositions, device and host profiles, study files, resource tables) is read through here, so a
// wrong path (a directory, /dev/zero, a multi-gigabyte log) ends in an error that names the file and
// the limit instead of an endless read or an out-of-memory kill.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

namespace rc::io {

// The size limits, one per kind of input, in bytes. Generous for real data: the largest scene
// file shipped is under 1 MiB, profiles and study files a few KiB.
inline constexpr std::uint64_t kProfileLimitBytes = 1ull << 20;   // device/host profiles, study files, tables
inline constexpr std::uint64_t kSceneLimitBytes = 256ull << 20;   // scene files and meshes

// What went wrong with an input file; what() starts with the path.
class InputFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Whether a reader takes a pipe. Only `--scene` does (docs/scenes.md): an anonymous pipe, as bash's
// process substitution `--scene <(gunzip -c room.scene.gz)` or a shell pipe into /dev/stdin gives,
// is read once into memory. A named pipe (FIFO) is refused everywhere: opening one blocks until a
// writer comes, which may be never. A writer already waiting on it is released (the refusal opens
// the read end without blocking and closes it: the writer gets a broken pipe and ends).
enum class Pipes { refused, read_once };

// The whole file as bytes. Throws InputFileError naming `path` when it cannot be opened, is a
// directory, a device, a socket or a pipe (before any read: a FIFO blocks on open; an anonymous
// pipe is read with Pipes::read_once), or holds more than `limit_bytes` (`what` names the kind of
// input in that message, e.g. "a scene file"). A pipe is read to at most limit_bytes + 1 bytes.
std::string read_file(const std::string& path, std::uint64_t limit_bytes, const std::string& what,
                      Pipes pipes = Pipes::refused);

// Throws InputFileError unless `path` names a regular file of at most `limit_bytes` (for readers
// that open the file themselves, such as Assimp's importer). A special file is named by its kind:
// "/dev/zero: is a character device, not a regular file (a mesh file must be one)".
void check_regular_file(const std::string& path, std::uint64_t limit_bytes, const std::string& what);

// True when `path` is an anonymous pipe (process substitution, a shell pipe), not a named one.
bool is_anonymous_pipe(const std::string& path);

// The UTF-8 byte order mark some editors put first in a text file; text readers skip it.
inline constexpr char kUtf8ByteOrderMark[] = "\xEF\xBB\xBF";

// `text` without a leading UTF-8 byte order mark.
inline std::string without_byte_order_mark(std::string text) {
  if (text.rfind(kUtf8ByteOrderMark, 0) == 0) text.erase(0, sizeof kUtf8ByteOrderMark - 1);
  return text;
}

}  // namespace rc::io
