// The one seam between the radiosity solver and whatever answers "is this segment blocked?".
// Software backends (float, CPU fixed point) and the board model all implement VisibilityBackend,
// so the solver never knows which one it talks to.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "scenes/geometry.h"
#include "scenes/sheets.h"

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

// Own-surface rule (every backend follows it): a segment is never tested against a face of the
// sheet (scenes/sheets.h) that holds its start point (the source face's) or its end point (its end
// face's). Both end points lie inside every face of their sheets, where the exact answer is "no
// hit" (t = 0 or t = 1 fails the strict test, or the twin's plane holds the point), but rounding can
// tip it either way; excluding those faces by index makes every backend answer the same question at
// every width. In a one-sided scene every face is its own sheet and this is the paper's own-face rule.
inline bool is_own_surface(const FaceSheets& sheets, const SegmentBatch& batch, std::size_t segment, int face) {
  return sheets.same(face, batch.source_face) || sheets.same(face, batch.end_faces[segment]);
}

// How many faces the own-surface rule excludes for a segment from source_face to end_face.
inline std::size_t own_surface_faces(const FaceSheets& sheets, int source_face, int end_face) {
  const auto source = static_cast<std::size_t>(sheets.size_of(source_face));
  return sheets.same(source_face, end_face) ? source : source + static_cast<std::size_t>(sheets.size_of(end_face));
}

class VisibilityBackend {
 public:
  virtual ~VisibilityBackend() = default;
  virtual std::string name() const = 0;
  // Called once before the first step with the faces (triangles) of the normalised scene and the
  // sheets they form (default: every face its own sheet). Keeps the sheets for the own-surface rule
  // (sheets()) and hands the faces to the backend.
  void load_faces(const std::vector<Triangle>& faces, const FaceSheets& sheets = {}) {
    sheets_ = sheets;
    load_triangles(faces);
  }
  // Starts answering one step. A backend may work asynchronously (the board does): the solver
  // computes form factors between submit() and collect(), which is the paper's concurrent mode.
  virtual void submit(const SegmentBatch& batch) = 0;
  // Returns, for every segment of the last submitted batch, 1 if any other face blocks it.
  virtual void collect(std::vector<std::uint8_t>& blocked) = 0;
  // Segment-triangle tests performed so far (what the cost model charges).
  virtual std::uint64_t tests_performed() const = 0;
  // True when the tests run on the host CPU (software backends), so the host pays for them.
  virtual bool runs_on_host() const { return true; }
  // The sheets of the faces last loaded.
  const FaceSheets& sheets() const { return sheets_; }

 protected:
  bool is_own_surface(const SegmentBatch& batch, std::size_t segment, int face) const {
    return rc::is_own_surface(sheets_, batch, segment, face);
  }

 private:
  // The faces of load_faces; sheets() already holds their sheets.
  virtual void load_triangles(const std::vector<Triangle>& faces) = 0;

  FaceSheets sheets_;
};

}  // namespace rc
