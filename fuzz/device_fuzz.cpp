// Device profiles (board/device_profile.h) on any bytes, read from a file as rc2000sim reads them:
// a profile, or std::invalid_argument naming the file and the field; then its energy table
// (host_sw/energy/energy_table.h) as a board run loads it: a table, MissingEnergyTable, or the same error.
// Every other outcome is a finding.
#include <cstddef>
#include <cstdint>
#include <stdexcept>

#include "board/device_profile.h"
#include "host_sw/energy/energy_table.h"
#include "fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = rc::fuzz::write_input("device.json", data, size);
  try {
    const rc::board::DeviceProfile profile = rc::board::load_device_profile(path);
    (void)rc::energy::device_energy_table(profile);
  } catch (const std::invalid_argument&) {
    // The documented error (profiles/profile_reader.h).
  }
  return 0;
}
