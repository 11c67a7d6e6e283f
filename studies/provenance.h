// Where a result comes from: the camopt version and the SHA-256 of the study that made it, both
// recorded in every result.json, and the plausibility warnings on a study's values.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace camopt::studies {

/// The version of this camopt build ("0.1.0", the project() version of CMakeLists.txt).
std::string CamoptVersion();

/// SHA-256 (FIPS 180-4) of `bytes`, as 64 lower-case hexadecimal digits (Nettle's).
std::string Sha256Hex(std::string_view bytes);

/// Values of a study that parse but are very likely a mistake (a modulus given in MPa under a GPa
/// key, a friction coefficient above 1, a cam speed of 1e6 rpm, a length of kilometres), as
/// "/json/path: what is odd" lines. The one place of these rules, for every kind: they look at
/// keys by their name and unit suffix (docs/studies.md, "Units").
std::vector<std::string> PlausibilityWarnings(const nlohmann::json& study);

}  // namespace camopt::studies
