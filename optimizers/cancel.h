// Cooperative cancellation of a run, process-wide: an embedding program (the Python module on
// Ctrl-C, the command line's signal thread) asks for it with RequestCancel; long work checks it
// where it already reports progress (studies/study.h, Progress::Update) and in the solvers'
// iteration callbacks (optimizers/), and unwinds by throwing Cancelled. Nothing is written by a
// cancelled run: a study's Outputs are written whole at the end only.
//
// Here, in optimizers/, because the solvers are the lowest room that checks it.
#pragma once

namespace camopt::optimizers {

/// Thrown by ThrowIfCancelled. Deliberately not a std::exception: the handlers that turn a
/// std::exception into a failed solve, a failed sweep case or an "internal error" let it through,
/// so a cancellation always reaches the caller that asked for it.
class Cancelled {
 public:
  const char* what() const noexcept { return "cancelled"; }
};

/// Asks every run in this process to stop (async-signal-safe: one atomic store).
void RequestCancel() noexcept;
/// Clears the request (the Python module does, before a run and after a cancelled one).
void ClearCancel() noexcept;
bool CancelRequested() noexcept;
/// Throws Cancelled when a cancellation was asked for.
void ThrowIfCancelled();

}  // namespace camopt::optimizers
