#include "host_sw/studies/sweep_csv.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "host_sw/studies/sweep_columns.h"

namespace rc {

namespace {

std::string csv_text(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char ch : s) q += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return q + "\"";
}

std::string csv_number(double x) {
  if (std::isnan(x)) return "";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", x);
  return buf;
}

std::string cell_csv_field(const SweepCell& v) {
  switch (v.kind) {
    case SweepCell::Kind::none: return "";
    case SweepCell::Kind::text: return csv_text(v.text);
    case SweepCell::Kind::number: return csv_number(v.number);
    case SweepCell::Kind::integer: return std::to_string(v.integer);
  }
  throw std::logic_error("csv_field: not a SweepCell kind");
}

}  // namespace

void write_sweep_csv(std::ostream& out, const std::vector<SweepRow>& rows, const std::vector<std::string>& extra) {
  const std::vector<std::string> names = sweep_columns(extra);
  for (std::size_t i = 0; i < names.size(); ++i) out << (i ? "," : "") << csv_text(names[i]);
  out << "\n";
  for (const SweepRow& r : rows) {
    const std::vector<SweepCell> values = sweep_cells(r, extra);
    for (std::size_t i = 0; i < values.size(); ++i) out << (i ? "," : "") << cell_csv_field(values[i]);
    out << "\n";
  }
}

}  // namespace rc
