// --export-vtk (export_vtk.hpp).
#include "app/export_vtk.hpp"

namespace nbscope {

OptionSpec export_vtk_option() {
  return {"--export-vtk", "DIR", "",
          "writes each frame run, its contacts and its violations as VTK XML PolyData (DIR/frame_TIMESTEP.vtp: points with id, "
          "radius, overlap and the dump's columns; lines tagged contact, missing or extra) and the run as DIR/series.pvd, for "
          "ParaView and OVITO (docs/export.md); each file whole or not at all"};
}

VtkFrame vtk_frame_of(const Elements& elements, const FrameResult& result) {
  VtkFrame f;
  f.timestep = result.frame;
  f.elements = &elements;
  f.ids = result.ids.get();
  f.columns = result.columns.get();
  f.reference = &result.reference;
  f.detected = &result.selected().pairs;
  f.checked = result.report().checked;
  return f;
}

}  // namespace nbscope
