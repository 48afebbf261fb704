// Pictures for reports: rc2000sim writes CSV, then asks Debian's python3-matplotlib (installed by
// scripts/) to draw it with a script from apps/plots/. A missing python only costs the picture.
#pragma once

#include <cstdio>
#include <string>

#include <sys/types.h>

namespace rc {

// A plot script running in a child process that takes its requests on stdin (apps/plots/entry.py).
// The child ends with this process (studies/child_guard.h): an interrupted command leaves no script
// drawing into its folder.
// Start it before the last stretch of work (rc2000sim paper: before the timing study): the
// interpreter and matplotlib load meanwhile, and draw() costs only the drawing (a script may draw
// its figures side by side in forked copies of itself, apps/plots/entry.py).
class PlotProcess {
 public:
  explicit PlotProcess(const std::string& script);
  ~PlotProcess() { finish(); }
  PlotProcess(const PlotProcess&) = delete;
  PlotProcess& operator=(const PlotProcess&) = delete;

  // Asks for apps/plots/<script> INPUT OUTPUT (a PNG, or a folder for scripts that draw several).
  void draw(const std::string& csv_path, const std::string& output);
  // Waits for every drawing; false (with a warning on stderr) if the script could not run or failed.
  bool finish();

 private:
  std::string command_;
  std::FILE* pipe_ = nullptr;  // the requests, to the child's stdin
  pid_t pid_ = -1;
  bool ok_ = true;
};

// One drawing, start to finish; returns false (and warns on stderr) if it could not.
bool plot(const std::string& script, const std::string& csv_path, const std::string& output);

}  // namespace rc
