#include "host_sw/studies/fidelity.h"

#include "host_sw/radiosity/segment_fix_names.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <memory>
#include <mutex>
#include <stdexcept>

#include "host_sw/radiosity/jobs.h"
#include "host_sw/radiosity/worker_pool.h"
#include "host_sw/visibility/visibility_factory.h"
#include "pipeline/float_format.h"

namespace rc {

bool Arithmetic::is_float() const { return pipeline::names_float_format(backend); }

Arithmetic Arithmetic::fixed(int bits, SegmentFixOptions fixes) {
  if (fixes.any()) fixes.bits = bits;
  return {"fast", bits, fixes};
}

std::string Arithmetic::label() const {
  if (is_float()) return backend;
  std::string l = "fixed:" + std::to_string(bits);
  if (fixes.offset_lsb != 0) l += "+offset:" + std::to_string(fixes.offset_lsb);
  if (fixes.neighbour_rings != 0) l += "+rings:" + std::to_string(fixes.neighbour_rings);
  if (fixes.coordinate_bits != 0) l += "+coordinates:" + std::to_string(fixes.coordinate_bits);
  return l;
}

namespace {

// Serialises the progress calls of worker threads.
class SerialProgress {
 public:
  explicit SerialProgress(const std::function<void(const std::string&)>& f) : f_(f) {}
  void operator()(const std::string& what) {
    if (!f_) return;
    std::lock_guard<std::mutex> lock(mutex_);
    f_(what);
  }

 private:
  const std::function<void(const std::string&)>& f_;
  std::mutex mutex_;
};

// Answers every batch in double precision and, side by side on a pool of threads, with every
// shadow; counts, per shadow, the needed segments on which it differs from the double-precision
// answer: what one ComparingVisibility per shadow counts, in one solve. The double-precision
// answer is split into chunks of segments (each answered by its own FloatVisibility, segments the
// solver does not need skipped), so that it too runs on every thread, and a repeated shooter's
// answer is reused (SegmentBatch::shooter's promise). The work starts at submit() and runs while the
// solver computes form factors; collect() joins in.
class FanOutComparingVisibility : public VisibilityBackend {
 public:
  FanOutComparingVisibility(std::vector<std::unique_ptr<VisibilityBackend>> shadows, int workers)
      : shadows_(std::move(shadows)), pool_(workers), counts_(shadows_.size()) {
    const int chunks = 2 * workers;
    for (int c = 0; c < chunks; ++c)
      chunks_.push_back(make_functional_answer("float", 0));
    chunk_batches_.resize(chunks_.size());
    chunk_flags_.resize(chunks_.size());
    shadow_flags_.resize(shadows_.size());
  }

  std::string name() const override { return "float (checked against " + std::to_string(shadows_.size()) + " arithmetics)"; }
  void load_triangles(const std::vector<Triangle>& faces) override {
    for (auto& c : chunks_) c->load_faces(faces, sheets());
    for (auto& s : shadows_) s->load_faces(faces, sheets());
    memo_.clear();
    memo_bytes_ = 0;
  }
  void submit(const SegmentBatch& batch) override {
    batch.check();
    batch_ = batch;
    reuse_ = nullptr;
    if (batch.shooter >= 0 && static_cast<std::size_t>(batch.shooter) < memo_.size() &&
        memo_[static_cast<std::size_t>(batch.shooter)].size() == batch.size())
      reuse_ = &memo_[static_cast<std::size_t>(batch.shooter)];
    tasks_.clear();
    if (!reuse_) {
      // Contiguous chunks of segments, as equal as can be.
      const std::size_t n = batch.size(), k = chunks_.size();
      for (std::size_t c = 0; c < k; ++c) {
        const std::size_t lo = n * c / k, hi = n * (c + 1) / k;
        SegmentBatch& b = chunk_batches_[c];
        b.start = batch.start;
        b.source_face = batch.source_face;
        b.shooter = -1;
        b.ends.assign(batch.ends.begin() + static_cast<std::ptrdiff_t>(lo), batch.ends.begin() + static_cast<std::ptrdiff_t>(hi));
        b.end_faces.assign(batch.end_faces.begin() + static_cast<std::ptrdiff_t>(lo),
                           batch.end_faces.begin() + static_cast<std::ptrdiff_t>(hi));
        if (batch.needed.empty())
          b.needed.clear();
        else
          b.needed.assign(batch.needed.begin() + static_cast<std::ptrdiff_t>(lo), batch.needed.begin() + static_cast<std::ptrdiff_t>(hi));
        if (!b.ends.empty()) tasks_.push_back(c);
      }
    }
    for (std::size_t s = 0; s < shadows_.size(); ++s) tasks_.push_back(chunks_.size() + s);
    next_ = 0;
    error_ = nullptr;
    pool_.start([this](int) { work(); });
  }
  void collect(std::vector<std::uint8_t>& blocked) override {
    pool_.finish();
    if (error_) std::rethrow_exception(error_);
    if (reuse_) {
      blocked = *reuse_;
    } else {
      blocked.clear();
      for (std::size_t c = 0; c < chunks_.size(); ++c)
        if (!chunk_batches_[c].ends.empty()) blocked.insert(blocked.end(), chunk_flags_[c].begin(), chunk_flags_[c].end());
      remember(blocked);
    }
    for (std::size_t s = 0; s < shadows_.size(); ++s) {
      const std::vector<std::uint8_t>& shadow = shadow_flags_[s];
      DecisionCounts& c = counts_[s];
      for (std::size_t i = 0; i < blocked.size(); ++i) {
        if (!batch_.is_needed(i)) continue;
        c.double_only += blocked[i] && !shadow[i];
        c.arithmetic_only += !blocked[i] && shadow[i];
        ++c.compared;
      }
    }
  }
  std::uint64_t tests_performed() const override {
    std::uint64_t t = 0;
    for (const auto& c : chunks_) t += c->tests_performed();
    return t;
  }

