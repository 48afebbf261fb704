#include "fuzz/fuzz_support.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <vector>

namespace rc::fuzz {

namespace {

std::string base_dir() {
  if (const char* tmp = std::getenv("TMPDIR"); tmp != nullptr && *tmp != '\0') return tmp;
  std::error_code error;
  if (std::filesystem::is_directory("/dev/shm", error)) return "/dev/shm";
  return "/tmp";
}

// Created on first use, removed by its destructor at a normal exit (a crash leaves it for the
// post-mortem; it holds only the last input, which libFuzzer saves anyway).
class Scratch {
 public:
  Scratch() {
    std::string pattern = base_dir() + "/rc-fuzz-XXXXXX";
    std::vector<char> buffer(pattern.begin(), pattern.end());
    buffer.push_back('\0');
    if (::mkdtemp(buffer.data()) == nullptr) {
      std::perror(("fuzz: cannot create a scratch folder like " + pattern).c_str());
      std::abort();
    }
    path_ = buffer.data();
  }
  ~Scratch() {
    std::error_code ignored;  // best effort at exit: nothing is left to report it to
    std::filesystem::remove_all(path_, ignored);
  }
  Scratch(const Scratch&) = delete;
  Scratch& operator=(const Scratch&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

void write_bytes(const std::string& path, const char* data, std::size_t size) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(data, static_cast<std::streamsize>(size));
  out.close();
  // A harness that cannot write its input tests nothing: stop loudly rather than pass.
  if (!out) {
    std::fprintf(stderr, "fuzz: cannot write %s\n", path.c_str());
    std::abort();
  }
}

}  // namespace

const std::string& scratch_dir() {
  static const Scratch scratch;
  return scratch.path();
}

std::string write_input(const std::string& name, const std::uint8_t* data, std::size_t size) {
  const std::string path = scratch_dir() + "/" + name;
  write_bytes(path, reinterpret_cast<const char*>(data), size);
  return path;
}

void write_fixture(const std::string& name, const std::string& content) {
  write_bytes(scratch_dir() + "/" + name, content.data(), content.size());
}

}  // namespace rc::fuzz
