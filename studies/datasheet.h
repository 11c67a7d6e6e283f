// datasheet.html: a reducer's catalogue page (docs/ratings.md) — ratings, stiffness, lost motion,
// accuracy, efficiency, bearing lives, dimensions and mass — laid out as the reducer makers' rating
// tables are, every number read from result.json and shown with its source (its JSON pointer).
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "studies/study.h"

namespace camopt::studies {

/// One row: a number of result.json (`pointer`) times `scale` in `unit`; `why_pointer`, when the
/// number is absent or null, points at the text that says why (a "not computed: …" string).
struct DatasheetRow {
  std::string label, pointer, unit;
  double scale = 1.0;
  std::string why_pointer = "";
};

struct DatasheetSection {
  std::string title;
  std::vector<DatasheetRow> rows;
};

/// A kind's page: its sections, the drawings of the run it shows (file names), and the result
/// pointer whose presence asks for the page (the study gave the blocks it reads).
struct DatasheetSpec {
  std::string when_pointer;
  std::vector<DatasheetSection> sections;
  std::vector<std::string> figures;
};

/// The page for `result` (pure: tests call it), `figures` the SVG texts to embed by file name.
std::string DatasheetHtml(const DatasheetSpec& spec, const nlohmann::json& result,
                          const std::vector<std::pair<std::string, std::string>>& figures);

/// Adds datasheet.html to `outputs` when `kind` has one (KindDescriptor::datasheet) and result.json has its
/// `when_pointer`; the life table of /life, when present, is added as rows.
void AddDatasheet(const std::string& kind, Outputs& outputs);

}  // namespace camopt::studies