  const std::vector<DecisionCounts>& counts() const { return counts_; }

 private:
  static constexpr std::size_t kMaxMemoBytes = std::size_t(1) << 28;

  void remember(const std::vector<std::uint8_t>& blocked) {
    if (batch_.shooter < 0 || memo_bytes_ + blocked.size() > kMaxMemoBytes) return;
    const auto shooter = static_cast<std::size_t>(batch_.shooter);
    if (shooter >= memo_.size()) memo_.resize(shooter + 1);
    if (!memo_[shooter].empty()) return;
    memo_[shooter] = blocked;
    memo_bytes_ += blocked.size();
  }

  // A thread takes the next task until none is left: a chunk of the double-precision answer or a shadow.
  void work() {
    for (std::size_t t; (t = next_.fetch_add(1)) < tasks_.size();) {
      try {
        const std::size_t task = tasks_[t];
        if (task < chunks_.size()) {
          chunks_[task]->submit(chunk_batches_[task]);
          chunks_[task]->collect(chunk_flags_[task]);
        } else {
          VisibilityBackend& shadow = *shadows_[task - chunks_.size()];
          shadow.submit(batch_);
          shadow.collect(shadow_flags_[task - chunks_.size()]);
        }
      } catch (...) {
        std::lock_guard<std::mutex> lock(error_mutex_);
        if (!error_) error_ = std::current_exception();
      }
    }
  }

  std::vector<std::unique_ptr<VisibilityBackend>> shadows_;
  WorkerPool pool_;
  std::vector<std::unique_ptr<VisibilityBackend>> chunks_;  // the double-precision answer's
  std::vector<SegmentBatch> chunk_batches_;
  std::vector<std::vector<std::uint8_t>> chunk_flags_, shadow_flags_;
  std::vector<std::size_t> tasks_;
  SegmentBatch batch_;
  std::vector<std::vector<std::uint8_t>> memo_;  // the double-precision answer by shooter
  std::size_t memo_bytes_ = 0;
  const std::vector<std::uint8_t>* reuse_ = nullptr;
  std::vector<DecisionCounts> counts_;
  std::atomic<std::size_t> next_{0};
  std::mutex error_mutex_;
  std::exception_ptr error_;
};

unsigned resolved_jobs(const FidelityOptions& o) { return o.jobs ? o.jobs : jobs(); }

// Each arithmetic's backend once, so that a bad one is refused before any work; its fixes too (on no
// faces: the fixer's checks of the options alone).
void check_arithmetics(const std::vector<Arithmetic>& arithmetics) {
  for (const Arithmetic& a : arithmetics) {
    make_software_visibility(a.backend, a.bits, 1);
    if (!a.fixes.any()) continue;
    if (a.is_float()) throw std::invalid_argument(a.backend + ": the segment fixes act on the fixed-point pipeline's grid, not on a float format");
    if (a.fixes.bits != a.bits)
      throw std::invalid_argument(a.label() + ": the fixes' width (" + std::to_string(a.fixes.bits) + ") is not the arithmetic's");
    SegmentFixer({}, FaceSheets{}, a.fixes);
  }
}

// An arithmetic's answer as a shadow of the reference: its functional answer, with its fixes around it.
class ShadowAnswer : public VisibilityBackend {
 public:
  explicit ShadowAnswer(const Arithmetic& a) : inner_(make_functional_answer(a.backend, a.bits, 1)) {
    if (a.fixes.any()) fixed_ = std::make_unique<FixedSegmentsVisibility>(*inner_, a.fixes);
  }
  std::string name() const override { return answer().name(); }
  void submit(const SegmentBatch& batch) override { answer().submit(batch); }
  void collect(std::vector<std::uint8_t>& blocked) override { answer().collect(blocked); }
  std::uint64_t tests_performed() const override { return answer().tests_performed(); }
  bool runs_on_host() const override { return answer().runs_on_host(); }

