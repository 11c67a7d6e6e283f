// The JSON Schemas of the study kinds, compiled into camopt from studies/schema/ at build time
// (cmake/embed_schemas.cmake). docs/studies.md says how they are kept in step with the parsers.
#pragma once

#include <map>
#include <string>

namespace camopt::studies {

/// kind → the text of `studies/schema/KIND.schema.json` (JSON Schema draft 2020-12).
const std::map<std::string, std::string>& EmbeddedSchemas();

/// The schema of a study kind; throws StudyError "schema KIND: expected a known study kind
/// (…), found KIND" for a kind without one.
const std::string& StudySchema(const std::string& kind);

}  // namespace camopt::studies
