// Results on chip (docs/board.md, "Results on chip"): the lanes OR their blocked bits into block RAM
// and the wrapper writes each result word to the result bank once, at the end of the pass. Checked:
// the pass time of pass_timing.h equals the cycle-level model's and the fast model's, to the cycle,
// for several lane / bank / width configurations (and hand-worked values for some); the result
// words equal those of the wrapper that keeps its results in the bank; a batch is limited by the
// block RAM left over, and a batch split to fit gives the bits of the unsplit one; the profile
// fields are read and checked.
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "board/board_params.h"
#include "board/cycle_wrapper.h"
#include "board/device_profile.h"
#include "tests/board/board_test_support.h"
#include "profiles/profile_json.h"

namespace rc::board::test {
namespace {

BoardParams on_chip(BoardParams p, std::uint64_t store_bits = 1u << 20) {
  p.results = ResultStore::on_chip;
  p.result_store_bits = store_bits;
  return p;
}

struct Step {
  PassData data;
  bool clear = true;
};

// One board running `steps` one after another from a scripted host.
struct Bench {
  std::unique_ptr<Rc2000> board;
  std::unique_ptr<ScriptedHost> host;
  std::vector<PassRecord> passes;
  std::vector<std::vector<std::uint8_t>> blocked;       // per step, read back from the result bank
  std::vector<std::vector<std::uint64_t>> result_words;  // per step, the result bank's words

