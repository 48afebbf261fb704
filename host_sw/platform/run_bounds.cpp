#include "host_sw/platform/run_bounds.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

namespace rc {

namespace {

double per(double amount, double seconds) { return seconds > 0 ? amount / seconds : 0.0; }

std::optional<double> ceiling(std::uint64_t tests, double busy_seconds) {
  if (!(busy_seconds > 0)) return std::nullopt;
  return static_cast<double>(tests) / busy_seconds;
}

// The result bank's words are read-modify-written when the lanes of a group share a word (sec 4.2,
// RayGroup::result_accesses): any group of two lanes or more.
std::string bank_role(const RunReport& r, const BankUseReport& b) {
  if (b.role != "results") return b.role;
  const auto& groups = r.board.layout.ray_groups;
  const bool shared = std::any_of(groups.begin(), groups.end(), [](const RayGroupReport& g) { return g.lanes >= 2; });
  return shared ? "results, read-modify-write" : "results, written";
}

ResourceUse lanes_use(const RunReport& r, double fpga_busy, double clock_hz) {
  double per_cycle = 0;
  std::uint64_t tested = 0;
  for (const LaneReport& l : r.board.lanes) {
    per_cycle += l.rate;
    tested += l.rays;
  }
  ResourceUse u;
  u.kind = ResourceUse::Kind::lanes;
  u.name = "lanes";
  u.unit = "tests/s";
  u.capacity = per_cycle * clock_hz;
  u.demand = per(static_cast<double>(tested), fpga_busy);
  u.utilisation = per(u.demand, u.capacity);
  u.busy_seconds = u.utilisation * fpga_busy;  // the time the lanes' tests take at their peak
  if (u.capacity > 0) u.tests_per_second_ceiling = u.capacity;
  return u;
}

ResourceUse bank_use(const RunReport& r, const BankUseReport& b, double fpga_busy) {
  const DeviceReport& d = r.board.device;
  ResourceUse u;
  u.kind = ResourceUse::Kind::bank;
  u.name = "bank " + std::to_string(b.bank);
  u.role = bank_role(r, b);
  u.unit = "bytes/s";
  u.capacity = d.bank_word_bits / 8.0 * d.bank_clock_hz;  // one word a bank cycle, read or written
  u.read_bytes_per_second = per(static_cast<double>(b.bytes_read), fpga_busy);
  u.written_bytes_per_second = per(static_cast<double>(b.bytes_written), fpga_busy);
  u.demand = u.read_bytes_per_second + u.written_bytes_per_second;
  u.busy_seconds = b.busy_seconds;
  u.utilisation = per(b.busy_seconds, fpga_busy);
  u.tests_per_second_ceiling = ceiling(r.intersections.tests, b.busy_seconds);
  return u;
}

std::string pci_mode(const PciReport& p) {
  if (p.dma_transfers > 0 && p.pio_transfers > 0) return "DMA and PIO";
  if (p.pio_transfers > 0) return "PIO";
  return "DMA";
}

ResourceUse pci_use(const RunReport& r) {
  const PciReport& p = r.board.pci;
  const DeviceReport& d = r.board.device;
  const double run = r.simulated_seconds;
  ResourceUse u;
  u.kind = ResourceUse::Kind::pci;
  u.name = "PCI";
  u.role = pci_mode(p);
  u.fpga = false;
  u.unit = "bytes/s";
  u.capacity = d.pci_width_bits / 8.0 * d.pci_clock_hz;
  u.read_bytes_per_second = per(static_cast<double>(p.bytes_to_host), run);
  u.written_bytes_per_second = per(static_cast<double>(p.bytes_to_board), run);
  u.demand = u.read_bytes_per_second + u.written_bytes_per_second;
  // Several cards: the busiest bus (segment); one card: its bus.
  u.busy_seconds = p.bus_busy_seconds;
  if (!r.board.cards.buses.empty()) {
    u.busy_seconds = 0;
    for (const BusReport& b : r.board.cards.buses) u.busy_seconds = std::max(u.busy_seconds, b.busy_seconds);
  }
  u.utilisation = per(u.busy_seconds, run);
  u.tests_per_second_ceiling = ceiling(r.intersections.tests, u.busy_seconds);
  return u;
}

ResourceUse cpu_use(const RunReport& r, ResourceUse::Kind kind, const char* name, double busy) {
  ResourceUse u;
  u.kind = kind;
  u.name = name;
  u.fpga = false;
  u.unit = "s/s";
  u.capacity = 1;
  u.busy_seconds = busy;
  u.demand = u.utilisation = per(busy, r.simulated_seconds);
  u.tests_per_second_ceiling = ceiling(r.intersections.tests, busy);
  return u;
}

// The driver CPU of the busiest driver thread: the host thread's, or with several cards each card's own.
double driver_seconds(const RunReport& r) {
  double most = r.time.driver_cpu;
  for (const CardReport& c : r.board.cards.per_card) most = std::max(most, c.driver_cpu_seconds);
  return most;
}

// The stream limit with the most FPGA time (the first of equal ones), as an index of `resources`.
void stream_bound(const RunReport& r, RunBounds& b) {
  const StreamLimitReport* top = nullptr;
  double total = 0;
  for (const StreamLimitReport& l : r.board.stream_limits) {
    total += l.fpga_busy_seconds;
    if (!top || l.fpga_busy_seconds > top->fpga_busy_seconds) top = &l;
  }
  if (!top) return;
  b.stream_bound_share = per(top->fpga_busy_seconds, total);
  const std::string bank = top->limit.rfind("bank ", 0) == 0 ? top->limit.substr(0, top->limit.find(' ', 5)) : "";
  for (std::size_t i = 0; i < b.resources.size(); ++i) {
    const ResourceUse& u = b.resources[i];
    if ((top->limit == "lanes" && u.kind == ResourceUse::Kind::lanes) ||
        (!bank.empty() && u.kind == ResourceUse::Kind::bank && u.name == bank))
      b.stream.bound = i;
  }
  if (!b.stream.bound) throw std::logic_error("run_bounds: stream limit '" + top->limit + "' names no resource");
  for (std::size_t i = 0; i < b.resources.size(); ++i) {
    const ResourceUse& u = b.resources[i];
    if (!u.fpga || i == *b.stream.bound || !u.tests_per_second_ceiling) continue;
    if (!b.stream.next || *u.tests_per_second_ceiling < *b.resources[*b.stream.next].tests_per_second_ceiling)
      b.stream.next = i;
  }
}

std::vector<RunPart> run_parts(const RunReport& r) {
  const RunTime& t = r.time;
  std::vector<RunPart> parts = {{"fpga", t.waiting, 0},
                                {"host_compute", t.host_compute, 0},
                                {"host_driver", t.driver_cpu, 0},
                                {"pci", t.pci_transfer, 0}};
  for (RunPart& p : parts) p.share = per(p.seconds, r.simulated_seconds);
  std::stable_sort(parts.begin(), parts.end(), [](const RunPart& a, const RunPart& b) { return a.seconds > b.seconds; });
  return parts;
}

std::string part_text(const RunPart& p) {
  const char* name = p.name == "fpga" ? "FPGA" : p.name == "host_compute" ? "host compute"
                                               : p.name == "host_driver"  ? "driver"
                                                                          : "PCI transfers";
  char text[96];
  std::snprintf(text, sizeof text, "%s %.1f%%", name, 100.0 * p.share);
  return text;
}

std::string rate(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", x);
  return text;
}

}  // namespace

std::string resource_label(const ResourceUse& u) { return u.role.empty() ? u.name : u.name + " (" + u.role + ")"; }

std::string RunBounds::stream_bound_name() const { return stream_bound() ? resource_label(*stream_bound()) : ""; }
std::string RunBounds::stream_next_name() const { return stream_next() ? resource_label(*stream_next()) : ""; }

std::string RunBounds::summary() const {
  const std::string card = cards > 1 ? " per card" : "";
  std::string text = "run: " + part_text(run[0]) + " of the time (next: " + part_text(run[1]) + ")";
  const ResourceUse* b = stream_bound();
  if (!b) return text + "; no FPGA pass";
  char busy[32];
  std::snprintf(busy, sizeof busy, "%.1f%% busy", 100.0 * b->utilisation);
  text += "; FPGA stream: " + resource_label(*b) + " " + busy + ", " + rate(*b->tests_per_second_ceiling) + " tests/s" + card;
  if (const ResourceUse* n = stream_next())
    text += "; next: " + resource_label(*n) + " at " + rate(*n->tests_per_second_ceiling) + " tests/s" + card;
  return text;
}

std::string RunBounds::bandwidth_line() const {
  const ResourceUse& lanes = resources.front();
  const ResourceUse* busiest = nullptr;
  const ResourceUse* pci = nullptr;
  for (const ResourceUse& u : resources) {
    if (u.kind == ResourceUse::Kind::bank && (!busiest || u.utilisation > busiest->utilisation)) busiest = &u;
    if (u.kind == ResourceUse::Kind::pci) pci = &u;
  }
  std::string text = "lanes " + rate(lanes.demand) + " of " + rate(lanes.capacity) + " tests/s (" +
                     rate(tests_per_cycle_demand) + " of " + rate(tests_per_cycle_capacity) + " a cycle); SRAM " +
                     rate(sram_bytes_per_second) + " B/s (" + rate(sram_bytes_per_test) + " B a test)";
  if (busiest) text += ", busiest " + busiest->name + " " + rate(busiest->demand) + " of " + rate(busiest->capacity) + " B/s";
  if (pci) {
    text += "; PCI " + rate(pci->written_bytes_per_second) + " B/s to the board, " + rate(pci->read_bytes_per_second) +
            " B/s to the host, of " + rate(pci->capacity) + " (" + pci->role + ")";
  }
  return text;
}

RunBounds run_bounds(const RunReport& r) {
  if (!r.board_run) throw std::invalid_argument("run_bounds: not a board run (a software run has no board to bound)");
  RunBounds b;
  const double fpga_busy = r.time.fpga_busy;
  b.cards = r.board.cards.count;
  b.clock_hz = r.board.device.clock_hz;
  b.tests = r.intersections.tests;
  b.tests_per_second = per(static_cast<double>(b.tests), r.simulated_seconds);
  b.tests_per_second_while_fpga_busy = per(static_cast<double>(b.tests), fpga_busy);
  b.resources.push_back(lanes_use(r, fpga_busy, b.clock_hz));
  b.tests_per_cycle_demand = per(b.resources[0].demand, b.clock_hz);
  b.tests_per_cycle_capacity = per(b.resources[0].capacity, b.clock_hz);
  double bank_bytes = 0;
  for (const BankUseReport& bank : r.board.banks) {
    b.resources.push_back(bank_use(r, bank, fpga_busy));
    bank_bytes += static_cast<double>(bank.bytes_read + bank.bytes_written);
  }
  b.sram_bytes_per_second = per(bank_bytes, fpga_busy);
  b.sram_bytes_per_test = b.tests > 0 ? bank_bytes / static_cast<double>(b.tests) : 0.0;
  b.resources.push_back(pci_use(r));
  b.resources.push_back(cpu_use(r, ResourceUse::Kind::host_compute, "host compute", r.time.host_compute));
  b.resources.push_back(cpu_use(r, ResourceUse::Kind::driver, "driver", driver_seconds(r)));
  stream_bound(r, b);
  b.run = run_parts(r);
  return b;
}

}  // namespace rc
