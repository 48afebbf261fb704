// The one seam between the radiosity solver and whatever answers "is this segment blocked?".
// Software backends (float, CPU fixed point) and the board model all implement VisibilityBackend,
// so the solver never knows which one it talks to.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "scenes/geometry.h"

namespace rc {

// One shooting step's visibility question: segments from one start point (the shooting patch's
// centre, on face `source_face`) to many end points (receiver patch centres).
struct SegmentBatch {
  Vec3 start;
  int source_face = -1;
  std::vector<Vec3> ends;     // one per segment
  std::vector<int> end_faces; // face each end point lies on, same length as ends
  // Segments whose answer the solver uses: 1 per segment, or empty for all of them. The paper-
  // faithful solver sends segments to receivers that exchange no energy (form factor 0); their
  // answers change nothing, so a backend may skip them (and report them clear) and the solver
  // ignores them whatever a backend says. The board still tests them: the hardware does.
  std::vector<std::uint8_t> needed;
  // The shooting patch. Within one solver run (one load_faces), batches from the same shooter are
  // identical, so their answers may be reused (ShooterMemoVisibility). -1: no such promise.
  int shooter = -1;

  std::size_t size() const { return ends.size(); }
  // Throws std::invalid_argument unless there is one end face per end point (every backend's submit).
  void check() const {
    if (end_faces.size() != ends.size()) {
      throw std::invalid_argument("segment batch has " + std::to_string(ends.size()) + " end points but " +
                                  std::to_string(end_faces.size()) + " end faces");
    }
  }
  bool is_needed(std::size_t segment) const { return needed.empty() || needed[segment] != 0; }
};

// Own-face rule (every backend follows it): a segment is never tested against its source face or
// its end point's face. Both end points lie on those faces, where the exact answer is "no hit"
// (t = 0 or t = 1 fails the strict test), but rounding can tip it either way; excluding them by
// index makes every backend answer the same question at every width.
inline bool is_own_face(const SegmentBatch& batch, std::size_t segment, int face) {
  return face == batch.source_face || face == batch.end_faces[segment];
}

class VisibilityBackend {
 public:
  virtual ~VisibilityBackend() = default;
  virtual std::string name() const = 0;
  // Called once before the first step with the faces (triangles) of the normalised scene.
  virtual void load_faces(const std::vector<Triangle>& faces) = 0;
  // Starts answering one step. A backend may work asynchronously (the board does): the solver
  // computes form factors between submit() and collect(), which is the paper's concurrent mode.
  virtual void submit(const SegmentBatch& batch) = 0;
  // Returns, for every segment of the last submitted batch, 1 if any other face blocks it.
  virtual void collect(std::vector<std::uint8_t>& blocked) = 0;
  // Segment-triangle tests performed so far (what the cost model charges).
  virtual std::uint64_t tests_performed() const = 0;
  // True when the tests run on the host CPU (software backends), so the host pays for them.
  virtual bool runs_on_host() const { return true; }
};

}  // namespace rc
