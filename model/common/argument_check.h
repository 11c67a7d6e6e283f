// The argument checks of the model's functions: a value out of its range is refused with
// std::invalid_argument "WHAT: FIELD must be REQUIREMENT, found VALUE" (12 significant digits),
// WHAT naming the model (a module binds it once: bearing_life_internal, output_bearing_internal, ...).
#pragma once

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "model/common/scalar.h"

namespace camopt::argument_check {

[[noreturn]] inline void Reject(const char* what, const std::string& field, const std::string& requirement,
                                double found) {
  std::ostringstream os;
  os.precision(12);
  os << what << ": " << field << " must be " << requirement << ", found " << found;
  throw std::invalid_argument(os.str());
}

/// x finite and > 0 (of a Jet, its value).
template <typename T>
void Positive(const char* what, const std::string& field, const T& x) {
  const double v = Value(x);
  if (!(std::isfinite(v) && v > 0.0)) Reject(what, field, "finite and > 0", v);
}

/// x finite and >= 0.
template <typename T>
void NonNegative(const char* what, const std::string& field, const T& x) {
  const double v = Value(x);
  if (!(std::isfinite(v) && v >= 0.0)) Reject(what, field, "finite and >= 0", v);
}

/// x finite.
template <typename T>
void Finite(const char* what, const std::string& field, const T& x) {
  const double v = Value(x);
  if (!std::isfinite(v)) Reject(what, field, "finite", v);
}

}  // namespace camopt::argument_check
