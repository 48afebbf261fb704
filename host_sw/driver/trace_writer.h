// A Chrome / Perfetto trace (trace-event JSON, "X" complete events and "i" instants) of a board
// run, restricted to a range of shooting steps: one track per actor (host thread, DMA, each lane,
// IRQ), times in simulated microseconds. Open the file in ui.perfetto.dev or chrome://tracing.
#pragma once

#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <systemc>

namespace rc {

class TraceWriter {
 public:
  // Steps are numbered from 1 (the first shooting step), the range is inclusive.
  TraceWriter(int first_step, int last_step) : first_(first_step), last_(last_step) {}

  bool wants(int step) const { return step >= first_ && step <= last_; }
  void complete(const std::string& track, const std::string& name, const sc_core::sc_time& start,
                const sc_core::sc_time& end, nlohmann::ordered_json args = nullptr);
  void instant(const std::string& track, const std::string& name, const sc_core::sc_time& at,
               nlohmann::ordered_json args = nullptr);
  std::size_t size() const { return events_.size(); }
  std::string text() const;                   // the trace.json document
  void write(const std::string& path) const;  // atomically (io/output_file.h); throws io::OutputFileError

 private:
  int track_id(const std::string& track);

  int first_, last_;
  std::map<std::string, int> tracks_;
  std::vector<std::string> track_order_;
  std::vector<nlohmann::ordered_json> events_;
};

}  // namespace rc
