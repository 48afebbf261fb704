// Host profiles (host_sw/driver/host_cpu_model.h) on any bytes, read from a file as rc2000sim reads them:
// a profile, or std::invalid_argument naming the file and the field; then its energy table
// (host_sw/energy/energy_table.h): a table, MissingEnergyTable, or the same error. Every other outcome is a
// finding.
#include <cstddef>
#include <cstdint>
#include <stdexcept>

#include "host_sw/energy/energy_table.h"
#include "fuzz/fuzz_support.h"
#include "host_sw/driver/host_cpu_model.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = rc::fuzz::write_input("host.json", data, size);
  try {
    const rc::HostProfile profile = rc::load_host_profile(path);
    (void)rc::energy::host_energy_table(profile.document, path);
  } catch (const std::invalid_argument&) {
    // The documented error (profiles/profile_reader.h).
  }
  return 0;
}
