#include "host_sw/platform/software_system.h"

#include "host_sw/platform/work_replay.h"

namespace rc {

SoftwareSystem::SoftwareSystem(const sc_core::sc_module_name& name, const Scene& scene, const SolverOptions& solver,
                               VisibilityBackend& visibility, const HostProfile& host)
    : sc_core::sc_module(name), m_scene(scene), m_solver(solver), m_visibility(&visibility), m_cpu(host) {
  m_cpu.set_free_running(true);
  SC_HAS_PROCESS(SoftwareSystem);
  SC_THREAD(run);
}

SoftwareSystem::SoftwareSystem(const sc_core::sc_module_name& name, const Scene& scene, const SolverOptions& solver,
                               const VisibilityRecording& replay, const HostProfile& host)
    : sc_core::sc_module(name), m_scene(scene), m_solver(solver), m_replay(&replay), m_cpu(host) {
  m_cpu.set_free_running(true);
  SC_HAS_PROCESS(SoftwareSystem);
  SC_THREAD(run);
}

void SoftwareSystem::run() {
  try {
    if (m_replay != nullptr) {
      replay_host_work(*m_replay, {m_scene.patches.size(), m_solver.fixed_steps}, m_cpu, nullptr);
      m_result.steps = m_solver.fixed_steps;
    } else {
      m_result = ProgressiveRadiosity(m_scene, *m_visibility, m_solver, &m_cpu).run();
    }
    m_tests = m_cpu.count(HostWork::IntersectionTest);
    m_cpu.sync();
  } catch (...) {
    m_error = std::current_exception();
  }
  m_end = sc_core::sc_time_stamp();
  m_finished = true;
}

void SoftwareSystem::rethrow_if_failed() const {
  if (m_error) std::rethrow_exception(m_error);
}

RunReport SoftwareSystem::report() const {
  RunReport r;
  r.simulated_seconds = m_end.to_seconds();
  r.time.host_compute = m_cpu.compute_time().to_seconds();
  r.intersections.tests = m_tests;
  r.intersections.per_second = m_end > sc_core::SC_ZERO_TIME ? m_tests / m_end.to_seconds() : 0.0;
  r.host_profile = m_cpu.profile().name;
  for (int k = 0; k < kHostWorkKinds; ++k) r.work[k] = {m_cpu.count(HostWork(k)), m_cpu.time(HostWork(k)).to_seconds()};
  const HostProfile& host = m_cpu.profile();
  attach_energy(r, energy::load_energy_tables(nullptr, host.document, host.file), static_cast<std::uint64_t>(m_result.steps));
  return r;
}

}  // namespace rc
