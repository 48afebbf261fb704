// A user's own virtual platform around the installed RC2000 model: the board built from a device
// profile found by name (the installed configs), and this file's own TLM initiator as the host. It
// reads the ID register, DMAs one face and four rays into the banks over PCI, writes the pass
// registers, START, waits for the interrupt, reads the result bits back over PCI and checks them
// against the CPU pipeline (pipeline/fixed_mt.h) and the pass's time against the timing formula
// (board/pass_timing.h), exactly. Exits 1 on any mismatch, 2 on an error.
#include <cstdint>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include <systemc>
#include <tlm_utils/simple_initiator_socket.h>

#include "board/board_params.h"
#include "board/device_profile.h"
#include "board/pass_timing.h"
#include "board/rc2000.h"
#include "board/register_map.h"
#include "board/word_format.h"
#include "pipeline/fixed_mt.h"

namespace {

using namespace rc;
using sc_core::sc_time;

int g_failures = 0;
template <class T>
void check(const char* what, const T& got, const T& want) {
  if (got == want) return;
  ++g_failures;
  std::fprintf(stderr, "MISMATCH %s\n", what);
}

// The host: a PCI master that reads and writes the board's registers (BAR0), waiting out each
// access's time, and uses the board's bridge DMA for bank data (BAR1).
class Host : public sc_core::sc_module {
 public:
  tlm_utils::simple_initiator_socket<Host> pci{"pci"};
  bool finished = false;

  Host(const sc_core::sc_module_name& name, board::Rc2000& b) : sc_core::sc_module(name), m_board(b) {
    pci.bind(b.pci.in);
    SC_HAS_PROCESS(Host);
    SC_THREAD(run);
  }

  std::uint32_t read(std::uint64_t offset) {
    std::uint32_t v = 0;
    access(tlm::TLM_READ_COMMAND, offset, &v, 1);
    return v;
  }
  void write(std::uint64_t offset, std::vector<std::uint32_t> values) {
    access(tlm::TLM_WRITE_COMMAND, offset, values.data(), values.size());
  }
  void dma(tlmx::DmaDirection dir, std::uint8_t* data, unsigned bank, std::uint64_t bytes) {
    if (bytes == 0) return;
    const tlmx::DmaResult r = m_board.dma.transfer(dir, data, m_board.bank_pci_address(bank), bytes);
    check("DMA completes", r.ok(), true);
  }

 private:
  void access(tlm::tlm_command cmd, std::uint64_t offset, std::uint32_t* values, std::size_t n) {
    tlm::tlm_generic_payload t;
    t.set_command(cmd);
    t.set_address(board::Rc2000::kBar0 + offset);
    t.set_data_ptr(reinterpret_cast<unsigned char*>(values));
    t.set_data_length(static_cast<unsigned>(n * 4));
    t.set_streaming_width(static_cast<unsigned>(n * 4));
    t.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
    sc_time delay = sc_core::SC_ZERO_TIME;
    pci->b_transport(t, delay);
    check("register access answered OK", t.is_response_ok(), true);
    sc_core::wait(delay);
  }
  void run();
  board::Rc2000& m_board;