 private:
  void load_triangles(const std::vector<Triangle>& faces) override { answer().load_faces(faces, sheets()); }
  VisibilityBackend& answer() const { return fixed_ ? static_cast<VisibilityBackend&>(*fixed_) : *inner_; }

  std::unique_ptr<VisibilityBackend> inner_;
  std::unique_ptr<FixedSegmentsVisibility> fixed_;
};

// The solver options of an arithmetic's own solve: the caller's, with the arithmetic's fixes when it has any.
SolverOptions arithmetic_solver(const SolverOptions& solver, const Arithmetic& a) {
  SolverOptions s = solver;
  if (a.fixes.any()) s.fixes = a.fixes;
  return s;
}

}  // namespace

ReferenceDecisions solve_reference(const Scene& scene, const SolverOptions& solver, const std::vector<Arithmetic>& arithmetics,
                                   const FidelityOptions& options) {
  check_arithmetics(arithmetics);
  SerialProgress progress(options.progress);
  std::vector<std::unique_ptr<VisibilityBackend>> shadows;
  for (const Arithmetic& a : arithmetics) shadows.push_back(std::make_unique<ShadowAnswer>(a));
  const int workers = static_cast<int>(resolved_jobs(options));
  FanOutComparingVisibility fan_out(std::move(shadows), workers);
  ProgressiveRadiosity radiosity(scene, fan_out, solver);
  const std::string what = " (double precision and " + std::to_string(arithmetics.size()) +
                           (arithmetics.size() == 1 ? " arithmetic)" : " arithmetics)");
  radiosity.on_progress([&](const StepProgress& p) { progress("reference step " + std::to_string(p.step) + what); });
  ReferenceDecisions out;
  out.reference = radiosity.run();
  out.decisions = fan_out.counts();
  return out;
}

std::vector<RecordedRun> solve_arithmetics(const Scene& scene, const SolverOptions& solver, const std::vector<Arithmetic>& arithmetics,
                                           const FidelityOptions& options) {
  check_arithmetics(arithmetics);
  std::vector<RecordedRun> out(arithmetics.size());
  const unsigned jobs = resolved_jobs(options);
  const std::size_t n = arithmetics.size();
  const unsigned workers = static_cast<unsigned>(std::min<std::size_t>(jobs, n));
  // Each solve's backend gets an equal share of the cores left over when solves are fewer than jobs.
  const int threads = workers ? static_cast<int>(std::max(1u, jobs / std::max(1u, workers))) : 1;
  SerialProgress progress(options.progress);
  std::atomic<std::size_t> next{0}, done{0};
  std::mutex error_mutex;
  std::exception_ptr error;
  auto work = [&](int) {
    for (std::size_t i; (i = next.fetch_add(1)) < n;) {
      try {
        const Arithmetic& a = arithmetics[i];
        out[i] = record_functional_run(scene, arithmetic_solver(solver, a), a.backend, a.bits, threads);
        progress("solved " + a.label() + " (" + std::to_string(done.fetch_add(1) + 1) + " of " + std::to_string(n) + ")");
      } catch (...) {
        std::lock_guard<std::mutex> lock(error_mutex);
        if (!error) error = std::current_exception();
      }
    }
  };
  WorkerPool pool(static_cast<int>(std::max(1u, workers)));  // work() catches every error itself
  pool.start(work);
  pool.finish();
  if (error) std::rethrow_exception(error);
  return out;
}

FidelityResult measure_fidelity(const Scene& scene, const SolverOptions& solver, const std::vector<Arithmetic>& arithmetics,
                                const FidelityOptions& options) {
  ReferenceDecisions ref = solve_reference(scene, solver, arithmetics, options);
  std::vector<RecordedRun> runs = solve_arithmetics(scene, solver, arithmetics, options);
  FidelityResult out;
  out.reference = std::move(ref.reference);
  for (std::size_t i = 0; i < arithmetics.size(); ++i) {
    ArithmeticFidelity row;
    row.arithmetic = arithmetics[i];
    row.run = std::move(runs[i]);
    row.error = compare_solutions(row.run.result.radiosity, out.reference.radiosity);
    row.decisions = ref.decisions[i];
    out.rows.push_back(std::move(row));
  }
  return out;
}

}  // namespace rc
