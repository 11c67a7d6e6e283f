// The table of functions the OpenCASCADE module (libcamopt_occt.so, cad/occt.cc) gives the rest
// of camopt. cad/solid.cc opens the module on first use and calls through this table; the module
// is built with camopt, by the same compiler, so the C++ types cross as they are. The version
// changes whenever the table does: a module of another build is refused, not called.
#pragma once

#include <string>
#include <vector>

#include "cad/solid.h"

namespace camopt::cad {

inline constexpr int kOcctModuleVersion = 1;

struct OcctFunctions {
  int version;
  /// OCCT's mesh of the extruded solid (a profile that is not star-shaped about the centre).
  TriangleMesh (*extrusion_mesh)(const Extrusion& e);
  SurfaceOutput (*bspline_surfaces)(const std::vector<PointGrid>& grids, const std::string& name,
                                    double tolerance_mm);
  double (*max_distance_to_step_faces)(const std::string& content,
                                       const std::vector<Eigen::Vector3d>& points);
  StepReadBack (*read_step)(const std::string& content);
  AssemblyReadBack (*read_step_assembly)(const std::string& content);
};

/// The module's one exported symbol: extern "C" const OcctFunctions* camopt_occt_functions().
inline constexpr char kOcctModuleEntry[] = "camopt_occt_functions";
/// The module's file name, looked for beside the binary that holds camopt's code and in the
/// library folder of its install tree (cad/solid.cc).
inline constexpr char kOcctModuleFile[] = "libcamopt_occt.so";

}  // namespace camopt::cad