 public:
  // What the host saw, checked after the simulation.
  std::vector<std::uint8_t> blocked;
  std::uint32_t pass_cycles = 0;
  sc_time irq_seen;
};

// One face across z = 0.5 and a start point below it; four end points above it, two of them past
// the face's edge. Fractional bits of the lanes: 15.
constexpr int kBits = 15;
const pipeline::FaceRecord kFace = pipeline::make_face_record({{0.1, 0.1, 0.5}, {0.9, 0.1, 0.5}, {0.1, 0.9, 0.5}}, kBits);
const pipeline::FixedVec3 kStart = pipeline::quantize_point({0.3, 0.3, 0.1}, kBits);
const std::vector<pipeline::FixedVec3> kEnds = {
    pipeline::quantize_point({0.3, 0.3, 0.9}, kBits), pipeline::quantize_point({0.95, 0.95, 0.9}, kBits),
    pipeline::quantize_point({0.4, 0.2, 0.9}, kBits), pipeline::quantize_point({0.99, 0.3, 0.12}, kBits)};

void Host::run() {
  const board::BankLayout& L = m_board.layout();
  const unsigned wb = L.word_bits / 8;
  check("ID register", read(board::reg::kId), board::reg::kIdValue);

  // The face record (nine words) and its own-face table entry (no ray ends on it) into the face bank.
  std::uint64_t words[9];
  board::face_record_words(kFace, words);
  const unsigned mask_bank = L.mask_bank ? *L.mask_bank : L.face_bank;
  std::vector<std::uint8_t> face_bytes((L.mask_bank ? 9 : 10) * wb, 0);
  for (unsigned i = 0; i < 9; ++i) board::store_word(face_bytes.data(), i, wb, words[i]);
  dma(tlmx::DmaDirection::to_device, face_bytes.data(), L.face_bank, face_bytes.size());
  if (L.mask_bank) {
    std::vector<std::uint8_t> mask(wb, 0);
    dma(tlmx::DmaDirection::to_device, mask.data(), mask_bank, mask.size());
  }
  // The rays, packed into the ray banks as the layout says.
  std::vector<std::int64_t> x, y, z;
  for (const auto& e : kEnds) x.push_back(e.x), y.push_back(e.y), z.push_back(e.z);
  const board::RaySplit split = board::split_rays(L, kEnds.size());
  std::vector<std::vector<std::uint8_t>> images;
  board::pack_rays(L, split, x.data(), y.data(), z.data(), images);
  for (unsigned bank = 0; bank < images.size(); ++bank)
    dma(tlmx::DmaDirection::to_device, images[bank].data(), bank, images[bank].size());

  // The pass: rays, faces, first face 0, no source face, the start point, every ray "ends before"
  // the face set (so the own-face rule excludes none); then START with CLEAR.
  const auto rays = static_cast<std::uint32_t>(kEnds.size());
  write(board::reg::kRayCount, {rays, 1, 0, board::reg::kNoFace, static_cast<std::uint32_t>(kStart.x),
                                static_cast<std::uint32_t>(kStart.y), static_cast<std::uint32_t>(kStart.z), rays});
  write(board::reg::kControl, {board::reg::kStart | board::reg::kClear});
  m_board.irq.wait_raised();
  irq_seen = sc_core::sc_time_stamp();
  check("STATUS after the pass", read(board::reg::kStatus), board::reg::kDone);
  pass_cycles = read(board::reg::kPassCyclesLo);
  write(board::reg::kStatus, {board::reg::kDone});

  std::vector<std::uint8_t> result(split.result_words * wb);
  dma(tlmx::DmaDirection::to_host, result.data(), L.result_bank, result.size());
  blocked.assign(kEnds.size(), 0);
  board::unpack_results(L, split, result.data(), blocked.data());
  finished = true;
}

int simulate(const std::string& device) {
  board::BoardChoices choices;
  choices.lanes = 1;
  choices.bits = kBits;
  choices.irq_latency = sc_time(2, sc_core::SC_US);
  const board::BoardParams params = board::make_board_params(board::find_device_profile(device), choices);
  board::Rc2000 rc2000("rc2000", params);
  std::vector<board::PassRecord> passes;
  rc2000.wrapper().on_pass([&](const board::PassRecord& r) { passes.push_back(r); });
  Host host("host", rc2000);
  sc_core::sc_start();

  check("the host finished", host.finished, true);
  check("one pass", passes.size(), std::size_t{1});
  if (!host.finished || passes.size() != 1) return 1;
  // The result bits against the CPU pipeline, ray by ray.
  std::vector<std::uint8_t> want;
  for (const auto& e : kEnds) want.push_back(pipeline::segment_hits(kFace, kStart, e, kBits) ? 1 : 0);
  check("blocked flags", host.blocked, want);
  check("some rays blocked, some not", want, std::vector<std::uint8_t>{1, 0, 1, 0});
  // The pass's time: the formula's device cycles, in the register and in simulated time, and the
  // interrupt exactly its latency after DONE.
  const board::PassTiming t = board::pass_timing(rc2000.layout(), params.timing,
                                                 board::split_rays(rc2000.layout(), kEnds.size()), 1, true);
  check("PASS_CYCLES register", std::uint64_t{host.pass_cycles}, t.total);
  check("pass time", passes[0].end - passes[0].start, params.timing.device_period * static_cast<double>(t.total));
  check("interrupt time", host.irq_seen, passes[0].end + params.irq_latency);
  std::printf("device %s: pass %llu cycles = %s, interrupt at %s, blocked %d%d%d%d\n", params.device.c_str(),
              static_cast<unsigned long long>(t.total), (passes[0].end - passes[0].start).to_string().c_str(),
              host.irq_seen.to_string().c_str(), host.blocked[0], host.blocked[1], host.blocked[2], host.blocked[3]);
  return g_failures == 0 ? 0 : 1;
}

}  // namespace

int sc_main(int argc, char** argv) {
  try {
    return simulate(argc > 1 ? argv[1] : "xc2v6000");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
}
