// Study files (host_sw/studies/study_file.h) on any bytes: a study, or std::invalid_argument naming the
// file, the line and the key. Parsing resolves device and host names and profile paths against
// configs/, as `rc2000sim sweep --study` does. Every other outcome is a finding.
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "fuzz/fuzz_support.h"
#include "host_sw/studies/study_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  // Relative scene paths are anchored at the study's folder: the scratch folder.
  const std::string path = rc::fuzz::scratch_dir() + "/study.toml";
  try {
    (void)rc::parse_study_text(text, path);
  } catch (const std::invalid_argument&) {
    // The documented error.
  }
  return 0;
}
