#include "host_sw/driver/multi_card_visibility.h"

#include <algorithm>
#include <stdexcept>

#include "host_sw/driver/trace_writer.h"

// The driver threads are spawned (one per card, sc_spawn), so the dynamic-process part of SystemC
// is needed here; <systemc> includes it on a second inclusion with this defined.
#define SC_INCLUDE_DYNAMIC_PROCESSES
#include <systemc>

namespace rc {

using sc_core::sc_time;

CardShare card_share(std::size_t total, unsigned cards, unsigned card) {
  if (cards == 0 || card >= cards) throw std::invalid_argument("card_share: card out of range");
  const std::size_t first = total * card / cards;
  return {first, total * (card + 1) / cards - first};
}

namespace {

// The card's part of an answer the host already has: what its lanes copy (the oracle seam of
// BoardVisibility). It answers only a batch of the size it was given.
class CardAnswer : public VisibilityBackend {
 public:
  std::vector<std::uint8_t> answer;  // in the card's segment order

  std::string name() const override { return "card answer"; }
  void load_triangles(const std::vector<Triangle>& ) override {}
  void submit(const SegmentBatch& batch) override {
    if (batch.size() != answer.size()) throw std::logic_error("a card's answer is for another batch");
  }
  void collect(std::vector<std::uint8_t>& blocked) override { blocked = answer; }
  std::uint64_t tests_performed() const override { return 0; }
};

// Global face g on a card holding [first, first + count): its local index, or -1 before the card's
// faces and `count` after them (monotone, so rays stay grouped by end face in face order).
// Face g as the card holding `faces` sees it: the first of its sheet's faces on the card when the
// sheet reaches the card (the own-surface rule only asks which sheet a face is on), else "before"
// (-1) or "after" (the card's face count) its faces. A one-sided face on the card is itself.
int local_face(int g, const CardShare& faces, const FaceSheets& sheets) {
  if (g < 0) return -1;
  const int first = static_cast<int>(faces.first), last = first + static_cast<int>(faces.count);
  const int lo = std::max(sheets.first(g), first), hi = std::min(sheets.end(g), last);
  if (lo < hi) return lo - first;
  return g < first ? -1 : static_cast<int>(faces.count);
}

}  // namespace

class MultiCardVisibility::Turn : public BusTurn {
 public:
  Turn(MultiCardVisibility& owner, unsigned card) : owner_(owner), card_(card) {}
  void acquire() override { owner_.acquire_bus(card_); }
  void release() override { owner_.release_bus(card_); }

