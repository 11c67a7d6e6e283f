#include "model/motion/motion_law.h"

#include <cmath>
#include <limits>

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
    {MotionLaw::kQuadraticParabola, "quadratic_parabola"},
    {MotionLaw::kPolynomial, "polynomial"},
    {MotionLaw::kBSpline, "bspline"},
};
}  // namespace

std::optional<LawCharacteristics> Characteristics(MotionLaw law) {
  const double pi = kPi, inf = std::numeric_limits<double>::infinity();
  switch (law) {
    case MotionLaw::kCycloidal:  // VDI 2143 "geneigte Sinuslinie" (Bestehorn's sinoid)
      return LawCharacteristics{2.0, 2.0 * pi, 4.0 * pi * pi};
    case MotionLaw::kSimpleHarmonic:  // "einfache Sinuslinie"; a jumps to ±π²/2 against a dwell
      return LawCharacteristics{pi / 2.0, pi * pi / 2.0, inf};
    case MotionLaw::kModifiedSine:  // v peaks at u = 1/2, j on the first eighth (k = 1/(4 + π))
      return LawCharacteristics{4.0 * pi / (4.0 + pi), 4.0 * pi * pi / (4.0 + pi),
                                16.0 * pi * pi * pi / (4.0 + pi)};
    case MotionLaw::kModifiedTrapezoid:  // "modifiziertes Beschleunigungstrapez", k = 1/(2 + π)
      return LawCharacteristics{2.0, 8.0 * pi / (2.0 + pi), 32.0 * pi * pi / (2.0 + pi)};
    case MotionLaw::kPolynomial345: {  // "Polynom 5. Grades": a peaks at u = 1/2 ± √3/6
      return LawCharacteristics{15.0 / 8.0, 10.0 / std::sqrt(3.0), 60.0};
    }
    case MotionLaw::kPolynomial4567: {  // a peaks where j = 0: u = (5 − √5)/10
      const double u = (5.0 - std::sqrt(5.0)) / 10.0;
      return LawCharacteristics{35.0 / 16.0, 420.0 * u * u * (1 - u) * (1 - u) * (1 - 2 * u), 52.5};
    }
    case MotionLaw::kQuadraticParabola:  // "quadratische Parabel"
      return LawCharacteristics{2.0, 4.0, inf};
    case MotionLaw::kDwell:
    case MotionLaw::kPolynomial:
    case MotionLaw::kBSpline:
      return std::nullopt;
  }
  return std::nullopt;
}

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
