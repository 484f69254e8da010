// nbscope physics: one frame as the pipeline (check/pipeline.hpp) and the views read it: its
// elements, shapes and Box2D side, and what travels with it (atom ids, a code's own pairs and their
// precision). The live Box2D world (physics/live_world.hpp), a kept past frame
// (physics/kept_frame.hpp) and a recorded frame are one kind of thing; the run they belong to,
// stepped and shown, is a FrameSource (io/frame_source.hpp).
#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include "core/elements.hpp"
#include "core/pairs.hpp"
#include "core/subdomain_grid.hpp"
#include "physics/atom_columns.hpp"
#include "physics/box2d_frame.hpp"
#include "physics/shapes.hpp"

namespace nbscope {

class Frame {
 public:
  virtual ~Frame() = default;
  // The frame's number and simulated time in seconds (a recording's own).
  [[nodiscard]] virtual std::int64_t frame() const = 0;
  [[nodiscard]] virtual double time() const = 0;
  // The frame's elements (bounding circles).
  [[nodiscard]] virtual const Elements& elements() const = 0;
  // Element -> (body, fixture); empty when the frame has no bodies.
  [[nodiscard]] virtual const std::vector<ElementSource>& element_sources() const = 0;
  // Bodies that exist at this frame (0 without bodies).
  [[nodiscard]] virtual std::int64_t body_count() const = 0;
  // Every shape at this frame in world coordinates, for drawing (clears `out` first).
  virtual void body_shapes(std::vector<BodyShape>& out) const = 0;
  // Box2D's side of the frame for the check, or null when there is none (recorded frames).
  [[nodiscard]] virtual const Box2dFrame* box2d() const = 0;
  // The atom ids of the elements' rows (a dump's, ascending), or null when rows name them.
  [[nodiscard]] virtual std::shared_ptr<const std::vector<std::int64_t>> ids() const { return nullptr; }
  // The code's own contact pairs of this frame (0-based rows), or null when it gives none.
  [[nodiscard]] virtual const PairList* recorded_pairs() const { return nullptr; }
  // What the positions behind recorded_pairs() resolve (check/check.hpp's precision band); 0: exact.
  [[nodiscard]] virtual double precision() const { return 0; }
  // The MPI rank whose file held each row (a run's per-rank dumps), or null when one file set did.
  [[nodiscard]] virtual const std::vector<std::int32_t>* ranks() const { return nullptr; }
  // With ranks: each rank's subdomain as the run split the box, or null when not known.
  [[nodiscard]] virtual const Subdomains* subdomains() const { return nullptr; }
  // The frame's other per-atom columns (a dump's type, vx, proc, ...), or null when it has none.
  [[nodiscard]] virtual std::shared_ptr<const AtomColumns> columns() const { return nullptr; }
};

// One dynamic circle per element: how frames without bodies are drawn.
inline void circles_of(const Elements& e, std::vector<BodyShape>& out) {
  out.clear();
  out.resize(static_cast<std::size_t>(e.size()));
  for (Eigen::Index k = 0; k < e.size(); ++k) {
    BodyShape& b = out[static_cast<std::size_t>(k)];
    b.element = static_cast<ElementId>(k);
    b.centre = Vec2{e.x[k], e.y[k]};
    b.radius = e.r[k];
  }
}

}  // namespace nbscope
