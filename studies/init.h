// `camopt init KIND`: a complete study file to start from, for every kind.
#pragma once

#include <map>
#include <string>

namespace camopt::studies {

/// The examples `camopt init` starts from, name → text (generated from studies/examples/ by
/// cmake/embed_templates.cmake; the list is CAMOPT_INIT_TEMPLATES in cmake/camopt_schemas.cmake).
const std::map<std::string, std::string>& EmbeddedTemplates();

/// What `camopt init KIND` writes.
struct InitStudy {
  std::string text;            ///< the study file, JSON, two-space indent, ending in a newline
  std::string example;         ///< the example it was written from ("lcr_ii")
  bool every_default = false;  ///< every field the kind declares is written out, defaults filled in
};

/// The kind's template example as its declaration reads it, written back with every field and
/// default spelled out (the declared kinds' echo, studies/archive.h); a kind not declared once
/// gets the example as it is (every_default false). @throws StudyError for an unknown kind,
/// naming the kinds and the nearest one.
InitStudy InitTemplate(const std::string& kind);

}  // namespace camopt::studies
