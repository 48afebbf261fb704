// The time of one pass of the FPGA wrapper (one batch of rays against one set of faces), in device
// clock cycles, as the fast model charges it and the cycle-level model reproduces it. Every term is
// documented in docs/board.md. With Pd the device clock period, Pb the bank clock period and
// to_dev(n) = ceil(n * Pb / Pd) the device cycles n bank cycles take:
//
//   total        = start + F * (setup + fetch) + stream_first + (F - 1) * stream_rest + latency
//                  + drain + finish
//                  (no stream terms and no drain when F = 0)
//   fetch        = to_dev(Lr + 9 + m)            face record (+ own-face word when m = 1: table in the face bank)
//                  max(that, to_dev(Lr + 1))     when the table is in its own bank (read in parallel)
//   stream       = max( ceil(3 * P_g / k_g)                 every group g: P_g packets, k_g banks
//                       to_dev(words of ray bank b)         every ray bank b
//                       to_dev(sum_g P_g * a_g) )           the result bank
//   a_g          = 2 (read-modify-write) when the group's lanes share a result word, else 1;
//                  1 for every group on the first face of a pass that clears the results
//   drain        = 0                                        results in the bank
//
// Results on chip (layout.results == on_chip, docs/board.md "Results on chip"): the lanes OR their
// bits into block RAM, which has a read and a write port per group at the device clock and so never
// stalls a group (at most one packet a cycle); after the last packet has left the pipeline the
// wrapper writes every result word to the result bank once, in order:
//   stream       = max( ceil(3 * P_g / k_g), to_dev(words of ray bank b) )   (no result-bank term;
//                  stream_first = stream_rest)
//   drain        = to_dev(sum_g P_g * a_g)                  a_g as above for one face: a pass that
//                  does not clear ORs onto the bank's words (read-modify-write when lanes share them)
//
// Ray-bank and result-bank read latencies are hidden (addresses run ahead of the data: ray reads of
// a face are issued while its face record is fetched from another bank, result reads while the ray
// is in the pipeline); the face record's read latency Lr is exposed, because the stream needs it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <systemc>

#include "board/bank_layout.h"

namespace rc::board {

struct WrapperTiming {
  sc_core::sc_time device_period = sc_core::sc_time(20, sc_core::SC_NS);
  sc_core::sc_time bank_period = sc_core::sc_time(10, sc_core::SC_NS);
  unsigned bank_read_latency = 2;  // bank cycles, address to data
  unsigned pass_start = 2;         // device cycles from the START edge to the first face
  unsigned face_setup = 1;         // device cycles per face before its record is fetched
  unsigned pass_finish = 1;        // device cycles from the last result write to DONE and the interrupt
  unsigned pipeline_latency = 37;  // paper sec 5.1

  // ceil(n * Pb / Pd): device cycles that n bank cycles take.
  std::uint64_t to_device(std::uint64_t bank_cycles) const;
};

struct BankTraffic {
  std::uint64_t reads = 0, writes = 0;
  std::uint64_t busy_bank_cycles = 0;
};

struct PassTiming {
  std::uint64_t start = 0, face_setup = 0, face_fetch = 0;
  std::uint64_t stream_first = 0, stream_rest = 0;
  std::uint64_t latency = 0, drain = 0, finish = 0;  // drain: results on chip, written out once
  std::uint64_t faces = 0;
  std::uint64_t total = 0;          // device cycles
  std::string limit;                // what bounds stream_rest: "lanes", "bank N (role)", ...
  std::vector<BankTraffic> banks;   // accesses of the whole pass, per bank
};

// Stream cycles of one face (the max above); `limit` receives the binding term's name.
// With results on chip there is no result-bank term and `clearing` changes nothing.
std::uint64_t stream_cycles(const BankLayout& layout, const WrapperTiming& t, const RaySplit& split, bool clearing,
                            std::string* limit = nullptr);
std::uint64_t fetch_cycles(const BankLayout& layout, const WrapperTiming& t);
// Results on chip: result-bank accesses of the end-of-pass write-out (sum_g P_g * a_g) and its
// device cycles (0 with results in the bank).
std::uint64_t drain_accesses(const BankLayout& layout, const RaySplit& split, bool clear);
std::uint64_t drain_cycles(const BankLayout& layout, const WrapperTiming& t, const RaySplit& split, bool clear);
PassTiming pass_timing(const BankLayout& layout, const WrapperTiming& t, const RaySplit& split, std::uint64_t faces,
                       bool clear);

}  // namespace rc::board
