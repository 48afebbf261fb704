#include "host_sw/driver/trace_writer.h"

#include <stdexcept>

#include "io/output_file.h"

namespace rc {

namespace {
double micros(const sc_core::sc_time& t) { return static_cast<double>(t.value()) * 1e-6; }  // ps -> us
}  // namespace

int TraceWriter::track_id(const std::string& track) {
  const auto it = tracks_.find(track);
  if (it != tracks_.end()) return it->second;
  const int id = static_cast<int>(tracks_.size()) + 1;
  tracks_[track] = id;
  track_order_.push_back(track);
  return id;
}

void TraceWriter::complete(const std::string& track, const std::string& name, const sc_core::sc_time& start,
                           const sc_core::sc_time& end, nlohmann::ordered_json args) {
  nlohmann::ordered_json e = {{"name", name}, {"ph", "X"}, {"ts", micros(start)}, {"dur", micros(end - start)},
                              {"pid", 1}, {"tid", track_id(track)}};
  if (!args.is_null()) e["args"] = std::move(args);
  events_.push_back(std::move(e));
}

void TraceWriter::instant(const std::string& track, const std::string& name, const sc_core::sc_time& at,
                          nlohmann::ordered_json args) {
  nlohmann::ordered_json e = {{"name", name}, {"ph", "i"}, {"s", "t"}, {"ts", micros(at)}, {"pid", 1},
                              {"tid", track_id(track)}};
  if (!args.is_null()) e["args"] = std::move(args);
  events_.push_back(std::move(e));
}

std::string TraceWriter::text() const {
  nlohmann::ordered_json events = nlohmann::ordered_json::array();
  events.push_back({{"name", "process_name"}, {"ph", "M"}, {"pid", 1}, {"args", {{"name", "rc2000sim"}}}});
  for (std::size_t i = 0; i < track_order_.size(); ++i) {
    const int id = static_cast<int>(i) + 1;
    events.push_back({{"name", "thread_name"}, {"ph", "M"}, {"pid", 1}, {"tid", id}, {"args", {{"name", track_order_[i]}}}});
    events.push_back({{"name", "thread_sort_index"}, {"ph", "M"}, {"pid", 1}, {"tid", id}, {"args", {{"sort_index", id}}}});
  }
  for (const auto& e : events_) events.push_back(e);
  // A name that is not UTF-8 leaves as U+FFFD, never as an exception after the run (docs/outputs.md).
  return nlohmann::ordered_json{{"displayTimeUnit", "ns"}, {"traceEvents", events}}.dump(
             -1, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
}

void TraceWriter::write(const std::string& path) const { io::write_file_atomically(path, text()); }

}  // namespace rc
