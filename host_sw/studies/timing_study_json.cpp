#include "host_sw/studies/timing_study_json.h"

#include <stdexcept>

#include <nlohmann/json.hpp>

#include "host_sw/outputs/run_report_json.h"

namespace rc {

std::string encode_worker_answer(const WorkerAnswer& answer) {
  nlohmann::json j;
  if (!answer.error.empty()) {
    j["error"] = answer.error;
  } else {
    nlohmann::json list = nlohmann::json::array();
    for (const TimingOutcome& o : answer.outcomes)
      list.push_back({{"label", o.label}, {"steps", o.steps}, {"report", encode(o.report)}});
    j["outcomes"] = std::move(list);
  }
  return j.dump();
}

WorkerAnswer decode_worker_answer(const std::string& text) {
  WorkerAnswer answer;
  try {
    const nlohmann::json j = nlohmann::json::parse(text);
    if (j.contains("error")) {
      answer.error = j.at("error").get<std::string>();
      return answer;
    }
    for (const nlohmann::json& m : j.at("outcomes")) {
      TimingOutcome o;
      o.label = m.at("label").get<std::string>();
      o.steps = m.at("steps").get<int>();
      o.report = decode(m.at("report").get<std::string>());
      o.simulated_seconds = o.report.simulated_seconds;
      answer.outcomes.push_back(std::move(o));
    }
  } catch (const nlohmann::json::exception& e) {
    throw std::invalid_argument(std::string("a timing study worker's answer is malformed: ") + e.what());
  }
  return answer;
}

}  // namespace rc
