// The one status of a run's answer. Every view of the answer — the exit code, the verdict line on
// stdout and in report.html, result.json's "status" and "verified", a sweep's case status — is a
// function of it, so they cannot disagree.
//
// Sizing and tuning kinds set their status from what the optimizer and the accurate model's
// verification (objectives/verification.h) found; analyses get theirs from the limits of their
// verdict (studies/report.h, EvaluateHeadlines), or "not_converged" when their own solver says so.
//
//   status                 meaning                                                   exit
//   optimal_verified       the optimizer's local test met; every limit verified         0
//   feasible_verified      every limit verified; the optimizer did not prove the       0 (3 with --strict)
//                          design locally optimal (a smaller one may exist)
//   infeasible             no design meets the limits (nothing to verify)               3
//   not_verifiable         the answer's limits cannot be checked by the accurate        3
//                          model (a quantity that does not converge, no check run)
//   not_converged          the solve or the verification did not reach an answer         3
//   limits_met             an analysis within every limit of its verdict                0
//   limits_exceeded        an analysis over a limit of its verdict                      0 (3 with --strict)
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace camopt::studies {

enum class Status {
  kOptimalVerified,
  kFeasibleVerified,
  kInfeasible,
  kNotVerifiable,
  kNotConverged,
  kLimitsMet,
  kLimitsExceeded,
};

/// Every status, in the order above (the result schema's enum, StatusFromName).
inline constexpr Status kAllStatuses[] = {Status::kOptimalVerified, Status::kFeasibleVerified, Status::kInfeasible,
                                          Status::kNotVerifiable,   Status::kNotConverged,     Status::kLimitsMet,
                                          Status::kLimitsExceeded};

/// result.json's spelling: "optimal_verified", "feasible_verified", "infeasible", "not_verifiable",
/// "not_converged", "limits_met", "limits_exceeded".
const char* StatusName(Status status);

/// The status of a spelling of StatusName, or nothing (a result.json of an older camopt).
std::optional<Status> StatusFromName(const std::string& name);

/// The `verified` flag of a sizing or tuning result: the status is one of the two verified ones.
bool IsVerified(Status status);

/// The exit code of a run that ended with `status`: 0 (the answer is what was asked) or 3 (it ran
/// to the end but the answer is not what was asked); `strict` (--strict) also gives 3 for a
/// verified design not proven optimal and for an analysis over a limit.
int ExitCode(Status status, bool strict);

/// The status of a sizing or tuning answer from what its search found: whether there is a design,
/// whether the accurate model's check ran on it, whether it holds, and whether the optimizer's own
/// test was met.
Status SizingStatus(bool has_design, bool verification_ran, bool verified, bool converged);

/// Asked means answered: a block of result.json that a study asks for by giving a field (an
/// output mechanism with clearance, a stiffness, tolerances, a speed for the lives, dynamics, an
/// export). When the study has any of `asked` (JSON pointers into the study) and result.json has no
/// `answer` (a JSON pointer into it), or has it null or as {"skipped": why} or {"error": why}, the
/// answer is incomplete: RunStudy gives it not_converged (exit 3) naming the block and why, never
/// exit 0 without it.
struct AskedBlock {
  std::vector<std::string> asked;
  std::string answer;
  std::string what;  ///< "the bearing lives"
  /// The lazy stages that compute it: with `analysis.evaluate` given and none of these in it, the
  /// block is not asked for (empty: not a stage of its own).
  std::vector<std::string> stages = {};
  /// Where the result says why the answer is null, when not inside the answer itself (a string;
  /// empty: nowhere else).
  std::string reason = {};
};

/// The blocks `kind` computes on request (KindDescriptor::asked).
const std::vector<AskedBlock>& AskedBlocks(const std::string& kind);

/// The blocks that `study` asks for and `result` lacks, each as "what (answer pointer)".
std::vector<std::string> MissingAnswers(const std::string& kind, const nlohmann::json& study,
                                        const nlohmann::json& result);

}  // namespace camopt::studies