 private:
  MultiCardVisibility& owner_;
  unsigned card_;
};

struct MultiCardVisibility::Card {
  std::unique_ptr<HostCpuModel> cpu;
  std::unique_ptr<Turn> turn;
  CardAnswer answer;
  std::unique_ptr<BoardVisibility> driver;
  CardShare faces;     // of the scene (every face with the rays split)
  CardShare segments;  // of the current step (every segment with the faces split)
  std::vector<Triangle> triangles;
  FaceSheets sheets;   // of the card's faces (FaceSheets::restricted)
  SegmentBatch batch;
  std::size_t timing_segments = 0;
  int timing_source = -1;
  std::vector<std::uint8_t> blocked;
  Job job = Job::none;
  bool started = false;
  std::exception_ptr error;
  sc_core::sc_event go;
  sc_time idle = sc_core::SC_ZERO_TIME, last_done = sc_core::SC_ZERO_TIME;
};

MultiCardVisibility::MultiCardVisibility(std::vector<BoardPorts> ports, HostCpuModel& host,
                                         BoardVisibilityOptions options, CardSplit split, TraceWriter* trace)
    : host_(host), options_(options), split_(split), trace_(trace) {
  if (ports.size() < 2) throw std::invalid_argument("MultiCardVisibility needs at least two cards");
  // Each driver on its own processor: a copy of the host's profile. It computes no form factors,
  // so the dual-processor overlap (a property of the solver's processor) is not its concern.
  HostProfile profile = host.profile();
  profile.driver_model.overlap = DriverModel::Overlap::FormFactors;
  for (std::size_t c = 0; c < ports.size(); ++c) {
    auto card = std::make_unique<Card>();
    card->cpu = std::make_unique<HostCpuModel>(profile);
    const std::string prefix = "card " + std::to_string(c) + " ";
    if (trace != nullptr) card->cpu->set_trace(trace, prefix + "host");
    BoardVisibilityOptions o = options;
    o.concurrent = true;  // submit() returns at the first START: the thread then tells the host
    o.oracle = options.oracle != nullptr ? &card->answer : nullptr;
    o.trace_prefix = prefix;
    card->turn = std::make_unique<Turn>(*this, static_cast<unsigned>(c));
    o.bus_turn = card->turn.get();  // cards sharing a bus reserve it in time order, ties in a fixed order
    card->driver = std::make_unique<BoardVisibility>(std::move(ports[c]), *card->cpu, o, trace);
    cards_.push_back(std::move(card));
  }
  pending_.assign(cards(), false);
  arrived_.assign(cards(), 0);
  for (unsigned c = 0; c < cards(); ++c) {
    sc_core::sc_spawn([this, c] { card_thread(c); }, ("card" + std::to_string(c) + "_driver").c_str());
  }
}

MultiCardVisibility::~MultiCardVisibility() = default;

const BoardVisibility& MultiCardVisibility::driver(unsigned card) const { return *cards_.at(card)->driver; }
const HostCpuModel& MultiCardVisibility::cpu(unsigned card) const { return *cards_.at(card)->cpu; }
std::size_t MultiCardVisibility::faces(unsigned card) const { return cards_.at(card)->faces.count; }

sc_time MultiCardVisibility::idle(unsigned card, const sc_time& end) const {
  const Card& k = *cards_.at(card);
  return k.idle + (k.job == Job::none && end > k.last_done ? end - k.last_done : sc_core::SC_ZERO_TIME);
}

std::uint64_t MultiCardVisibility::tests_performed() const {
  std::uint64_t tests = 0;
  for (const auto& k : cards_) tests += k->driver->tests_performed();
  return tests;
}

void MultiCardVisibility::pass_finished(unsigned card, const board::PassRecord& record) {
  cards_.at(card)->driver->pass_finished(record);
  step_passes_.emplace_back(record.start, record.end);
}

// ---- the cards' threads -----------------------------------------------------------------------------

// Waits for a job, runs it on the card's driver, and tells the host when the card has STARTed its
// first pass and when it is done. The driver's local time is synced before each message, so the
// host sees it when it happens.
void MultiCardVisibility::card_thread(unsigned c) {
  Card& k = *cards_[c];
  for (;;) {
    const sc_time from = sc_core::sc_time_stamp();
    while (k.job == Job::none) sc_core::wait(k.go);
    k.idle += sc_core::sc_time_stamp() - from;
    try {
      switch (k.job) {
        case Job::load:
          k.driver->load_faces(k.triangles, k.sheets);
          break;
        case Job::step:
          k.driver->submit(k.batch);
          card_started(k);
          k.driver->collect(k.blocked);
          break;
        case Job::timing_step:
          k.driver->submit_timing_only(k.timing_segments, k.timing_source);
          card_started(k);
          k.driver->collect_timing_only();
          break;
        case Job::none:
          break;
      }
      k.cpu->sync();
    } catch (...) {
      k.error = std::current_exception();
    }
    k.job = Job::none;
    k.last_done = sc_core::sc_time_stamp();
    progress_.notify();
  }
}

void MultiCardVisibility::card_started(Card& k) {
  k.cpu->sync();
  k.started = true;
  progress_.notify();
}

// The bus arbitrates in call order. Two cards whose accesses are requested at the same time would
// reach it in whatever order the scheduler runs their threads, which depends on every other event
// of the simulation (a timing study runs many systems side by side). So a card asks, waits a delta
// cycle, and goes when no card that asked in an earlier delta cycle, or in the same one with a
// lower number, still waits for or holds its turn. Only asks from earlier delta cycles are looked
// at, so what a card sees does not depend on the order of the threads within a delta cycle. The
// driver's local time is synced first, so all of this happens at the access's time.
void MultiCardVisibility::acquire_bus(unsigned c) {
  pending_[c] = true;
  arrived_[c] = sc_core::sc_delta_count();
  const auto before = [&](unsigned d) {
    return d != c && pending_[d] && (arrived_[d] < arrived_[c] || (arrived_[d] == arrived_[c] && d < c));
  };
  for (;;) {
    sc_core::wait(sc_core::SC_ZERO_TIME);
    bool blocked = false;
    for (unsigned d = 0; d < cards(); ++d) blocked = blocked || before(d);
    if (!blocked) return;
    sc_core::wait(released_);
  }
}

void MultiCardVisibility::release_bus(unsigned c) {
  pending_[c] = false;
  released_.notify(sc_core::SC_ZERO_TIME);
}

// ---- the host's side --------------------------------------------------------------------------------

void MultiCardVisibility::hand_out(Job job) {
  host_.sync();  // the cards start at the host's time
  for (auto& k : cards_) {
    k->cpu->set_step(host_.step());
    k->started = false;
    k->job = job;
    k->go.notify();
  }
}

void MultiCardVisibility::wait_for_cards(bool started_is_enough) {
  auto ready = [&] {
    for (const auto& k : cards_) {
      if (k->job != Job::none && !(started_is_enough && k->started)) return false;
    }
    return true;
  };
  host_.sync();  // the host's own work (form factors between submit and collect) comes first
  const sc_time from = sc_core::sc_time_stamp();
  while (!ready()) sc_core::wait(progress_);
  const sc_time now = sc_core::sc_time_stamp();
  waiting_ += now - from;
  if (trace_ != nullptr && trace_->wants(host_.step()) && now > from) {
    trace_->complete("host", started_is_enough ? "wait for the cards' START" : "wait for the cards", from, now);
  }
  for (auto& k : cards_) {
    if (k->error) std::rethrow_exception(std::exchange(k->error, nullptr));
  }
}

void MultiCardVisibility::load_triangles(const std::vector<Triangle>& faces) {
  if (options_.oracle != nullptr) options_.oracle->load_faces(faces, sheets());
  for (unsigned c = 0; c < cards(); ++c) {
    Card& k = *cards_[c];
    k.faces = split_ == CardSplit::faces ? card_share(faces.size(), cards(), c) : CardShare{0, faces.size()};
    k.triangles.assign(faces.begin() + static_cast<long>(k.faces.first),
                       faces.begin() + static_cast<long>(k.faces.first + k.faces.count));
    k.sheets = sheets().restricted(static_cast<int>(k.faces.first), static_cast<int>(k.faces.count));
  }
  hand_out(Job::load);
  wait_for_cards(false);
}

void MultiCardVisibility::submit(const SegmentBatch& batch) {
  batch.check();
  rays_ = batch.size();
  if (options_.oracle != nullptr) {
    options_.oracle->submit(batch);
    options_.oracle->collect(answer_);
  }
  for (unsigned c = 0; c < cards(); ++c) {
    Card& k = *cards_[c];
    SegmentBatch& b = k.batch;
    b.start = batch.start;
    b.shooter = -1;  // a part of a batch: no promise about other steps
    if (split_ == CardSplit::rays) {
      k.segments = card_share(rays_, cards(), c);
      const auto first = static_cast<long>(k.segments.first), last = first + static_cast<long>(k.segments.count);
      b.source_face = batch.source_face;
      b.ends.assign(batch.ends.begin() + first, batch.ends.begin() + last);
      b.end_faces.assign(batch.end_faces.begin() + first, batch.end_faces.begin() + last);
      if (batch.needed.empty()) {
        b.needed.clear();
      } else {
        b.needed.assign(batch.needed.begin() + first, batch.needed.begin() + last);
      }
      if (options_.oracle != nullptr) k.answer.answer.assign(answer_.begin() + first, answer_.begin() + last);
    } else {
      k.segments = {0, rays_};
      b.source_face = local_face(batch.source_face, k.faces, sheets());
      if (b.source_face == static_cast<int>(k.faces.count)) b.source_face = -1;  // not on this card
      b.ends = batch.ends;
      b.end_faces.resize(rays_);
      for (std::size_t i = 0; i < rays_; ++i) b.end_faces[i] = local_face(batch.end_faces[i], k.faces, sheets());
      b.needed = batch.needed;
      if (options_.oracle != nullptr) {
        if (c == 0) {
          k.answer.answer = answer_;
        } else {
          k.answer.answer.assign(rays_, 0);
        }
      }
    }
  }
  begin_step(Job::step);
}

void MultiCardVisibility::submit_timing_only(std::size_t segments, int source_face) {
  rays_ = segments;
  for (unsigned c = 0; c < cards(); ++c) {
    Card& k = *cards_[c];
    if (split_ == CardSplit::rays) {
      k.segments = card_share(segments, cards(), c);
      k.timing_source = source_face;
    } else {
      k.segments = {0, segments};
      k.timing_source = local_face(source_face, k.faces, sheets());
      if (k.timing_source == static_cast<int>(k.faces.count)) k.timing_source = -1;
    }
    k.timing_segments = k.segments.count;
  }
  begin_step(Job::timing_step);
}

// Every card gets its share at once (the host's time); then, as one card's driver does: serial,
// wait for the answers; concurrent, return when the cards have STARTed (or at once, with the form
// factors on the second processor).
void MultiCardVisibility::begin_step(Job job) {
  hand_out(job);
  host_.clear_intervals();
  step_passes_.clear();
  if (!options_.concurrent) {
    wait_for_cards(false);
  } else if (host_.profile().driver_model.overlap == DriverModel::Overlap::DualCpu) {
    host_.fork_second_cpu();
  } else {
    wait_for_cards(true);
  }
}

// Host compute that overlapped any card's pass of the step (the union of the passes, so two cards
// working at once count once).
void MultiCardVisibility::finish_step() {
  wait_for_cards(false);
  host_.join_second_cpu();
  std::sort(step_passes_.begin(), step_passes_.end());
  std::size_t i = 0;
  while (i < step_passes_.size()) {
    sc_time from = step_passes_[i].first, to = step_passes_[i].second;
    for (++i; i < step_passes_.size() && step_passes_[i].first <= to; ++i) to = std::max(to, step_passes_[i].second);
    overlap_ += host_.overlap(from, to);
  }
  step_passes_.clear();
}

void MultiCardVisibility::collect(std::vector<std::uint8_t>& blocked) {
  finish_step();
  blocked.assign(rays_, 0);
  for (const auto& k : cards_) {
    if (split_ == CardSplit::rays) {
      std::copy(k->blocked.begin(), k->blocked.end(), blocked.begin() + static_cast<long>(k->segments.first));
    } else {
      for (std::size_t i = 0; i < rays_; ++i) blocked[i] |= k->blocked[i];
    }
  }
}

void MultiCardVisibility::collect_timing_only() { finish_step(); }

}  // namespace rc
