// nbscope ui: the z-lists of a 3D frame as the Layers panel shows them (book p.123: heads C[nz],
// next Z) — read from an NBS 3D trace's arrays (at the stepper's operation, so they agree with the
// Arrays panel, or finished), else built from the layers as the book's loop builds them — and the
// stepper's place in layers and rows. No ImGui: unit-tested without a context.
//
// Index: ZLists | zlists_from_trace | zlists_from_layers | zlist_text.
#pragma once
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/layers.hpp"
#include "core/stepper.hpp"
#include "core/trace.hpp"

namespace nbscope::ui {

// Every z-list of a frame: the heads and each layer's chain through Z.
struct ZLists {
  enum class Source : std::uint8_t { Stepper, Trace, Layers };
  std::vector<std::int32_t> heads;                  // C[iz] (-1: an empty list)
  std::vector<std::vector<std::int32_t>> chains;    // per layer: C[iz], Z[C[iz]], ... head first
  Source source = Source::Layers;
  std::size_t position = 0, events = 0;  // Stepper: the operation they stand at, of how many
};

// The z-lists in the traced arrays "C" and "Z" of `log` as they stand in `state` (the stepper's
// state after its position: an unfinished list is what the Arrays panel shows). nullopt when the
// trace has no such arrays (not NBS 3D). Chains stop after every element once (a corrupt cycle).
[[nodiscard]] std::optional<ZLists> zlists_from_state(const TraceLog& log, const ArrayState& state);
// The finished z-lists of a whole NBS 3D trace: Z as left at the end, each head C[iz] as it was
// just before the detector cleared it. nullopt when the trace has no C and Z.
[[nodiscard]] std::optional<ZLists> zlists_from_trace(const TraceLog& log);
// The z-lists as the book's first loop builds them from the layers of `slice` (k = 0..N-1, each
// pushed at the front: C[iz] holds the layer's highest index, Z links downwards).
[[nodiscard]] ZLists zlists_from_layers(const LayerSlice& slice);
// "C[2] = 17: 17 -> 12 -> 3 -> -1", the chain cut with "..." past `max_shown` elements. Elements
// are rows in the chosen numbering, as the arrays hold them (a dump's atom ids too: the Arrays and
// the Stepper say the same).
[[nodiscard]] std::string zlist_text(const ZLists& z, std::int32_t layer, bool book, std::size_t max_shown = 12);

}  // namespace nbscope::ui