  Bench(const std::string& name, const BoardParams& params, const std::vector<Step>& steps) {
    board = std::make_unique<Rc2000>(name.c_str(), params);
    board->wrapper().on_pass([this](const PassRecord& r) { passes.push_back(r); });
    host = std::make_unique<ScriptedHost>((name + "_host").c_str(), *board, [this, steps](ScriptedHost& h) {
      for (const Step& s : steps) {
        blocked.push_back(run_pass(h, s.data, s.clear));
        const BankLayout& L = board->layout();
        const RaySplit split = split_rays(L, s.data.ends.size());
        const std::vector<std::uint8_t> bytes =
            board->bank(L.result_bank).debug_bytes(0, split.result_words * (L.word_bits / 8));
        std::vector<std::uint64_t> words;
        for (std::uint64_t w = 0; w < split.result_words; ++w) words.push_back(load_word(bytes.data(), w, L.word_bits / 8));
        result_words.push_back(words);
      }
    });
  }
  // The formula's cycles for step i on this board.
  PassTiming formula(const Step& s) const {
    const BankLayout& L = board->layout();
    return pass_timing(L, board->params().timing, split_rays(L, s.data.ends.size()), s.data.faces.size(), s.clear);
  }
};

void run_until_finished(const std::vector<Bench*>& benches) { test::run_until_finished(hosts_of(benches)); }

// The CPU's answer for each step: a pass that does not clear ORs onto the previous step's words
// (the steps that do so reuse the previous step's rays).
std::vector<std::vector<std::uint8_t>> expected(const std::vector<Step>& steps, int bits) {
  std::vector<std::vector<std::uint8_t>> out;
  for (const Step& s : steps) {
    std::vector<std::uint8_t> e = expected_blocked(s.data, bits);
    if (!s.clear)
      for (std::size_t r = 0; r < e.size(); ++r) e[r] |= out.back()[r];
    out.push_back(e);
  }
  return out;
}

// A clearing pass of 37 rays on one face; 100 rays on 5 faces with own-face masks and the shooter's
// face; the same 100 rays against 3 other faces without CLEAR (ORed onto the previous words); 1 ray.
std::vector<Step> steps_for(int bits) {
  std::vector<Step> steps;
  steps.push_back({crossing_pass(37, bits, 1, 37), true});
  PassData masked = crossing_pass(100, bits, 5, 700);
  masked.source_face = 2;
  steps.push_back({masked, true});
  PassData other = masked;
  other.faces = crossing_pass(1, bits, 3, 9).faces;
  other.end_faces.assign(other.ends.size(), -1);
  other.source_face = -1;
  steps.push_back({other, false});
  steps.push_back({crossing_pass(1, bits, 1, 1), true});
  return steps;
}

struct Config {
  const char* name;
  unsigned lanes;
  int bits;
  unsigned banks;
  sc_time bank_period;
};

// 1 and 2 lanes at 15 bits (2 lanes share a result word), 2 lanes at 31 bits on 6 banks (one lane per
// word, the second lane's group in one bank at 1/3 rate), 3 lanes at 15 bits on 8 banks (a 2-lane and
// a 1-lane group), and 2 lanes with banks slower than the device (the ray banks stall the lanes).
const std::vector<Config> kConfigs = {{"l1b15", 1, 15, 6, sc_time(10, SC_NS)},
                                      {"l2b15", 2, 15, 6, sc_time(10, SC_NS)},
                                      {"l2b31", 2, 31, 6, sc_time(10, SC_NS)},
                                      {"l3b15", 3, 15, 8, sc_time(10, SC_NS)},
                                      {"l2slow", 2, 15, 6, sc_time(25, SC_NS)}};

BoardParams params_for(const Config& c, WrapperModel model) {
  BoardParams p = round_params(c.lanes, c.bits, c.banks, model);
  p.timing.bank_period = c.bank_period;
  return p;
}

// Formula = cycle-level model = fast model, every step of every configuration, to the cycle; and the
// bank traffic of the formula is what both models reported to the banks.
TEST(ResultsOnChip, FormulaCycleModelAndFastModelAgree) {
  std::vector<std::unique_ptr<Bench>> fast, cycle;
  std::vector<std::vector<Step>> steps;
  std::vector<Bench*> all;
  for (const Config& c : kConfigs) {
    steps.push_back(steps_for(c.bits));
    fast.push_back(std::make_unique<Bench>(std::string("fast_") + c.name, on_chip(params_for(c, WrapperModel::fast)),
                                           steps.back()));
    cycle.push_back(std::make_unique<Bench>(std::string("cycle_") + c.name,
                                            on_chip(params_for(c, WrapperModel::cycle)), steps.back()));
    all.push_back(fast.back().get());
    all.push_back(cycle.back().get());
  }
  run_until_finished(all);

  for (std::size_t i = 0; i < kConfigs.size(); ++i) {
    const Bench& f = *fast[i];
    const Bench& c = *cycle[i];
    ASSERT_EQ(f.passes.size(), steps[i].size()) << kConfigs[i].name;
    ASSERT_EQ(c.passes.size(), steps[i].size()) << kConfigs[i].name;
    ASSERT_EQ(f.board->layout().results, ResultStore::on_chip);
    std::uint64_t reads = 0, writes = 0;
    for (std::size_t s = 0; s < steps[i].size(); ++s) {
      const PassTiming t = f.formula(steps[i][s]);
      EXPECT_EQ(f.passes[s].error, reg::kOk) << kConfigs[i].name << " step " << s;
      EXPECT_EQ(f.passes[s].cycles, t.total) << kConfigs[i].name << " step " << s;
      EXPECT_EQ(c.passes[s].cycles, t.total) << kConfigs[i].name << " step " << s;
      EXPECT_EQ(f.passes[s].end - f.passes[s].start, c.passes[s].end - c.passes[s].start);
      EXPECT_EQ(f.passes[s].limit, c.passes[s].limit);
      EXPECT_EQ(f.passes[s].lane_rays, c.passes[s].lane_rays);
      EXPECT_EQ(f.blocked[s], c.blocked[s]) << kConfigs[i].name << " step " << s;
      EXPECT_EQ(f.result_words[s], c.result_words[s]) << kConfigs[i].name << " step " << s;
      // No result-bank term can bound the stream any more.
      EXPECT_EQ(f.passes[s].limit.find("results"), std::string::npos) << f.passes[s].limit;
      reads += t.banks[f.board->layout().result_bank].reads;
      writes += t.banks[f.board->layout().result_bank].writes;
    }
    for (const Bench* b : {&f, &c}) {
      const tlmx::SramBankReport r = b->board->bank(b->board->layout().result_bank).report();
      EXPECT_EQ(r.reads, reads) << kConfigs[i].name;
      EXPECT_EQ(r.writes, writes) << kConfigs[i].name;
    }
    const std::vector<std::vector<std::uint8_t>> want = expected(steps[i], kConfigs[i].bits);
    for (std::size_t s = 0; s < steps[i].size(); ++s) EXPECT_EQ(f.blocked[s], want[s]) << kConfigs[i].name << " step " << s;
  }

  // Worked by hand (device 20 ns, banks 10 ns: fetch = ceil((2 + 9) / 2) = 6; drain = to_dev(sum P_g a_g)):
  //   1 lane, 37 rays, 1 face, CLEAR: 2 + 1 + 6 + 37 (stream) + 37 + ceil(37 / 2) = 19 (drain) + 1 = 103
  EXPECT_EQ(fast[0]->passes[0].cycles, 103u);
  //   2 lanes, 37 rays (19 packets): 2 + 7 + 19 + 37 + ceil(19 / 2) = 10 + 1 = 76
  EXPECT_EQ(fast[1]->passes[0].cycles, 76u);
  //   2 lanes, 100 rays (50 packets), 3 faces, no CLEAR: the drain reads and writes each shared word:
  //   2 + 3 * 7 + 3 * 50 + 37 + to_dev(2 * 50) = 50 + 1 = 261
  EXPECT_EQ(fast[1]->passes[2].cycles, 261u);
  //   2 lanes, banks at 25 ns: fetch ceil(11 * 1.25) = 14, stream = to_dev(50 ray words) = 63 every face
  //   (in the bank the result bank's read-modify-writes took to_dev(100) = 125 after the first face);
  //   5 faces, CLEAR: 2 + 5 * 15 + 5 * 63 + 37 + to_dev(50) = 63 + 1 = 493 (678 with results in the bank)
  EXPECT_EQ(fast[4]->passes[1].cycles, 493u);
  EXPECT_EQ(fast[4]->passes[1].limit, "bank 1 (rays g0 X)");
  BankLayout in_bank = fast[4]->board->layout();
  in_bank = place_results(in_bank, ResultStore::bank, 0);
  EXPECT_EQ(pass_timing(in_bank, fast[4]->board->params().timing, split_rays(in_bank, 100), 5, true).total, 678u);
}

// The same passes on boards that keep their results in the bank and on chip, fast and cycle-level:
// the same blocked bits and the same result words, CLEAR or not. Under the nominal split, which does
// not depend on where the results are: the limit split follows the result bank's accesses only when
// the results are in the bank, so its packets (and so its words) may differ on chip (docs/board.md,
// "Ray split"); the blocked bits are the same under either (RaySplit.FormulaAndCycleModelAgreeUnderEitherSplit).
TEST(ResultsOnChip, SameResultWordsAsResultsInTheBank) {
  auto params_for = [](const Config& c, WrapperModel model) {
    BoardParams p = test::params_for(c, model);
    p.ray_split = RaySplitRule::nominal;
    return p;
  };
  struct Four {
    std::unique_ptr<Bench> bank_fast, bank_cycle, chip_fast, chip_cycle;
  };
  std::vector<Four> boards;
  std::vector<Bench*> all;
  const std::vector<Config> configs = {kConfigs[1], kConfigs[2], kConfigs[3]};
  for (const Config& c : configs) {
    const std::vector<Step> steps = steps_for(c.bits);
    const std::string n = c.name;
    Four f;
    f.bank_fast = std::make_unique<Bench>("bank_fast_" + n, params_for(c, WrapperModel::fast), steps);
    f.bank_cycle = std::make_unique<Bench>("bank_cycle_" + n, params_for(c, WrapperModel::cycle), steps);
    f.chip_fast = std::make_unique<Bench>("chip_fast_" + n, on_chip(params_for(c, WrapperModel::fast)), steps);
    f.chip_cycle = std::make_unique<Bench>("chip_cycle_" + n, on_chip(params_for(c, WrapperModel::cycle)), steps);
    for (Bench* b : {f.bank_fast.get(), f.bank_cycle.get(), f.chip_fast.get(), f.chip_cycle.get()}) all.push_back(b);
    boards.push_back(std::move(f));
  }
  run_until_finished(all);
  for (std::size_t i = 0; i < configs.size(); ++i) {
    const Four& f = boards[i];
    ASSERT_EQ(f.bank_fast->board->layout().results, ResultStore::bank);
    ASSERT_EQ(f.bank_fast->blocked.size(), 4u);
    const std::vector<std::vector<std::uint8_t>> want = expected(steps_for(configs[i].bits), configs[i].bits);
    for (const Bench* b : {f.bank_cycle.get(), f.chip_fast.get(), f.chip_cycle.get()}) {
      EXPECT_EQ(b->blocked, f.bank_fast->blocked) << configs[i].name;
      EXPECT_EQ(b->result_words, f.bank_fast->result_words) << configs[i].name;
    }
    EXPECT_EQ(f.bank_fast->blocked, want) << configs[i].name;
  }
}

// A profile whose block RAM holds 101 bits: two lanes at 15 bits keep one 2-bit entry per packet, so
// a batch holds 100 rays (101 would need 51 entries, 102 bits); the banks alone would take 2^21.
// A pass of 101 rays is refused (kTooManyRays); split into 100 + 1 it gives the bits of one pass of
// 101 rays on the board that keeps its results in the bank.
TEST(ResultsOnChip, BatchesSplitWhenTheBlockRamIsTooSmall) {
  nlohmann::ordered_json j = rc::profiles::json_of(find_device_profile("xc2v6000").document);
  j["fpga"]["block_ram_bits"] = {{"value", 101}, {"source", "test: a block RAM too small for one batch"}};
  j["wrapper"]["results"] = {{"value", "on_chip"}, {"source", "test"}};
  const DeviceProfile tiny = device_profile_from_document(rc::profiles::document_of(j), "tiny-bram.json");
  EXPECT_EQ(tiny.block_ram_bits, 101u);
  EXPECT_EQ(tiny.results, ResultStore::on_chip);
  BoardChoices choices;
  choices.lanes = 2;
  const BoardParams chip = make_board_params(tiny, choices);
  EXPECT_EQ(chip.result_store_bits, 101u);  // the design uses no block RAM (design_fit.h)
  const BankLayout L = make_bank_layout(chip);
  EXPECT_EQ(L.max_rays_per_batch, 100u);
  for (std::uint64_t r = 0; r <= 100; ++r) EXPECT_TRUE(split_rays(L, r).fits) << r;
  EXPECT_FALSE(split_rays(L, 101).fits);
  EXPECT_EQ(result_store_bits(L, split_rays(L, 99)), 100u);  // 50 entries of 2 bits, one slot unused

  BoardParams bank = chip;
  bank.results = ResultStore::bank;
  EXPECT_EQ(make_bank_layout(bank).max_rays_per_batch, std::uint64_t{1} << 21);
  // The real profile's block RAM (2,654,208 bits) holds more than the banks: the banks' limit stays.
  DeviceProfile real = find_device_profile("xc2v6000");
  real.results = ResultStore::on_chip;
  EXPECT_EQ(make_bank_layout(make_board_params(real, choices)).max_rays_per_batch, std::uint64_t{1} << 21);

  const int bits = 15;
  const PassData whole = crossing_pass(101, bits, 1, 5);
  PassData first = whole, second = whole;
  first.ends.resize(100);
  first.end_faces.resize(100);
  second.ends.erase(second.ends.begin(), second.ends.begin() + 100);
  second.end_faces.erase(second.end_faces.begin(), second.end_faces.begin() + 100);

  Bench in_bank("in_bank", bank, {{whole, true}});
  std::uint32_t refused_status = 0, refused_code = 0;
  std::vector<std::vector<std::uint8_t>> split_bits;
  Rc2000 board("on_chip", chip);
  ScriptedHost host("on_chip_host", board, [&](ScriptedHost& h) {
    (void)load_pass(board, whole);
    h.write(reg::kRayCount, {101, 1, 0, reg::kNoFace, static_cast<std::uint32_t>(whole.start.x),
                             static_cast<std::uint32_t>(whole.start.y), static_cast<std::uint32_t>(whole.start.z), 101});
    h.write(reg::kControl, {reg::kStart | reg::kClear});
    board.irq.wait_raised();
    refused_status = h.read(reg::kStatus);
    refused_code = h.read(reg::kErrorCode);
    h.write(reg::kStatus, {reg::kDone | reg::kError});
    split_bits.push_back(run_pass(h, first));
    split_bits.push_back(run_pass(h, second));
  });
  while (!(host.finished && in_bank.host->finished)) sc_core::sc_start(sc_time(10, SC_US));
  sc_core::sc_stop();

  EXPECT_NE(refused_status & reg::kError, 0u);
  EXPECT_EQ(refused_code, reg::kTooManyRays);
  ASSERT_EQ(split_bits.size(), 2u);
  std::vector<std::uint8_t> joined = split_bits[0];
  joined.insert(joined.end(), split_bits[1].begin(), split_bits[1].end());
  ASSERT_EQ(in_bank.blocked.size(), 1u);
  EXPECT_EQ(joined, in_bank.blocked[0]);
  EXPECT_EQ(joined, expected_blocked(whole, bits));
}

void expect_invalid(const std::function<void()>& f, std::initializer_list<const char*> parts) {
  try {
    f();
    ADD_FAILURE() << "no error";
  } catch (const std::invalid_argument& e) {
    for (const char* p : parts) EXPECT_NE(std::string(e.what()).find(p), std::string::npos) << e.what() << " lacks " << p;
  }
}

// Every shipped profile has both fields; a missing or mistyped one names the file and the field.
TEST(ResultsOnChip, ProfileFieldsAreReadAndChecked) {
  for (const char* name : {"xc2v6000", "virtex4-sx55", "spartan3-5000"}) {
    const DeviceProfile p = find_device_profile(name);
    EXPECT_EQ(p.results, ResultStore::bank) << name;  // today's design is the default everywhere
    EXPECT_EQ(p.block_ram_bits % 18432, 0u) << name;  // whole 18-Kbit blocks
  }
  EXPECT_EQ(find_device_profile("xc2v6000").block_ram_bits, 144u * 18432);
  EXPECT_EQ(find_device_profile("virtex4-sx55").block_ram_bits, 320u * 18432);
  EXPECT_EQ(find_device_profile("spartan3-5000").block_ram_bits, 104u * 18432);

  const nlohmann::ordered_json good = rc::profiles::json_of(find_device_profile("xc2v6000").document);
  nlohmann::ordered_json j = good;
  j["fpga"].erase("block_ram_bits");
  expect_invalid([&] { device_profile_from_document(rc::profiles::document_of(j), "p.json"); }, {"p.json", "fpga.block_ram_bits: missing"});
  j = good;
  j["wrapper"].erase("results");
  expect_invalid([&] { device_profile_from_document(rc::profiles::document_of(j), "p.json"); }, {"p.json", "wrapper.results", "missing", "bank, on_chip"});
  j = good;
  j["wrapper"]["results"]["value"] = "bram";
  expect_invalid([&] { device_profile_from_document(rc::profiles::document_of(j), "p.json"); },
                 {"p.json", "wrapper.results", "'bram' is not one of bank, on_chip"});
  j = good;
  j["wrapper"]["results"] = "on_chip";
  expect_invalid([&] { device_profile_from_document(rc::profiles::document_of(j), "p.json"); }, {"p.json", "wrapper.results", "source"});
  j = good;
  j["wrapper"]["results"]["source"] = "";
  expect_invalid([&] { device_profile_from_document(rc::profiles::document_of(j), "p.json"); }, {"p.json", "wrapper.results", "source"});

  // Results on chip on a device with no block RAM left: an error before any board is made.
  j = good;
  j["fpga"]["block_ram_bits"]["value"] = 0;
  j["wrapper"]["results"]["value"] = "on_chip";
  const DeviceProfile none = device_profile_from_document(rc::profiles::document_of(j), "none.json");
  expect_invalid([&] { make_board_params(none, BoardChoices{}); }, {"none.json", "on_chip", "0 block RAM bits"});
  expect_invalid([&] { place_results(make_bank_layout(1, 6, 15, 32, 1u << 20), ResultStore::on_chip, 0); },
                 {"block RAM"});
}

}  // namespace
}  // namespace rc::board::test
