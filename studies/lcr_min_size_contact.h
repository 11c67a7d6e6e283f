// The finite-length contact in lcr_min_size (docs/lcr.md, "Crowned rollers and 3D contact"):
// parsing of the top-level "contact" object, fixed.crowning, variables.crowning_coefficient_mm
// and load.overload_torque_Nm, and its part of result.json (the 3D solve of a candidate is in
// sizing/lcr_search.h). Kept apart from lcr_min_size_study.cc, which calls these hooks only when the
// study has a 3D contact.
#pragma once

#include <optional>

#include <nlohmann/json.hpp>

#include "sizing/lcr_search.h"
#include "sizing/lcr_sizing3d.h"
#include "studies/input.h"

namespace camopt::studies::lcr_min_size {

struct Input;
struct Study;
using Candidate = sizing::LcrCandidate;
struct Result;

/// The 3D contact of the study, or nothing (the line model: the fast path). roller_length_mm: the
/// longest roller the crowning must fit; catalogue: the rollers come from a catalogue (no roller
/// length variable). @throws StudyError: crowning, misalignment, an overload torque or a crowning
/// or length variable with the line model; a crowning variable the crowning type does not have;
/// ranges whose ends the crowning does not fit.
std::optional<sizing::LcrSizing3DSpec> ParseContact3D(const Input& in, const Node& root, double roller_length_mm,
                                                          bool catalogue);

/// Adds the 3D parts to result.json's members (r.json): "contact", best.input/output.crowning,
/// best.contact (3D peaks, edge margins, the line-model outer diameter), best.half_space_check,
/// and each candidate's crowning.
void AddContact3DJson(const Study& s, Result& r);

/// Adds crowning and contact to the best design's lcr_analysis study.
void AddContact3DAnalysis(const Study& s, const Candidate& best, nlohmann::json& analysis);

}  // namespace camopt::studies::lcr_min_size
