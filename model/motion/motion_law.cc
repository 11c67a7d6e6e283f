#include "model/motion/motion_law.h"

namespace camopt::motion {

namespace {
struct LawEntry {
  MotionLaw law;
  const char* name;
};
constexpr LawEntry kLaws[] = {
    {MotionLaw::kDwell, "dwell"},
    {MotionLaw::kCycloidal, "cycloidal"},
    {MotionLaw::kSimpleHarmonic, "simple_harmonic"},
    {MotionLaw::kModifiedSine, "modified_sine"},
    {MotionLaw::kModifiedTrapezoid, "modified_trapezoid"},
    {MotionLaw::kPolynomial345, "poly_345"},
    {MotionLaw::kPolynomial4567, "poly_4567"},
    {MotionLaw::kPolynomial, "polynomial"},
    {MotionLaw::kBSpline, "bspline"},
};
}  // namespace

std::string LawName(MotionLaw law) {
  for (const auto& e : kLaws)
    if (e.law == law) return e.name;
  return "unknown";
}

std::optional<MotionLaw> LawFromName(const std::string& name) {
  for (const auto& e : kLaws)
    if (name == e.name) return e.law;
  return std::nullopt;
}

std::vector<std::string> LawNames() {
  std::vector<std::string> names;
  for (const auto& e : kLaws) names.push_back(e.name);
  return names;
}

}  // namespace camopt::motion
