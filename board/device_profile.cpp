#include "board/device_profile.h"

#include <map>
#include <mutex>
#include <stdexcept>

#include "io/parse_number.h"
#include "pipeline/fixed_format.h"
#include "profiles/profile_reader.h"

namespace rc::board {

double DeviceProfile::clock_mhz(int lanes) const {
  const auto it = clock_mhz_by_lanes.find(lanes);
  if (it != clock_mhz_by_lanes.end()) return it->second;
  if (clock_mhz_default) return *clock_mhz_default;
  throw std::invalid_argument((file.empty() ? name : file) + ": clock.mhz_by_lanes." + std::to_string(lanes) + ": missing: device profile " +
                              name + " gives no clock for " + std::to_string(lanes) +
                              " lanes (clock.mhz_by_lanes has no entry and there is no clock.mhz_default)");
}

namespace {

void read_clock(const profiles::ProfileReader& r, DeviceProfile& p) {
  {
    for (const std::string& key : r.keys("clock.mhz_by_lanes", "must be an object keyed by lane count")) {
      const std::string path = "clock.mhz_by_lanes." + key;
      // The whole key must be the count: "2abc" or " 2" is no lane count (std::stoi read them as 2).
      const std::optional<std::uint64_t> lanes = io::parse_unsigned(key);
      if (!lanes || *lanes < 1 || *lanes > LaneCount::kMax) {
        r.fail(path, "key must be a lane count, a whole number 1.." + std::to_string(LaneCount::kMax) +
                         " (a design has at most " + std::to_string(LaneCount::kMax) + " lanes: the CONFIG register holds 8 bits)");
      }
      p.clock_mhz_by_lanes[static_cast<int>(*lanes)] = r.number(path, 1e-3, 1e4);
    }
  }
  p.clock_mhz_default = r.optional_number("clock.mhz_default", 1e-3, 1e4);
  if (p.clock_mhz_by_lanes.empty() && !p.clock_mhz_default)
    r.fail("clock", "needs mhz_by_lanes or mhz_default");
  const std::uint64_t bits = r.integer("clock.design_bits", 0, 1024);
  if (!pipeline::is_valid_frac_bits(static_cast<int>(bits))) {
    r.refuse("clock.design_bits", std::to_string(bits),
             "is not a fractional width the pipeline has (" + std::to_string(pipeline::kMinFracBits) + ".." +
                 std::to_string(pipeline::kMaxFracBits) + ")");
  }
  p.clock_bits = static_cast<int>(bits);
}

// The banks, each value checked against what the wrapper and its registers can use (bank_layout.h).
void read_banks(const profiles::ProfileReader& r, DeviceProfile& p) {
  const std::uint64_t count = r.integer("banks.count", 0, 1u << 20);
  if (count < kMinBanks) {
    r.refuse("banks.count", std::to_string(count),
             "is fewer than the " + std::to_string(kMinBanks) + " banks the wrapper needs (faces, X, Y, Z, results; paper sec 4.1)");
  }
  if (count > kMaxBanks) {
    r.refuse("banks.count", std::to_string(count),
             "is more than the wrapper's CONFIG register can count (8 bits: at most " + std::to_string(kMaxBanks) + ")");
  }
  p.bank_count = static_cast<unsigned>(count);
  p.bank_word_bits = static_cast<unsigned>(r.integer("banks.word_bits", 32, 64));
  if (p.bank_word_bits != 32 && p.bank_word_bits != 64) r.fail("banks.word_bits", "must be 32 or 64");
  p.bank_capacity_bytes = r.integer("banks.capacity_bytes", 1, std::uint64_t(1) << 53);
  const std::string problem = bank_capacity_problem(p.bank_capacity_bytes, p.bank_word_bits);
  if (!problem.empty()) r.refuse("banks.capacity_bytes", std::to_string(p.bank_capacity_bytes), problem);
  p.bank_clock_mhz = r.number("banks.clock_mhz", 1e-3, 1e4);
  p.bank_read_latency_cycles = static_cast<unsigned>(r.integer("banks.read_latency_cycles", 0, 100));
  p.bank_write_latency_cycles = static_cast<unsigned>(r.integer("banks.write_latency_cycles", 0, 100));
}

}  // namespace

DeviceProfile load_device_profile(const std::string& path) {
  return device_profile_from_document(profiles::read_profile_document(path, "a device profile"), path);
}

DeviceProfile device_profile_from_document(const profiles::ProfileDocument& document, const std::string& origin) {
  DeviceProfile p;
  p.document = document;
  p.file = origin;
  const profiles::ProfileReader r(p.document, origin);
  r.schema("rc2000sim.device/1");
  p.name = r.text("name");
  if (p.name.empty()) r.fail("name", "must not be empty");
  p.part = r.text("fpga.part");
  p.slices = static_cast<int>(r.integer("fpga.slices", 1, 1u << 24));
  p.block_multipliers = static_cast<int>(r.integer("fpga.block_multipliers", 0, 1u << 20));
  p.block_ram_bits = r.integer("fpga.block_ram_bits", 0, std::uint64_t(1) << 40);
  read_clock(r, p);
  p.pipeline_latency_cycles = static_cast<unsigned>(r.integer("pipeline.latency_cycles", 1, 1000));

  read_banks(r, p);

  p.pci_width_bits = static_cast<unsigned>(r.integer("pci.width_bits", 32, 64));
  if (p.pci_width_bits != 32 && p.pci_width_bits != 64) r.fail("pci.width_bits", "must be 32 or 64");
  p.pci_clock_mhz = r.number("pci.clock_mhz", 1, 1000);
  p.pci_burst_efficiency = r.number("pci.burst_efficiency", 1e-3, 1.0);
  p.pci_setup_cycles = static_cast<unsigned>(r.integer("pci.setup_cycles", 0, 1000));
  // At most 2^32 - 1: a burst is one TLM transaction, whose data length is 32-bit (tlm/dma_engine.cpp).
  p.pci_max_burst_bytes = r.integer("pci.max_burst_bytes", 8, (std::uint64_t(1) << 32) - 1);
  p.pci_master_abort_cycles = static_cast<unsigned>(r.integer("pci.master_abort_cycles", 1, 1000));
  p.bridge_latency_cycles = static_cast<unsigned>(r.integer("pci.bridge_latency_cycles", 0, 1000));

  p.pass_start_cycles = static_cast<unsigned>(r.integer("wrapper.pass_start_cycles", 0, 1u << 20));
  p.face_setup_cycles = static_cast<unsigned>(r.integer("wrapper.face_setup_cycles", 0, 1u << 20));
  p.pass_finish_cycles = static_cast<unsigned>(r.integer("wrapper.pass_finish_cycles", 0, 1u << 20));
  p.register_access_cycles = static_cast<unsigned>(r.integer("wrapper.register_access_cycles", 1, 1u << 20));
  p.results = static_cast<ResultStore>(r.choice("wrapper.results", result_store_names()));
  // "energy" is the energy table's, read and checked whole by host_sw/energy/energy_table.h.
  r.refuse_unknown_keys({"description", "energy"});
  return p;
}

// A profile named from the config folder is read once per process: no command writes device profiles,
// and a run asks for its own device and, for sec 5.6's bandwidth, the RC2000's xc2v6000 again
// (tests/scripts/profile_reads_test.sh). A path is read each time (tests rewrite their own files).
DeviceProfile find_device_profile(const std::string& name_or_path) {
  const std::string path = profiles::resolve_profile_path(name_or_path, "devices");
  if (path == name_or_path) return load_device_profile(path);
  static std::mutex guard;
  static std::map<std::string, DeviceProfile> loaded;
  const std::lock_guard<std::mutex> lock(guard);
  auto it = loaded.find(path);
  if (it == loaded.end()) it = loaded.emplace(path, load_device_profile(path)).first;
  return it->second;
}

}  // namespace rc::board
