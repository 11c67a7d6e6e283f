// The SUNDIALS CVODE objects of one integration, owned together (the globoidal turret's contact
// dynamics and the disc cam follower's both integrate a 2-state system with contact events).
#pragma once

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <stdexcept>
#include <string>

namespace camopt {

/// RAII owner of a CVODE integrator with a dense linear solver: context, state and dense-output
/// vectors, matrix, linear solver and the integrator memory, freed in reverse order.
struct CvodeSolver {
  SUNContext ctx = nullptr;
  N_Vector y = nullptr, dense = nullptr;
  SUNMatrix a = nullptr;
  SUNLinearSolver ls = nullptr;
  void* mem = nullptr;
  CvodeSolver() {
    if (SUNContext_Create(nullptr, &ctx) != 0) throw std::runtime_error("SUNContext_Create failed");
  }
  ~CvodeSolver() {
    if (mem) CVodeFree(&mem);
    if (ls) SUNLinSolFree(ls);
    if (a) SUNMatDestroy(a);
    if (dense) N_VDestroy(dense);
    if (y) N_VDestroy(y);
    SUNContext_Free(&ctx);
  }
  CvodeSolver(const CvodeSolver&) = delete;
  CvodeSolver& operator=(const CvodeSolver&) = delete;
};

/// Throws std::runtime_error("WHO: CVODE setup failed in WHAT") for a negative CVODE flag.
inline void RequireCvode(int flag, const char* who, const char* what) {
  if (flag < 0) throw std::runtime_error(std::string(who) + ": CVODE setup failed in " + what);
}

/// An error handler that prints nothing: failures are reported by the flags, translated by the caller.
inline void QuietCvodeErrors(int, const char*, const char*, char*, void*) {}

}  // namespace camopt
