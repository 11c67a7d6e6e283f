// A study kind written as the recipe of studies/kind.h says, and nothing more: an Input, a Result, a
// Run and one registration. It is linked into camopt_with_test_kind (the command line plus this
// file) only, and tests/test_kind_test.cc drives it there: `kinds`, `init`, `schema` (input and
// result), `run` with its report, and the studio. The physics is Hertz's line contact of a roller on
// a flat (model/contact/hertz.h); the test checks it against the closed form it writes itself.
#include <cmath>
#include <optional>
#include <string>

#include "model/contact/hertz.h"
#include "studies/kind.h"

namespace camopt::studies::test_line_contact {
namespace {

struct Input {
  std::string study = "test_line_contact", name;
  std::optional<std::string> description;
  double force_N = 1000, length_mm = 10, roller_radius_mm = 5;
  double youngs_modulus_MPa = 206000, poisson_ratio = 0.3;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("study", &study, Field().Required().Const("test_line_contact").Desc("the study kind"));
    a->Visit("name", &name, Field().Desc("the design's name, in titles"));
    a->Visit("description", &description, Field().Desc("free text"));
    a->Visit("force_N", &force_N, Field().Positive().Unit("N").Desc("the load on the roller"));
    a->Visit("length_mm", &length_mm, Field().Positive().Unit("mm").Desc("the roller's contact length"));
    a->Visit("roller_radius_mm", &roller_radius_mm, Field().Positive().Unit("mm").Desc("on a flat"));
    a->Visit("youngs_modulus_MPa", &youngs_modulus_MPa, Field().Positive().Unit("MPa").Desc("both bodies'"));
    a->Visit("poisson_ratio", &poisson_ratio, Field().AtLeast(0.0).Below(0.5).Desc("both bodies'"));
  }
};

struct Result {
  std::string study = "test_line_contact", name;
  double max_contact_stress_MPa = 0, half_width_mm = 0;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("study", &study, Field().Const("test_line_contact"));
    a->Visit("name", &name, Field().Desc("the design's name"));
    a->Visit("max_contact_stress_MPa", &max_contact_stress_MPa, Field().Unit("MPa").Desc("Hertz's peak pressure"));
    a->Visit("half_width_mm", &half_width_mm, Field().Unit("mm").Desc("the contact's half-width"));
  }
};

Result Run(const Input& in, const RunContext&) {
  const double e_star = CompositeModulus(in.youngs_modulus_MPa, in.poisson_ratio, in.youngs_modulus_MPa, in.poisson_ratio);
  Result r;
  r.name = in.name;
  r.max_contact_stress_MPa = contact::LineContactPeakPressure(in.force_N, in.length_mm, in.roller_radius_mm, e_star);
  r.half_width_mm = contact::LineContactHalfWidth(in.force_N, in.length_mm, in.roller_radius_mm, e_star);
  return r;
}

CAMOPT_REGISTER_KIND(Kind<Input, Result>{
    .name = "test_line_contact", .title = "camopt study: a roller on a flat (the test kind)", .run = Run});

}  // namespace
}  // namespace camopt::studies::test_line_contact
