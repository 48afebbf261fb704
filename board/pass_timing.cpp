#include "board/pass_timing.h"

#include <algorithm>

namespace rc::board {

std::uint64_t WrapperTiming::to_device(std::uint64_t bank_cycles) const {
  const std::uint64_t pb = bank_period.value(), pd = device_period.value();
  return (bank_cycles * pb + pd - 1) / pd;
}

namespace {

unsigned result_accesses(const RayGroup& g, bool clearing) { return clearing ? 1 : g.result_accesses(); }

// Keeps the largest term and, when asked, its name (the first of equal terms wins).
struct Bound {
  std::string* limit;
  std::uint64_t best = 0;
  bool any = false;
  template <class Name>
  void add(std::uint64_t term, Name name) {
    if (any && term <= best) return;
    best = term;
    any = true;
    if (limit) *limit = name();
  }
};

}  // namespace

std::uint64_t stream_cycles(const BankLayout& layout, const WrapperTiming& t, const RaySplit& split, bool clearing,
                            std::string* limit) {
  Bound b{limit};
  std::uint64_t result = 0;
  for (std::size_t g = 0; g < layout.groups.size(); ++g) {
    const RayGroup& group = layout.groups[g];
    const std::uint64_t P = split.packets[g];
    b.add((3 * P + group.k() - 1) / group.k(), [] { return std::string("lanes"); });
    for (unsigned j = 0; j < group.k(); ++j) {
      const unsigned bank = group.banks[j];
      b.add(t.to_device(group_bank_words(group, j, P)),
            [&] { return "bank " + std::to_string(bank) + " (" + layout.role(bank) + ")"; });
    }
    result += P * result_accesses(group, clearing);
  }
  // On chip the lanes' bits go to block RAM, which keeps up with every group (a read and a write
  // port per group at the device clock); the result bank sees the pass only at its end (drain).
  if (layout.results == ResultStore::bank)
    b.add(t.to_device(result), [&] { return "bank " + std::to_string(layout.result_bank) + " (results)"; });
  return b.best;
}

std::uint64_t drain_accesses(const BankLayout& layout, const RaySplit& split, bool clear) {
  if (layout.results != ResultStore::on_chip) return 0;
  std::uint64_t accesses = 0;
  for (std::size_t g = 0; g < layout.groups.size(); ++g)
    accesses += split.packets[g] * result_accesses(layout.groups[g], clear);
  return accesses;
}

std::uint64_t drain_cycles(const BankLayout& layout, const WrapperTiming& t, const RaySplit& split, bool clear) {
  return t.to_device(drain_accesses(layout, split, clear));
}

std::uint64_t fetch_cycles(const BankLayout& layout, const WrapperTiming& t) {
  const std::uint64_t words = layout.face_words() + (layout.mask_in_face_bank() ? 1 : 0);
  std::uint64_t fetch = t.to_device(t.bank_read_latency + words);
  if (layout.mask_bank) fetch = std::max(fetch, t.to_device(t.bank_read_latency + 1));
  return fetch;
}

PassTiming pass_timing(const BankLayout& layout, const WrapperTiming& t, const RaySplit& split, std::uint64_t faces,
                       bool clear) {
  PassTiming p;
  p.faces = faces;
  p.start = t.pass_start;
  p.face_setup = t.face_setup;
  p.face_fetch = fetch_cycles(layout, t);
  p.stream_first = stream_cycles(layout, t, split, clear);
  p.stream_rest = stream_cycles(layout, t, split, false, &p.limit);
  p.latency = t.pipeline_latency;
  p.drain = faces > 0 ? drain_cycles(layout, t, split, clear) : 0;
  p.finish = t.pass_finish;
  p.total = p.start + faces * (p.face_setup + p.face_fetch) +
            (faces > 0 ? p.stream_first + (faces - 1) * p.stream_rest : 0) + p.latency + p.drain + p.finish;

  // Bank traffic of the whole pass (the fast model reports it to the banks through DMI accounting).
  p.banks.assign(layout.banks_available, BankTraffic{});
  const std::uint64_t face_words = layout.face_words() + (layout.mask_in_face_bank() ? 1 : 0);
  p.banks[layout.face_bank].reads += faces * face_words;
  p.banks[layout.face_bank].busy_bank_cycles += faces * (t.bank_read_latency + face_words);
  if (layout.mask_bank) {
    p.banks[*layout.mask_bank].reads += faces;
    p.banks[*layout.mask_bank].busy_bank_cycles += faces * (t.bank_read_latency + 1);
  }
  for (std::size_t g = 0; g < layout.groups.size(); ++g) {
    const RayGroup& group = layout.groups[g];
    const std::uint64_t P = split.packets[g];
    for (unsigned j = 0; j < group.k(); ++j) {
      const std::uint64_t words = faces * group_bank_words(group, j, P);
      p.banks[group.banks[j]].reads += words;
      p.banks[group.banks[j]].busy_bank_cycles += words;
    }
    BankTraffic& r = p.banks[layout.result_bank];
    if (layout.results == ResultStore::on_chip) {  // the write-out: each word once
      if (faces == 0) continue;
      r.writes += P;
      if (group.result_accesses() == 2 && !clear) r.reads += P;
      continue;
    }
    r.writes += faces * P;
    if (group.result_accesses() == 2 && faces > 0) r.reads += (faces - (clear ? 1 : 0)) * P;
  }
  BankTraffic& r = p.banks[layout.result_bank];
  r.busy_bank_cycles = r.reads + r.writes;
  return p;
}

}  // namespace rc::board
