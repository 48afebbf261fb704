#include "host_sw/studies/study_table.h"

#include <algorithm>
#include <sstream>

#include "host_sw/studies/sweep_columns.h"
#include "host_sw/studies/sweep_csv.h"

namespace rc {

namespace {

std::string quoted_csv_field(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

// The next CSV record: a line, joined with the following ones while a quoted field is open (an odd
// count of quotes so far), so a field holding a line break stays in its row.
bool next_record(std::istream& in, std::string& record) {
  if (!std::getline(in, record)) return false;
  std::string more;
  auto open = [&] { return std::count(record.begin(), record.end(), '"') % 2 != 0; };
  while (open() && std::getline(in, more)) record += "\n" + more;
  return true;
}

}  // namespace

// Each scene's table as write_sweep_csv writes it, its header kept once (every scene of a study has
// the same columns: the same axes), each line prefixed with the scene.
void write_study_table_csv(std::ostream& out, const StudyResult& result, const std::vector<std::string>& extra) {
  bool header_written = false;
  for (std::size_t i = 0; i < result.scenes.size(); ++i) {
    std::ostringstream scene_csv;
    write_sweep_csv(scene_csv, result.scenes[i].rows, extra);
    std::istringstream lines(scene_csv.str());
    std::string line;
    const bool has_header = next_record(lines, line);
    if (has_header && !header_written) {
      out << "scene," << line << '\n';
      header_written = true;
    }
    const std::string scene = quoted_csv_field(result.study.scenes.at(i).name);
    while (next_record(lines, line)) out << scene << ',' << line << '\n';
  }
}

}  // namespace rc
