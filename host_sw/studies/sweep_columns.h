// The columns of a sweep row (docs/results/sweep.md defines each): their names in order and each
// row's values as typed cells, which the CSV (sweep_csv.h) and the JSON record (sweep_row_json.h)
// write in their own syntax, so the two files always hold the same columns.
#pragma once

#include <string>
#include <vector>

#include "host_sw/studies/sweep_config.h"
#include "host_sw/studies/sweep_row.h"

namespace rc {

// The columns beyond the classic ones that a sweep over `axes` adds: "host" when more than one
// host is swept, "cards", "card_split" and "card_bus" when more than one card is, then each profile
// axis's path. They follow "concurrent".
std::vector<std::string> extra_columns(const SweepAxes& axes);

// One column's value in one row: nothing (an empty CSV field, JSON null), a text, an integer or a
// number (a NaN figure is `none`).
struct SweepCell {
  enum class Kind { none, text, integer, number };
  Kind kind = Kind::none;
  std::string text;
  long long integer = 0;
  double number = 0;
};

// The column names: the classic ones, with `extra` (extra_columns) after "concurrent".
std::vector<std::string> sweep_columns(const std::vector<std::string>& extra);

// Every column's value, in sweep_columns(extra) order.
std::vector<SweepCell> sweep_cells(const SweepRow& row, const std::vector<std::string>& extra);

}  // namespace rc
