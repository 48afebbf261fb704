#include "apps/plot.h"

#include <csignal>
#include <filesystem>

namespace rc {

PlotProcess::PlotProcess(const std::string& script) {
  const std::string path = std::string(RC_SOURCE_DIR) + "/apps/plots/" + script;
  if (!std::filesystem::exists(path)) {
    std::fprintf(stderr, "warning: %s not found; its pictures are not drawn\n", path.c_str());
    ok_ = false;
    return;
  }
  // Debian's interpreter, which has python3-matplotlib, even when another python3 is first on PATH.
  const std::string python = std::filesystem::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
  command_ = python + " '" + path + "' -";
  std::signal(SIGPIPE, SIG_IGN);  // a script that died must cost a warning, not the process
  std::fflush(nullptr);           // the child must not inherit unflushed output
  pipe_ = popen(command_.c_str(), "w");
  if (pipe_ == nullptr) ok_ = false;
}

void PlotProcess::draw(const std::string& csv_path, const std::string& output) {
  if (pipe_ == nullptr) return;
  if (std::fprintf(pipe_, "%s\t%s\n", csv_path.c_str(), output.c_str()) < 0) ok_ = false;
}

bool PlotProcess::finish() {
  if (pipe_ != nullptr) {
    const int status = pclose(pipe_);
    pipe_ = nullptr;
    if (status != 0) ok_ = false;
    if (!ok_) std::fprintf(stderr, "warning: plotting failed (%s); the CSV is complete\n", command_.c_str());
  }
  return ok_;
}

bool plot(const std::string& script, const std::string& csv_path, const std::string& output) {
  PlotProcess process(script);
  process.draw(csv_path, output);
  return process.finish();
}

}  // namespace rc
