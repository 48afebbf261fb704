// The software-only implementation as a SystemC system: the host thread runs the solver with
// visibility answered on the host CPU, and the host CPU cost model turns its work (intersection
// tests included) into simulated time. It talks to no board, so its time is charged without
// yielding (one wait at the end).
#pragma once

#include <exception>

#include <systemc>

#include "host_sw/driver/host_cpu_model.h"
#include "host_sw/platform/run_report.h"
#include "host_sw/radiosity/radiosity.h"
#include "host_sw/visibility/visibility_recording.h"
#include "scenes/scene.h"

namespace rc {

class SoftwareSystem : public sc_core::sc_module {
 public:
  // `visibility` answers (e.g. a replay); its tests_performed() is what the host pays for.
  SoftwareSystem(const sc_core::sc_module_name& name, const Scene& scene, const SolverOptions& solver,
                 VisibilityBackend& visibility, const HostProfile& host);
  // Timing replay (work_replay.h) of solver.fixed_steps steps of a recording; no radiosity.
  SoftwareSystem(const sc_core::sc_module_name& name, const Scene& scene, const SolverOptions& solver,
                 const VisibilityRecording& replay, const HostProfile& host);

  bool finished() const { return m_finished; }
  void rethrow_if_failed() const;
  const SolverResult& result() const { return m_result; }
  sc_core::sc_time end_time() const { return m_end; }
  const HostCpuModel& cpu() const { return m_cpu; }
  RunReport report() const;

 private:
  void run();

  const Scene& m_scene;
  SolverOptions m_solver;
  VisibilityBackend* m_visibility = nullptr;
  const VisibilityRecording* m_replay = nullptr;
  std::uint64_t m_tests = 0;
  HostCpuModel m_cpu;
  SolverResult m_result;
  sc_core::sc_time m_end = sc_core::SC_ZERO_TIME;
  bool m_finished = false;
  std::exception_ptr m_error;
};

}  // namespace rc
