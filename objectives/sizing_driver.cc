#include "objectives/sizing_driver.h"

#include <stdexcept>

namespace camopt::objectives {

SizingDriverResult RunSizingDriver(const SizingCandidates& c,
                                   const std::function<void(double, const std::string&)>& progress) {
  if (!c.solve || !c.feasible_size || !c.verify) throw std::invalid_argument("RunSizingDriver: missing hooks");
  SizingDriverResult out;
  for (int i = 0; i < c.count; ++i) {
    if (progress) progress(double(i) / c.count, c.label ? c.label(i) : std::to_string(i + 1));
    c.solve(i);
  }
  if (progress) progress(1.0, std::to_string(c.count) + " candidates");
  std::vector<bool> checked(size_t(c.count), false);
  for (;;) {
    int best = -1;
    double smallest = 0;
    for (int i = 0; i < c.count; ++i) {
      const std::optional<double> size = c.feasible_size(i);
      if (size && (best < 0 || *size < smallest)) best = i, smallest = *size;
    }
    out.best = best;
    if (best < 0 || checked[size_t(best)]) break;  // none left, or checked and holds: the answer
    checked[size_t(best)] = true;
    out.verified.push_back(best);
    c.verify(best);
  }
  return out;
}

}  // namespace camopt::objectives
