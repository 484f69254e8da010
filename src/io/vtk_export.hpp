// nbscope io: --export-vtk DIR (docs/export.md): each frame, its contacts and its violations as VTK
// XML PolyData (DIR/frame_TIMESTEP.vtp, ASCII) and the run as a ParaView collection (DIR/series.pvd),
// for ParaView and OVITO.
//
//   points      the atoms (z = 0 in 2D); point data: id, radius, overlap and every column the frame
//               keeps (type, vx, ..., proc: AtomColumns), each by its own name
//   verts       one per atom (so ParaView draws the points), cell data kind 0
//   lines       each pair of R and A (a frame not checked: A), cell data kind 1 contact (in both),
//               2 missing (in R, not in A), 3 extra (in A, not in R), and gap |c_i - c_j| - (r_i + r_j)
//
// Every file is written through a temporary and renamed into place (io/atomic_file.hpp): an error
// or an interruption leaves no half-written file; series.pvd is written by finish(), listing the
// frames written so far.
#pragma once
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "core/elements.hpp"
#include "core/pairs.hpp"
#include "physics/atom_columns.hpp"

namespace nbscope {

// The line cells' kinds (cell data `kind`); atoms' vertex cells are kVtkAtom.
enum VtkCellKind : std::int32_t { kVtkAtom = 0, kVtkContact = 1, kVtkMissing = 2, kVtkExtra = 3 };

// One frame to export; pointers stay owned by the caller.
struct VtkFrame {
  std::int64_t timestep = 0;                         // the file's name and the collection's timestep
  const Elements* elements = nullptr;
  const std::vector<std::int64_t>* ids = nullptr;    // each row's atom id (null or another size: the row)
  const AtomColumns* columns = nullptr;              // null: none
  const PairList* reference = nullptr;               // R, sorted (null or empty with `checked` false: not checked)
  const PairList* detected = nullptr;                // A, sorted
  bool checked = false;                              // R was computed: lines not in both are missing or extra
};

// The text of `frame` as a .vtp file.
std::string vtk_polydata(const VtkFrame& frame);

// A run's export into one directory.
class VtkSeries {
 public:
  // Creates `dir` when it does not exist; Error "--export-vtk: DIR: exists and is not a directory" or
  // "...: cannot make it (<why>)".
  explicit VtkSeries(std::string dir);
  // Writes DIR/frame_TIMESTEP.vtp (whole or not at all) and remembers it for the collection.
  void add(const VtkFrame& frame);
  // Writes DIR/series.pvd listing every frame added, in timestep order (a timestep added twice: its last file once).
  void finish();
  // The directory, and how many frames were written.
  [[nodiscard]] const std::string& dir() const { return dir_; }
  [[nodiscard]] std::size_t frames() const { return files_.size(); }

 private:
  std::string dir_;
  std::vector<std::pair<std::int64_t, std::string>> files_;  // timestep, file name
};

}  // namespace nbscope
