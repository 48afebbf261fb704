// The output edge of a RunReport (host_sw/platform/run_report.h): the one writer of the report
// document of docs/outputs.md, and the internal codec between the timing study's processes.
#pragma once

#include <array>
#include <string>

#include <nlohmann/json.hpp>

#include "host_sw/platform/run_report.h"

namespace rc {

// The one writer: the report document of docs/outputs.md.
nlohmann::ordered_json to_json(const RunReport& report);
// The host work part of it ({"step": {"count", "seconds"}, ...}).
nlohmann::ordered_json work_json(const std::array<WorkTally, kHostWorkKinds>& work);
// An estimate as report.json writes it (board.energy): totals, tables, components and every term
// with its counter, count and profile figure (key, value, unit, source). docs/outputs.md.
nlohmann::ordered_json energy_report_json(const energy::EnergyReport& e);

// Between processes of one timing study: every field, exactly (doubles round-trip).
std::string encode(const RunReport& report);
RunReport decode(const std::string& text);  // throws std::invalid_argument on a malformed text

}  // namespace rc
