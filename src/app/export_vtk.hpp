// nbscope app: --export-vtk DIR of replay and headless (and watch): each frame the loop checks
// written as VTK XML PolyData, the run as DIR/series.pvd (io/vtk_export.hpp; docs/export.md).
#pragma once
#include <string>

#include "app/option_spec.hpp"
#include "check/frame_result.hpp"
#include "core/elements.hpp"
#include "io/vtk_export.hpp"

namespace nbscope {

// --export-vtk's row.
OptionSpec export_vtk_option();
// The frame of `result` (its elements `elements`) as the exporter takes it: points, the columns,
// R and the selected lane's A. Pointers into both arguments.
VtkFrame vtk_frame_of(const Elements& elements, const FrameResult& result);

}  // namespace nbscope
