// The Pareto front of a sweep: the "ok" cases that no other ok case dominates over the sweep's
// objectives (the output columns to minimize or maximize). Its plots and page are in
// studies/sweep_report.h.
#pragma once

#include <cstddef>
#include <vector>

#include "studies/sweep.h"

namespace camopt::studies::sweep {

/// The objective values of a record, each oriented for minimisation (the minimised columns, then
/// the maximised ones negated); false when one is not a number.
bool Objectives(const Sweep& sweep, const CaseRecord& r, std::vector<double>& f);

/// The objectives' output columns: the minimised ones, then the maximised ones.
std::vector<size_t> ObjectiveColumns(const Sweep& sweep);

/// Whether an output column is an objective to maximize.
bool Maximized(const Sweep& sweep, size_t column);

/// The indices (into records) of the non-dominated "ok" records for the sweep's Pareto
/// objectives, in record order. Records with a non-numeric objective take no part.
std::vector<size_t> ParetoFront(const Sweep& sweep, const std::vector<CaseRecord>& records);

}  // namespace camopt::studies::sweep
