// Several RC2000 cards answering one scene's visibility (paper sec 6: "several FPGA cards working
// simultaneously on the same scene"), as one visibility backend for the solver.
//
// Each card keeps its own driver, the unchanged BoardVisibility protocol (upload, START, wait for
// ITS interrupt, read back), run by its own SC_THREAD and charging its CPU work to its own
// HostCpuModel on a copy of the host profile: as if each card's driver ran on its own processor
// (exact for two cards on the paper's dual Athlon MP host, optimistic beyond). The solver's thread
// hands every card its share of a step at once and waits for all of them, so no card waits for
// another's uploads; on a shared bus their transfers contend through the bus's arbitration.
//
// Splits (contiguous shares, sizes differing by at most one):
//   rays   card c gets a share of the step's segments and holds every face; results concatenated.
//   faces  card c holds a share of the faces and gets every segment; a segment is blocked if any
//          card blocks it. Face indices are mapped to the card's: end faces and the source face whose
//          sheet reaches the card become the local index of the sheet's first face there, the others
//          "before" (-1) or "after" (the card's face count) its faces, and each card holds its part
//          of every sheet, so the own-surface rule skips exactly the faces it skips on one card.
//
// Modes, as one card's (host_sw/driver/board_visibility.h): serial, submit() waits until every card has its
// answer. Concurrent (sec 4.3), overlap FormFactors: submit() returns when every card has STARTed
// its first pass, and the solver computes form factors while the cards work; overlap DualCpu: the
// form factors go to the host's second processor from the hand-off (HostCpuModel::fork_second_cpu).
// collect() waits for every card.
//
// The solver's thread does no driver work: its timeline is its own compute plus waiting() for the
// cards; each card's driver thread: driver CPU + PCI + interrupt waiting + idle (waiting for work).
//
// With an oracle (BoardVisibilityOptions::oracle) the whole step's answer is asked once on the
// host thread, and each card's lanes copy their part: the rays split, the card's segments; the
// faces split, card 0 copies the whole answer and the others an all-clear one (a whole-scene model
// cannot say which card's faces block a segment). The OR the host sees, every time and every
// transfer are those of lanes that compute.
#pragma once

#include <cstdint>
#include <exception>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <systemc>

#include "io/choice.h"
#include "host_sw/driver/board_visibility.h"
#include "host_sw/driver/host_cpu_model.h"
#include "host_sw/driver/timing_replay_target.h"
#include "host_sw/radiosity/visibility.h"

namespace rc {

class TraceWriter;

// rays: each card a share of a step's segments, every face; faces: each card a share of the faces,
// every segment. Named by ChoiceNames<CardSplit> (below), printed and parsed by io/choice.h.
enum class CardSplit { rays, faces };

}  // namespace rc

template <>
struct rc::ChoiceNames<rc::CardSplit> {
  static constexpr std::string_view what = "card split";
  static constexpr std::array<std::string_view, 2> names = {"rays", "faces"};
};

namespace rc {

// Card `card` of `cards` gets [first, first + count) of `total` items: contiguous and balanced.
struct CardShare {
  std::size_t first = 0, count = 0;
};
CardShare card_share(std::size_t total, unsigned cards, unsigned card);

class MultiCardVisibility : public VisibilityBackend, public TimingReplayTarget {
 public:
  // One driver per element of `ports` (at least two). `options` are every driver's; its oracle,
  // if any, is asked here. The driver threads are spawned here: construct during elaboration.
  MultiCardVisibility(std::vector<BoardPorts> ports, HostCpuModel& host, BoardVisibilityOptions options, CardSplit split,
                      TraceWriter* trace = nullptr);
  ~MultiCardVisibility() override;

  // The platform calls this when card `card`'s wrapper finishes a pass.
  void pass_finished(unsigned card, const board::PassRecord& record);

  std::string name() const override { return "board x " + std::to_string(cards()); }
  void load_triangles(const std::vector<Triangle>& faces) override;
  void submit(const SegmentBatch& batch) override;
  void collect(std::vector<std::uint8_t>& blocked) override;
  std::uint64_t tests_performed() const override;
  bool runs_on_host() const override { return false; }

  void submit_timing_only(std::size_t segments, int source_face) override;
  void collect_timing_only() override;

  unsigned cards() const { return static_cast<unsigned>(cards_.size()); }
  CardSplit split() const { return split_; }
  const BoardVisibility& driver(unsigned card) const;
  const HostCpuModel& cpu(unsigned card) const;  // the card's driver processor
  std::size_t faces(unsigned card) const;        // faces the card holds
  sc_core::sc_time waiting() const { return waiting_; }  // the solver's thread waiting for the cards
  sc_core::sc_time overlap() const { return overlap_; }  // host compute while any card's FPGA worked
  // The card's driver thread waiting for work, from time 0 until `end` (the run's end).
  sc_core::sc_time idle(unsigned card, const sc_core::sc_time& end) const;

 private:
  enum class Job { none, load, step, timing_step };
  struct Card;
  class Turn;

  // The cards' turns at the bus (BusTurn): among accesses requested at the same time, the one
  // that arrived in the earliest delta cycle goes first, then the lowest card number.
  void acquire_bus(unsigned card);
  void release_bus(unsigned card);

  void card_thread(unsigned card);
  void card_started(Card& card);
  void hand_out(Job job);
  void begin_step(Job job);
  void finish_step();
  void wait_for_cards(bool started_is_enough);

  HostCpuModel& host_;
  BoardVisibilityOptions options_;
  CardSplit split_;
  TraceWriter* trace_;
  std::vector<std::unique_ptr<Card>> cards_;
  sc_core::sc_event progress_;  // a card has started its pass or finished its job
  sc_core::sc_event released_;  // a card's bus access is done
  std::vector<bool> pending_;   // a card waits for or holds its turn at the bus
  std::vector<std::uint64_t> arrived_;  // the delta cycle it asked in
  std::size_t rays_ = 0;
  std::vector<std::uint8_t> answer_;  // the oracle's, segment order
  std::vector<std::pair<sc_core::sc_time, sc_core::sc_time>> step_passes_;
  sc_core::sc_time waiting_ = sc_core::SC_ZERO_TIME, overlap_ = sc_core::SC_ZERO_TIME;
};

}  // namespace rc
