// What the harnesses share. Each harness (fuzz/*_fuzz.cpp) feeds its input to one of the project's
// readers and catches only the error that reader documents; anything else leaves the harness and is
// a finding: a crash, a sanitizer report, an exception of another type, a huge allocation
// (libFuzzer's -malloc_limit_mb), a hang (-timeout). docs/reliability.md, "Fuzzing".
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace rc::fuzz {

// A folder private to this process for input files, for readers that take a path: in $TMPDIR if
// set (scripts/fuzz points it at its work folder), else in /dev/shm (memory: thousands of small
// writes a second never touch a disk), else in /tmp. Removed when the process exits normally.
const std::string& scratch_dir();

// Writes the bytes to <scratch_dir>/<name>, replacing the previous input, and returns the path.
std::string write_input(const std::string& name, const std::uint8_t* data, std::size_t size);

// Writes a fixed file (a mesh a composition can name, say) into the scratch folder once.
void write_fixture(const std::string& name, const std::string& content);

}  // namespace rc::fuzz
