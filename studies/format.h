// Number formatting for messages and labels shared by every study kind (result files carry full
// precision through nlohmann::json and writers.h; this is for text a person reads).
#pragma once

#include <cstdio>
#include <string>

namespace camopt::studies {

/// v with `significant_digits` significant digits, as printf's %g (6 by default: "63.525",
/// "1e-09").
inline std::string Format(double v, int significant_digits = 6) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", significant_digits, v);
  return buf;
}

}  // namespace camopt::studies
