#include "host_sw/outputs/trace_json.h"

#include <nlohmann/json.hpp>

#include "io/output_file.h"

namespace rc {

namespace {

using nlohmann::ordered_json;

double micros(const sc_core::sc_time& t) { return static_cast<double>(t.value()) * 1e-6; }  // ps -> us

ordered_json event_json(const TraceEvent& e) {
  ordered_json j;
  if (e.phase == TraceEvent::Phase::complete) {
    j = {{"name", e.name}, {"ph", "X"}, {"ts", micros(e.start)}, {"dur", micros(e.end - e.start)}, {"pid", 1}, {"tid", e.track}};
  } else {
    j = {{"name", e.name}, {"ph", "i"}, {"s", "t"}, {"ts", micros(e.start)}, {"pid", 1}, {"tid", e.track}};
  }
  if (e.args.empty()) return j;
  ordered_json& args = j["args"];
  for (const TraceArg& a : e.args) std::visit([&](const auto& v) { args[a.key] = v; }, a.value);
  return j;
}

}  // namespace

std::string trace_json(const TraceWriter& trace) {
  ordered_json events = ordered_json::array();
  events.push_back({{"name", "process_name"}, {"ph", "M"}, {"pid", 1}, {"args", {{"name", "rc2000sim"}}}});
  for (std::size_t i = 0; i < trace.tracks().size(); ++i) {
    const int id = static_cast<int>(i) + 1;
    events.push_back({{"name", "thread_name"}, {"ph", "M"}, {"pid", 1}, {"tid", id}, {"args", {{"name", trace.tracks()[i]}}}});
    events.push_back({{"name", "thread_sort_index"}, {"ph", "M"}, {"pid", 1}, {"tid", id}, {"args", {{"sort_index", id}}}});
  }
  for (const TraceEvent& e : trace.events()) events.push_back(event_json(e));
  // A name that is not UTF-8 leaves as U+FFFD, never as an exception after the run (docs/outputs.md).
  return ordered_json{{"displayTimeUnit", "ns"}, {"traceEvents", events}}.dump(-1, ' ', false,
                                                                              ordered_json::error_handler_t::replace) +
         "\n";
}

void write_trace_json(const TraceWriter& trace, const std::string& path) { io::write_file_atomically(path, trace_json(trace)); }

}  // namespace rc
