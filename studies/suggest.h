// "Did you mean …?" for a misspelt name: the nearest of the names a field, an enum or the command
// line accepts.
#pragma once

#include <string>
#include <vector>

namespace camopt::studies {

/// The candidate nearest to `word` by the optimal-string-alignment distance (insertions,
/// deletions, substitutions and swaps of two neighbours each cost 1; case ignored), when that
/// distance is at most max(1, length/3) of the longer of the two and the choice is unique; ""
/// otherwise (no suggestion beats a wrong one).
std::string NearestName(const std::string& word, const std::vector<std::string>& candidates);

/// The names listed in an expected-value text: the quoted ones ("\"ipopt\", \"slsqp\"") or, after
/// "one of " or inside the first parentheses, the comma-separated words.
std::vector<std::string> NamesInExpected(const std::string& expected);

}  // namespace camopt::studies
