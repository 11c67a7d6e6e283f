#include "optimizers/cancel.h"

#include <atomic>

namespace camopt::optimizers {

namespace {
std::atomic<bool> g_cancel{false};
static_assert(std::atomic<bool>::is_always_lock_free, "RequestCancel must be async-signal-safe");
}  // namespace

void RequestCancel() noexcept { g_cancel.store(true); }
void ClearCancel() noexcept { g_cancel.store(false); }
bool CancelRequested() noexcept { return g_cancel.load(std::memory_order_relaxed); }
void ThrowIfCancelled() {
  if (CancelRequested()) throw Cancelled();
}

}  // namespace camopt::optimizers
