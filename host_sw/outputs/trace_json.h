// The output edge of a board run's trace (host_sw/driver/trace_writer.h): the trace-event JSON
// document Perfetto and chrome://tracing open, times in simulated microseconds.
#pragma once

#include <string>

#include "host_sw/driver/trace_writer.h"

namespace rc {

std::string trace_json(const TraceWriter& trace);  // the trace.json document
// Atomically (io/output_file.h); throws io::OutputFileError.
void write_trace_json(const TraceWriter& trace, const std::string& path);

}  // namespace rc
