// The evaluations a problem has run, looked up by their point: a solver asks for the values and
// then the Jacobian of one point (or a verification re-reads the optimum), and the model runs
// once. Every problem that wraps an expensive model (the cycloid sizing and tuning, the crowning
// scan) keeps its evaluations here.
#pragma once

#include <cstddef>
#include <deque>
#include <functional>
#include <utility>
#include <vector>

namespace camopt::objectives {

template <typename Evaluation>
class EvaluationMemo {
 public:
  /// Keeps the last `capacity` points (0: every point run); `on_new` sees each new evaluation.
  explicit EvaluationMemo(size_t capacity = 0, std::function<void(const Evaluation&)> on_new = {})
      : capacity_(capacity), on_new_(std::move(on_new)) {}

  /// The kept evaluation at exactly `key` that `usable` accepts (one with a gradient, when asked
  /// for), else `evaluate()`'s, kept. The reference holds until `capacity` newer points are run.
  template <typename Usable, typename Evaluate>
  const Evaluation& Get(const std::vector<double>& key, Usable&& usable, Evaluate&& evaluate) {
    for (const Entry& e : memory_)
      if (e.key == key && usable(e.value)) return e.value;
    if (capacity_ > 0 && memory_.size() >= capacity_) memory_.pop_front();
    memory_.push_back({key, evaluate()});
    if (on_new_) on_new_(memory_.back().value);
    return memory_.back().value;
  }

 private:
  struct Entry {
    std::vector<double> key;
    Evaluation value;
  };
  size_t capacity_;
  std::function<void(const Evaluation&)> on_new_;
  std::deque<Entry> memory_;
};

}  // namespace camopt::objectives
