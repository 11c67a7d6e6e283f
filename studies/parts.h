// Whole parts of a design as a shop makes them (docs/parts.md): each part an extruded solid (its
// profile, bore and holes), drawn (DXF, layers PROFILE, CUTTER_PATH, BORE, HOLES, CENTRE_MARKS,
// TEXT), modelled (STEP AP214) and meshed (STL), named by part; the assembly of the parts' placed
// occurrences (assembly.step, an ISO 10303-214 product structure) and the bill of materials
// (bom.csv: part, count, material, volume, mass from volume × density, designation).
//
// The kinds build their PartsSet from their geometry (studies/cycloid_parts.h for the cycloid
// drive); this file writes it.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include "cad/arc_fit.h"
#include "cad/extrusion.h"
#include "studies/geometry_files.h"
#include "studies/study.h"

namespace camopt::studies {

/// One part: its solid in its own frame (z from 0 to the thickness) and what the BOM says of it.
struct Part {
  std::string name;         ///< file stem and product name: "disc_1", "ring_pins", …
  std::string description;  ///< one line: what it is
  std::string material;     ///< the BOM's material column
  int count = 1;            ///< occurrences in the assembly
  cad::Extrusion solid;     ///< profile (closed, counter-clockwise), bore, holes, thickness
  std::vector<cad::ArcSegment> cutter_path;  ///< the cutter's (grinding wheel's) centre path; empty: none
  double cutter_diameter_mm = 0.0;
  double volume_mm3 = 0.0;  ///< from the exact profile's area (not the arcs'), minus bore and holes
  double mass_kg = 0.0;     ///< volume × the set's density
  std::string designation;  ///< a catalogue designation (a bearing), or empty
  std::string note;         ///< what the drawing simplifies, or empty
};

/// The parts of one design, their placements in the assembly (cad::Placement::part indexes
/// `parts`) and the density the masses are from.
struct PartsSet {
  std::string design_name;
  std::vector<Part> parts;
  std::vector<cad::Placement> placements;
  double density_kg_m3 = 7850.0;
  double assembly_crank_angle_rad = 0.0;  ///< the state the assembly shows
  std::vector<std::string> notes;         ///< parts left out and why
};

/// A circle as a closed counter-clockwise chain of two half arcs.
std::vector<cad::ArcSegment> CircleChain(const Vec2<double>& centre, double radius);
/// The chain turned by `angle_rad` about the origin (bulges unchanged).
std::vector<cad::ArcSegment> RotatedChain(const std::vector<cad::ArcSegment>& chain, double angle_rad);

/// result.json's "parts": each part's files, count, volume and mass, the assembly and the BOM.
struct PartsBlock {
  struct Entry {
    std::string description;
    int count = 1;
    std::string material;
    double thickness_mm = 0, volume_mm3 = 0, mass_kg = 0;
    std::string dxf, stl;
    std::optional<std::string> step;
    std::optional<double> bore_diameter_mm;
    std::optional<std::vector<PlanarFitSummary::Hole>> holes;
    std::optional<std::string> designation, note;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("description", &description, Field().Desc("what the part is"));
      a->Visit("count", &count, Field().Desc("occurrences in the assembly"));
      a->Visit("material", &material, Field().Desc("the BOM's material"));
      a->Visit("thickness_mm", &thickness_mm, Field().Unit("mm"));
      a->Visit("volume_mm3", &volume_mm3, Field().Unit("mm³").Desc("from the exact profile, minus bore and holes"));
      a->Visit("mass_kg", &mass_kg, Field().Unit("kg").Desc("the volume times the density"));
      a->Visit("dxf", &dxf, Field().Desc("the part's DXF"));
      a->Visit("stl", &stl, Field().Desc("its STL"));
      a->Visit("step", &step, Field().Desc("its STEP (with geometry_files.step)"));
      a->Visit("bore_diameter_mm", &bore_diameter_mm, Field().Unit("mm"));
      a->Visit("holes", &holes, Field());
      a->Visit("designation", &designation, Field().Desc("a catalogue designation (a bearing)"));
      a->Visit("note", &note, Field().Desc("what the drawing simplifies"));
    }
  };
  std::map<std::string, Entry> parts;
  std::string bom = "bom.csv";
  double total_mass_kg = 0, density_kg_m3 = 0;
  std::optional<std::string> assembly;
  std::optional<long> assembly_occurrences;
  std::optional<double> assembly_crank_angle_deg;
  std::optional<std::vector<std::string>> notes;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("parts", &parts, Field().Desc("each part by its file stem"));
    a->Visit("bom", &bom, Field().Desc("the bill of materials"));
    a->Visit("total_mass_kg", &total_mass_kg, Field().Unit("kg").Desc("every part times its count"));
    a->Visit("density_kg_m3", &density_kg_m3, Field().Unit("kg/m³").Desc("the masses' density"));
    a->Visit("assembly", &assembly, Field().Desc("with geometry_files.step: the assembly's STEP"));
    a->Visit("assembly_occurrences", &assembly_occurrences, Field().Desc("the parts placed in it"));
    a->Visit("assembly_crank_angle_deg", &assembly_crank_angle_deg, Field().Unit("°").Desc("the state it shows"));
    a->Visit("notes", &notes, Field().Desc("parts left out and why"));
  }
};
/// The block, or {"written": false} when the geometry files are off.
std::variant<PartsBlock, GeometryFilesOff> PartsOf(const PartsSet& set, const GeometryFileOptions& options);

/// Writes `<part>.dxf`, `<part>.step` (options.step) and `<part>.stl` of every part, `assembly.step`
/// (options.step, with placements) and `bom.csv`.
void WriteParts(const PartsSet& set, const GeometryFileOptions& options, Outputs& out);

/// bom.csv's text (separate for the tests).
std::string BomCsv(const PartsSet& set);

}  // namespace camopt::studies
