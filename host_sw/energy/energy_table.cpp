#include "host_sw/energy/energy_table.h"

#include "profiles/profile_reader.h"

namespace rc::energy {

namespace {

// Units by the key's suffix: the key says what its number means, and the reader converts once.
struct Unit {
  const char* suffix;
  const char* name;
  double si;
  double max;  // a limit far above any real part: a misplaced decimal point is an error
};
constexpr Unit kUnits[] = {{"_pj_per_cycle", "pJ", 1e-12, 1e6}, {"_pj_per_slice_cycle", "pJ", 1e-12, 1e6},
                           {"_nj", "nJ", 1e-9, 1e6},               {"_mw", "mW", 1e-3, 1e6},
                           {"_w", "W", 1.0, 1e4}};

const Unit& unit_of(const std::string& path) {
  for (const Unit& u : kUnits) {
    const std::string s = u.suffix;
    if (path.size() > s.size() && path.compare(path.size() - s.size(), s.size(), s) == 0) return u;
  }
  throw std::logic_error("energy table key without a unit suffix: " + path);
}

Figure figure(const profiles::ProfileReader& r, const std::string& path) {
  const Unit& u = unit_of(path);
  return {r.number(path, 0, u.max), path, u.name, r.source(path)};
}

void require_section(const profiles::ProfileReader& r, const char* what) {
  if (!r.has("energy")) {
    throw MissingEnergyTable(r.file() + " has no energy table (an \"energy\" section: docs/energy.md), so " + what +
                             " has no energy figures; its times are unaffected");
  }
}

}  // namespace

double Figure::si() const { return value * unit_of(path).si; }

DeviceEnergyTable device_energy_table(const board::DeviceProfile& profile) {
  const profiles::ProfileReader r(profile.document, profile.file);
  require_section(r, "the board");
  DeviceEnergyTable t;
  t.file = profile.file;
  t.fpga = {figure(r, "energy.fpga.static_w"), figure(r, "energy.fpga.slice_pj_per_cycle"),
            figure(r, "energy.fpga.multiplier_pj_per_cycle"), figure(r, "energy.fpga.clock_pj_per_slice_cycle")};
  t.sram = {figure(r, "energy.sram.read_nj"), figure(r, "energy.sram.write_nj"), figure(r, "energy.sram.standby_mw")};
  t.pci = {figure(r, "energy.pci.data_phase_nj"), figure(r, "energy.pci.transaction_nj"),
           figure(r, "energy.pci.bridge_w")};
  // The rest of the profile is the device loader's; here only the energy section is checked whole.
  std::vector<std::string> elsewhere;
  for (const std::string& key : profile.document.top_keys())
    if (key != "energy") elsewhere.push_back(key);
  r.refuse_unknown_keys(elsewhere);
  return t;
}

HostEnergyTable host_energy_table(const profiles::ProfileDocument& host_profile, const std::string& file) {
  const profiles::ProfileReader r(host_profile, file);
  require_section(r, "the host");
  HostEnergyTable t{file, figure(r, "energy.busy_w"), figure(r, "energy.wait_w")};
  std::vector<std::string> elsewhere;
  for (const std::string& key : host_profile.top_keys())
    if (key != "energy") elsewhere.push_back(key);
  r.refuse_unknown_keys(elsewhere);
  return t;
}

EnergyTables load_energy_tables(const board::DeviceProfile* device, const profiles::ProfileDocument& host_profile,
                                const std::string& host_file) {
  EnergyTables t;
  std::string missing;
  try {
    t.host = host_energy_table(host_profile, host_file);
  } catch (const MissingEnergyTable& e) {
    missing = e.what();
  }
  if (device != nullptr) {
    try {
      t.device = device_energy_table(*device);
    } catch (const MissingEnergyTable& e) {
      missing += (missing.empty() ? "" : "; ") + std::string(e.what());
    }
  }
  t.missing = missing;
  return t;
}

}  // namespace rc::energy
