// The SUNDIALS CVODE objects of one integration, owned together (the globoidal turret's contact
// dynamics and the disc cam follower's both integrate a 2-state system with contact events).
#pragma once

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <new>
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

/// Sets sv up for y' = rhs(t, y) from y(0) = y0 (n states): BDF with Newton iterations on a dense
/// n × n system, scalar tolerances, quiet errors, `user` handed to rhs and to the nroots root
/// functions. sv.y holds the state, sv.dense is the dense-output buffer. `who` names the caller
/// in setup errors. `method` CV_ADAMS instead suits a lightly damped oscillator (the torsional
/// model, model/common/torsional_dynamics.cc): Adams–Moulton has no BDF's damping of the
/// oscillation at orders above 2.
inline void StartBdfDense(CvodeSolver& sv, const double* y0, int n, CVRhsFn rhs, void* user, double rtol,
                          double atol, CVRootFn roots, int nroots, const char* who, int method = CV_BDF) {
  sv.y = N_VNew_Serial(n, sv.ctx);
  sv.dense = N_VNew_Serial(n, sv.ctx);
  if (!sv.y || !sv.dense) throw std::bad_alloc();
  double* y = N_VGetArrayPointer(sv.y);
  for (int i = 0; i < n; ++i) y[i] = y0[i];
  sv.mem = CVodeCreate(method, sv.ctx);
  if (!sv.mem) throw std::runtime_error(std::string(who) + ": CVodeCreate failed");
  RequireCvode(CVodeInit(sv.mem, rhs, 0.0, sv.y), who, "CVodeInit");
  RequireCvode(CVodeSetErrHandlerFn(sv.mem, QuietCvodeErrors, nullptr), who, "CVodeSetErrHandlerFn");
  RequireCvode(CVodeSetUserData(sv.mem, user), who, "CVodeSetUserData");
  RequireCvode(CVodeSStolerances(sv.mem, rtol, atol), who, "tolerances");
  sv.a = SUNDenseMatrix(n, n, sv.ctx);
  sv.ls = SUNLinSol_Dense(sv.y, sv.a, sv.ctx);
  RequireCvode(CVodeSetLinearSolver(sv.mem, sv.ls, sv.a), who, "CVodeSetLinearSolver");
  if (nroots > 0) RequireCvode(CVodeRootInit(sv.mem, nroots, roots), who, "CVodeRootInit");
}

}  // namespace camopt
