// cad/solid.h without OpenCASCADE: the extruded solid's STEP file and mesh are written directly
// (cad/extrusion.h); what needs the kernel (the mesh of a profile that is not star-shaped, B-spline
// surfaces, reading STEP back) is called in the module libcamopt_occt.so (cad/occt.cc), opened on
// first use. Linked directly, OCCT's 60-odd shared libraries cost every process about 0.1 s of CPU
// at start (the loader's symbol lookups), also the runs that never call it (docs/performance.md,
// "A process's start").
#include "cad/solid.h"

#include <dlfcn.h>
#include <link.h>

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

#include "cad/occt_module.h"

#ifndef CAMOPT_INSTALL_LIBDIR
#define CAMOPT_INSTALL_LIBDIR "lib"
#endif

namespace camopt::cad {

namespace {

// The file of the binary that holds this code: a shared library (libcamopt.so, from its link map)
// or, for an executable, /proc/self/exe (dladdr gives an executable's argv[0], not its path).
std::filesystem::path OwnBinary() {
  Dl_info info{};
  link_map* map = nullptr;
  if (dladdr1(reinterpret_cast<void*>(&OwnBinary), &info, reinterpret_cast<void**>(&map), RTLD_DL_LINKMAP) != 0 &&
      map != nullptr && map->l_name != nullptr && map->l_name[0] != '\0') {
    return map->l_name;
  }
  std::error_code ec;
  std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::filesystem::path() : exe;
}

const OcctFunctions* OpenOcctModule() {
  const std::filesystem::path dir = OwnBinary().parent_path();
  // Beside the binary (the build folder; the wheel's camopt.libs/ beside libcamopt.so; an install's
  // lib/ beside libcamopt.so), then the install tree's library folder seen from its bin/.
  const std::vector<std::filesystem::path> candidates = {
      dir / kOcctModuleFile, dir / ".." / CAMOPT_INSTALL_LIBDIR / kOcctModuleFile};
  std::string tried;
  for (const std::filesystem::path& candidate : candidates) {
    std::error_code ec;
    if (!std::filesystem::exists(candidate, ec)) {
      tried += "\n  " + candidate.lexically_normal().string() + ": no such file";
      continue;
    }
    void* handle = dlopen(candidate.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle == nullptr) {
      const char* why = dlerror();
      tried += "\n  " + candidate.lexically_normal().string() + ": " + (why ? why : "not loaded");
      continue;
    }
    using Entry = const OcctFunctions* (*)();
    const auto entry = reinterpret_cast<Entry>(dlsym(handle, kOcctModuleEntry));
    const OcctFunctions* functions = entry ? entry() : nullptr;
    if (functions == nullptr || functions->version != kOcctModuleVersion) {
      tried += "\n  " + candidate.lexically_normal().string() + ": a module of another camopt build";
      dlclose(handle);
      continue;
    }
    return functions;  // kept open for the process's life
  }
  throw std::runtime_error(std::string("OpenCASCADE is needed here (STEP surfaces, the mesh of a profile that is "
                                       "not star-shaped, reading STEP back), and its module ") +
                           kOcctModuleFile + ", built and installed with camopt, was not loaded:" + tried);
}

// Opened once per process (a failure is tried again on the next call, and says why each time).
const OcctFunctions& Occt() {
  static const OcctFunctions* const functions = OpenOcctModule();
  return *functions;
}

}  // namespace

SolidOutput ExtrudeCam(const Extrusion& e) {
  SolidOutput out;
  // The B-rep and, for a profile star-shaped about the centre, the mesh are written directly
  // (cad/extrusion.h): no kernel, no process-wide lock.
  try {
    if (e.step) out.step = StepOfExtrusion(e);
    out.faces = static_cast<int>(e.profile.size()) + 2 + static_cast<int>(BoreChain(e).size()) + 2 * int(e.holes.size());
    if (std::optional<TriangleMesh> mesh = MeshExtrusion(e, MeshDeflection(e), e.step)) {
      out.mesh = std::move(*mesh);
      return out;
    }
  } catch (const std::invalid_argument& bad) {
    throw std::runtime_error(std::string("extruded cam: ") + bad.what());
  }
  out.mesh = Occt().extrusion_mesh(e);
  return out;
}

SurfaceOutput BSplineSurfaces(const std::vector<PointGrid>& grids, const std::string& name, double tolerance_mm) {
  return Occt().bspline_surfaces(grids, name, tolerance_mm);
}

double MaxDistanceToStepFaces(const std::string& content, const std::vector<Eigen::Vector3d>& points) {
  return Occt().max_distance_to_step_faces(content, points);
}

StepReadBack ReadStep(const std::string& content) { return Occt().read_step(content); }

AssemblyReadBack ReadStepAssembly(const std::string& content) { return Occt().read_step_assembly(content); }

}  // namespace camopt::cad
