// The JSON Schemas of the study kinds: each emitted from the kind's declaration (studies/archive.h),
// so that the schema, the parser and the docs' table cannot drift apart (docs/studies.md, "Keeping
// the schemas in step with the parsers").
#pragma once

#include <string>

namespace camopt::studies {

/// The schema of a study kind (JSON Schema draft 2020-12, DeclaredSchema); throws StudyError "schema KIND: expected a known study kind
/// (…), found KIND" for a kind without one.
const std::string& StudySchema(const std::string& kind);

/// The JSON Schema of KIND's result.json (`camopt schema KIND --result`), emitted from the
/// declaration of its result (studies/archive.h). @throws StudyError for an unknown kind or a kind
/// whose result is not declared yet, naming those that are.
const std::string& StudyResultSchema(const std::string& kind);

}  // namespace camopt::studies
