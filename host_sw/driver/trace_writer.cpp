#include "host_sw/driver/trace_writer.h"

namespace rc {

int TraceWriter::track_id(const std::string& track) {
  const auto it = tracks_.find(track);
  if (it != tracks_.end()) return it->second;
  const int id = static_cast<int>(tracks_.size()) + 1;
  tracks_[track] = id;
  track_order_.push_back(track);
  return id;
}

void TraceWriter::complete(const std::string& track, const std::string& name, const sc_core::sc_time& start,
                           const sc_core::sc_time& end, std::vector<TraceArg> args) {
  events_.push_back({TraceEvent::Phase::complete, name, start, end, track_id(track), std::move(args)});
}

void TraceWriter::instant(const std::string& track, const std::string& name, const sc_core::sc_time& at,
                          std::vector<TraceArg> args) {
  events_.push_back({TraceEvent::Phase::instant, name, at, at, track_id(track), std::move(args)});
}

}  // namespace rc
