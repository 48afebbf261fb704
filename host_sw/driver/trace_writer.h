// A Chrome / Perfetto trace (trace-event "X" complete events and "i" instants) of a board run,
// restricted to a range of shooting steps: one track per actor (host thread, DMA, each lane, IRQ),
// times in simulated time. The driver records typed events here; the trace.json text is written at
// the output edge (host_sw/outputs/trace_json.h). Open the file in ui.perfetto.dev or chrome://tracing.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <variant>
#include <vector>

#include <systemc>

namespace rc {

// One argument of an event ("bytes": 4096, "limit": "lanes"), in the order given.
struct TraceArg {
  std::string key;
  std::variant<std::uint64_t, std::string> value;
  TraceArg(std::string k, std::uint64_t v) : key(std::move(k)), value(v) {}
  TraceArg(std::string k, std::string v) : key(std::move(k)), value(std::move(v)) {}
};

struct TraceEvent {
  enum class Phase { complete, instant };  // "X" (start and duration), "i" (a thread-scoped instant)
  Phase phase = Phase::complete;
  std::string name;
  sc_core::sc_time start, end;  // an instant: start == end
  int track = 0;                // 1-based, in TraceWriter::tracks() order
  std::vector<TraceArg> args;
};

class TraceWriter {
 public:
  // Steps are numbered from 1 (the first shooting step), the range is inclusive.
  TraceWriter(int first_step, int last_step) : first_(first_step), last_(last_step) {}

  bool wants(int step) const { return step >= first_ && step <= last_; }
  void complete(const std::string& track, const std::string& name, const sc_core::sc_time& start,
                const sc_core::sc_time& end, std::vector<TraceArg> args = {});
  void instant(const std::string& track, const std::string& name, const sc_core::sc_time& at,
               std::vector<TraceArg> args = {});
  std::size_t size() const { return events_.size(); }
  const std::vector<TraceEvent>& events() const { return events_; }
  const std::vector<std::string>& tracks() const { return track_order_; }  // track i + 1's name at [i]

 private:
  int track_id(const std::string& track);

  int first_, last_;
  std::map<std::string, int> tracks_;
  std::vector<std::string> track_order_;
  std::vector<TraceEvent> events_;
};

}  // namespace rc
