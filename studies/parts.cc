#include "studies/parts.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "cad/dxf.h"
#include "cad/solid.h"
#include "studies/format.h"
#include "studies/provenance.h"

namespace camopt::studies {

std::vector<cad::ArcSegment> CircleChain(const Vec2<double>& centre, double radius) {
  const Vec2<double> a = centre + Vec2<double>(radius, 0.0), b = centre - Vec2<double>(radius, 0.0);
  return {{a, b, 1.0}, {b, a, 1.0}};
}

std::vector<cad::ArcSegment> RotatedChain(const std::vector<cad::ArcSegment>& chain, double angle_rad) {
  const double c = std::cos(angle_rad), s = std::sin(angle_rad);
  auto turn = [&](const Vec2<double>& p) { return Vec2<double>(c * p.x() - s * p.y(), s * p.x() + c * p.y()); };
  std::vector<cad::ArcSegment> out;
  out.reserve(chain.size());
  for (const cad::ArcSegment& a : chain) out.push_back({turn(a.start), turn(a.end), a.bulge});
  return out;
}

namespace {

std::string DxfOf(const PartsSet& set, const Part& p) {
  const cad::Extrusion& e = p.solid;
  cad::DxfDocument dxf;
  dxf.AddLayer("PROFILE", 7);
  dxf.AddChain("PROFILE", e.profile, true);
  if (!p.cutter_path.empty()) {
    dxf.AddLayer("CUTTER_PATH", 1);
    dxf.AddChain("CUTTER_PATH", p.cutter_path, true);
  }
  if (e.bore_diameter_mm > 0) {
    dxf.AddLayer("BORE", 7);
    dxf.AddCircle("BORE", e.bore_centre, 0.5 * e.bore_diameter_mm);
  }
  if (!e.holes.empty()) {
    dxf.AddLayer("HOLES", 7);
    for (const cad::Hole& h : e.holes) dxf.AddCircle("HOLES", h.centre, 0.5 * h.diameter_mm);
  }
  dxf.AddLayer("CENTRE_MARKS", 3);
  double size = 0.0, xmin = e.bore_centre.x(), ymin = e.bore_centre.y();
  for (const cad::ArcSegment& a : e.profile) {
    size = std::max(size, (a.start - e.bore_centre).norm());
    xmin = std::min(xmin, a.start.x());
    ymin = std::min(ymin, a.start.y());
  }
  const double mark = std::max(0.5, 0.08 * size);
  dxf.AddCentreMark("CENTRE_MARKS", e.bore_centre, mark);
  for (const cad::Hole& h : e.holes) dxf.AddCentreMark("CENTRE_MARKS", h.centre, std::min(mark, 0.75 * h.diameter_mm));
  dxf.AddLayer("TEXT", 7);
  const double h = std::max(0.5, 0.04 * size);
  std::vector<std::string> lines = {set.design_name + ": " + p.name + " (" + p.description + ")",
                                    "units: mm (INSUNITS 4); thickness " + Format(e.thickness_mm, 6) + " mm; " +
                                        std::to_string(p.count) + " off; " + p.material};
  if (!p.cutter_path.empty())
    lines.push_back("cutter path: centre of a cutter of diameter " + Format(p.cutter_diameter_mm, 6) + " mm");
  if (!p.note.empty()) lines.push_back(p.note);
  lines.push_back("camopt " + CamoptVersion());
  for (size_t i = 0; i < lines.size(); ++i)
    dxf.AddText("TEXT", Vec2<double>(xmin, ymin - (2.0 + 1.6 * (i + 1)) * h), h, lines[i]);
  return dxf.ToString();
}

// A CSV field: quoted when it holds a comma, a quote or a line break (RFC 4180).
std::string CsvField(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

// A number of the bill of materials: ten significant digits.
std::string TenDigits(double v) { return Format(v, 10); }

}  // namespace

std::string BomCsv(const PartsSet& set) {
  std::string out = "part,count,description,material,thickness_mm,volume_mm3,mass_kg,total_mass_kg,designation,note\n";
  double total = 0.0;
  for (const Part& p : set.parts) {
    total += p.count * p.mass_kg;
    out += CsvField(p.name) + "," + std::to_string(p.count) + "," + CsvField(p.description) + "," +
           CsvField(p.material) + "," + TenDigits(p.solid.thickness_mm) + "," + TenDigits(p.volume_mm3) + "," +
           TenDigits(p.mass_kg) + "," + TenDigits(p.count * p.mass_kg) + "," + CsvField(p.designation) + "," +
           CsvField(p.note) + "\n";
  }
  out += "total,,,,,,," + TenDigits(total) + ",,density " + TenDigits(set.density_kg_m3) + " kg/m^3\n";
  return out;
}

std::variant<PartsBlock, GeometryFilesOff> PartsOf(const PartsSet& set, const GeometryFileOptions& options) {
  if (!options.write) return GeometryFilesOff{};
  PartsBlock out;
  double total = 0.0;
  for (const Part& p : set.parts) {
    PartsBlock::Entry j;
    j.description = p.description, j.count = p.count, j.material = p.material;
    j.thickness_mm = p.solid.thickness_mm, j.volume_mm3 = p.volume_mm3, j.mass_kg = p.mass_kg;
    j.dxf = p.name + ".dxf", j.stl = p.name + ".stl";
    if (options.step) j.step = p.name + ".step";
    if (p.solid.bore_diameter_mm > 0) j.bore_diameter_mm = p.solid.bore_diameter_mm;
    if (!p.solid.holes.empty()) {
      std::vector<PlanarFitSummary::Hole>& holes = j.holes.emplace();
      for (const cad::Hole& h : p.solid.holes) holes.push_back({h.centre.x(), h.centre.y(), h.diameter_mm});
    }
    if (!p.designation.empty()) j.designation = p.designation;
    if (!p.note.empty()) j.note = p.note;
    total += p.count * p.mass_kg;
    out.parts[p.name] = std::move(j);
  }
  out.total_mass_kg = total;
  out.density_kg_m3 = set.density_kg_m3;
  if (options.step && !set.placements.empty()) {
    out.assembly = "assembly.step";
    out.assembly_occurrences = long(set.placements.size());
    out.assembly_crank_angle_deg = set.assembly_crank_angle_rad * 180.0 / 3.14159265358979323846;
  }
  if (!set.notes.empty()) out.notes = set.notes;
  return out;
}

void WriteParts(const PartsSet& set, const GeometryFileOptions& options, Outputs& out) {
  if (!options.write) return;
  std::vector<cad::Extrusion> solids;
  for (const Part& p : set.parts) {
    out.Add(p.name + ".dxf", DxfOf(set, p));
    cad::Extrusion e = p.solid;
    e.name = p.name;
    e.step = options.step;
    cad::SolidOutput solid = cad::ExtrudeCam(e);
    if (options.step) out.Add(p.name + ".step", std::move(solid.step));
    out.Add(p.name + ".stl", StlFile(solid.mesh, set.design_name + " " + p.name, options));
    solids.push_back(std::move(e));
  }
  if (options.step && !set.placements.empty())
    out.Add("assembly.step", cad::StepAssembly(set.design_name, solids, set.placements));
  out.Add("bom.csv", BomCsv(set));
}

}  // namespace camopt::studies
