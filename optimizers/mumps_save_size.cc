// MUMPS 5.3 and later compute, at the end of every call (analysis, factorisation, and each solve),
// how much disk and memory a `save` of the instance (JOB = 7) would take: dmumps_driver.F, "Compute
// space for save", and again in dmumps_sol_driver.F, both through
// DMUMPS_COMPUTE_MEMORY_SAVE(id, TOTAL_FILE_SIZE, TOTAL_STRUC_SIZE) of dmumps_save_restore.F, which
// walks the instance's 186 + 35 components by a Fortran SELECT CASE on their names. The two sizes
// only fill the informational RINFO(7:8) / RINFOG(17:18) and KEEP8(55:58); a save computes its own.
//
// Ipopt 3.11 solves one right-hand side per MUMPS call (its limited-memory Hessian's low-rank
// update alone takes 2 × history solves per matrix), and the sizing polish's augmented systems are
// small, so this bookkeeping was ≈ 27 % of the line-model LCR sizing's time and ≈ 10 % of the
// crowned one's (docs/performance.md, "Ipopt's linear solver"). camopt never saves a MUMPS
// instance (nor does Ipopt), so the program defines the routine to report both sizes as zero; the
// shared libdmumps calls it through its PLT, so the program's definition is the one bound. The
// factorisation and the solves are untouched: every sizing result is bit-identical.
//
// Compiled only when CMake found MUMPS 5.3–5.x headers (CAMOPT_MUMPS_SAVE_SIZE_OFF; the routine's
// module name and arguments are those of those versions), and exported from the executables with
// --export-dynamic-symbol (CMakeLists.txt). Elsewhere MUMPS keeps computing the sizes.
#include "optimizers/mumps_save_size.h"

#include <dlfcn.h>

#include <cstdint>

#ifdef CAMOPT_MUMPS_SAVE_SIZE_OFF
extern "C" __attribute__((visibility("default"))) void
__dmumps_save_restore_MOD_dmumps_compute_memory_save(void* /*id*/, std::int64_t* total_file_size,
                                                     std::int64_t* total_struc_size) {
  *total_file_size = 0;
  *total_struc_size = 0;
}
#endif

namespace camopt::optimizers {

bool MumpsSaveSizeSkipped() {
#ifdef CAMOPT_MUMPS_SAVE_SIZE_OFF
  // The definition the dynamic linker resolves for everybody (libdmumps included) is this one.
  return dlsym(RTLD_DEFAULT, "__dmumps_save_restore_MOD_dmumps_compute_memory_save") ==
         reinterpret_cast<void*>(&__dmumps_save_restore_MOD_dmumps_compute_memory_save);
#else
  return false;
#endif
}

}  // namespace camopt::optimizers
