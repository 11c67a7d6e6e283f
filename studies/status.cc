#include "studies/status.h"

namespace camopt::studies {

const char* StatusName(Status status) {
  switch (status) {
    case Status::kOptimalVerified: return "optimal_verified";
    case Status::kFeasibleVerified: return "feasible_verified";
    case Status::kInfeasible: return "infeasible";
    case Status::kNotVerifiable: return "not_verifiable";
    case Status::kNotConverged: return "not_converged";
    case Status::kLimitsMet: return "limits_met";
    case Status::kLimitsExceeded: return "limits_exceeded";
  }
  return "not_converged";
}

std::optional<Status> StatusFromName(const std::string& name) {
  for (Status s : {Status::kOptimalVerified, Status::kFeasibleVerified, Status::kInfeasible, Status::kNotVerifiable,
                   Status::kNotConverged, Status::kLimitsMet, Status::kLimitsExceeded})
    if (name == StatusName(s)) return s;
  return std::nullopt;
}

bool IsVerified(Status status) {
  return status == Status::kOptimalVerified || status == Status::kFeasibleVerified;
}

int ExitCode(Status status, bool strict) {
  switch (status) {
    case Status::kOptimalVerified:
    case Status::kLimitsMet: return 0;
    case Status::kFeasibleVerified:
    case Status::kLimitsExceeded: return strict ? 3 : 0;
    case Status::kInfeasible:
    case Status::kNotVerifiable:
    case Status::kNotConverged: return 3;
  }
  return 3;
}

Status SizingStatus(bool has_design, bool verification_ran, bool verified, bool converged) {
  if (!has_design) return Status::kInfeasible;
  if (verified) return converged ? Status::kOptimalVerified : Status::kFeasibleVerified;
  if (!verification_ran) return Status::kNotVerifiable;
  // The accurate model rejects the design the search ended on: after its tightening rounds when
  // the optimizer converged (the verification did not converge to a design that holds), or at an
  // infeasible stopping point of the optimizer.
  return converged ? Status::kNotConverged : Status::kInfeasible;
}

}  // namespace camopt::studies
