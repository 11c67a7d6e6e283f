#include "studies/measured_profile.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <numeric>
#include <sstream>
#include <utility>

#include "studies/format.h"

namespace camopt::studies {

namespace {

// 15 significant digits: a point within 1e-13 of its size of the exact value (well below 0.1 µm on
// any part up to 100 m), a normal unit to 1e-14; printf's %.15g is exact and portable.
std::string Num(double v) {
  char b[40];
  std::snprintf(b, sizeof b, "%.15g", v == 0.0 ? 0.0 : v);  // no "-0"
  return b;
}

std::vector<std::string> SplitCsv(const std::string& line) {
  std::vector<std::string> cells;
  std::string cell;
  std::istringstream in(line);
  while (std::getline(in, cell, ',')) {
    const size_t a = cell.find_first_not_of(" \t\r"), b = cell.find_last_not_of(" \t\r");
    cells.push_back(a == std::string::npos ? "" : cell.substr(a, b - a + 1));
  }
  if (!line.empty() && line.back() == ',') cells.push_back("");
  return cells;
}

}  // namespace

std::string InspectionCsv(const std::string& design, const InspectedPart& part, double spacing_mm,
                          double tolerance_um, long* points) {
  const std::vector<profile::InspectionPoint> pts = profile::InspectionPoints(part.profile, spacing_mm);
  const double half = 0.5 * tolerance_um * 1e-3;
  const double step = part.profile.length_mm() / double(pts.size());
  std::string s;
  s += "# camopt inspection points: " + design + ", part " + part.name + "\n";
  s += "# frame: " + part.frame + "\n";
  s += "# datum: " + part.datum + "\n";
  s += "# units: mm; normals (nx, ny) unit, outward (out of the material)\n";
  s += "# points on the theoretically exact profile (the model's, not the DXF's arcs), " +
       std::to_string(pts.size()) + " at equal arc-length steps of " + Num(step) + " mm (<= " + Num(spacing_mm) +
       " mm) over its length " + Num(part.profile.length_mm()) + " mm, counter-clockwise\n";
  s += "# ISO 1101 profile of a line, tolerance " + Num(tolerance_um) +
       " um: the zone between the two lines enveloping circles of diameter " + Num(tolerance_um) +
       " um centred on the exact profile, i.e. +-" + Num(0.5 * tolerance_um) +
       " um along the normal (upper_mm, lower_mm: the zone's bounds as normal deviations)\n";
  s += "x_mm,y_mm,nx,ny,nominal_mm,upper_mm,lower_mm\n";
  // Counter-clockwise about the part: reversed when the profile's parameter runs clockwise.
  std::vector<size_t> order(pts.size());
  std::iota(order.begin(), order.end(), size_t{0});
  const profile::CurvePoint c0 = part.profile.Eval(part.profile.t0());
  if (Cross(c0.tangent, part.profile.OutwardNormal(c0)) > 0) std::reverse(order.begin() + 1, order.end());
  for (size_t i : order) {
    const auto& p = pts[i];
    s += Num(p.point.x()) + "," + Num(p.point.y()) + "," + Num(p.normal.x()) + "," + Num(p.normal.y()) + ",0," +
         Num(half) + "," + Num(-half) + "\n";
  }
  *points = long(pts.size());
  return s;
}

MeasuredProfile ReadMeasuredProfile(const Node& node, const InspectedPart& part, double max_gap_mm) {
  MeasuredProfile m;
  const Node file_node = node["file"];
  m.part = node["part"].String();
  m.kind = node["kind"].String();
  std::filesystem::path p(file_node.String());
  if (p.is_relative()) p = std::filesystem::path(node.file()).parent_path() / p;
  m.file = p.string();
  const std::string path = file_node.path();
  // "STUDY: /measured_profile/file: CSV line N: expected E, found F".
  auto fail = [&](long line, const std::string& expected, const std::string& found) {
    const std::string where = m.file + (line > 0 ? " line " + std::to_string(line) : "");
    throw StudyError(node.file() + ": " + path + ": " + where + ": expected " + expected + ", found " + found,
                     node.file(), path, expected, found);
  };
  std::string text;
  try {
    CheckFileInside(m.file);
    text = ReadFileCapped(m.file, CurrentInputLimits().max_file_bytes, "measured profile");
  } catch (const StudyError& e) {
    std::string why = e.what();
    if (why.rfind(m.file + ": ", 0) == 0) why = why.substr(m.file.size() + 2);
    fail(0, "a readable CSV file of the measured " + part.name, why);
  }
  const bool deviations = m.kind == "normal_deviation";
  const std::vector<std::string> required =
      deviations ? std::vector<std::string>{"x_mm", "y_mm", "deviation_mm"} : std::vector<std::string>{"x_mm", "y_mm"};
  std::map<std::string, int> column;
  std::istringstream in(text);
  std::string line;
  long line_no = 0;
  bool header = false;
  size_t width = 0;
  const double far_mm = std::min(1.0, 0.1 * part.profile.size_mm());
  // A nominal point (normal_deviation) lies on the exact profile within this (a report rounded to
  // 1 µm, or the inspection file's 15 digits).
  const double on_profile_mm = 0.005;
  struct Row {
    Vec2<double> q;
    double t, d, s;
  };
  std::vector<Row> rows;
  while (std::getline(in, line)) {
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const size_t first = line.find_first_not_of(" \t");
    if (first == std::string::npos || line[first] == '#') continue;
    const std::vector<std::string> cells = SplitCsv(line);
    if (!header) {
      for (size_t i = 0; i < cells.size(); ++i) column[cells[i]] = int(i);
      for (const auto& name : required)
        if (!column.count(name))
          fail(line_no, "a header line with the columns " + std::string(deviations ? "x_mm,y_mm,deviation_mm (nx,ny "
                                                                                     "optional)" : "x_mm,y_mm"),
               "\"" + line.substr(0, 200) + "\" without " + name);
      header = true;
      width = cells.size();
      continue;
    }
    if (cells.size() != width)
      fail(line_no, std::to_string(width) + " comma-separated values (as the header)", std::to_string(cells.size()));
    auto number = [&](const std::string& name) {
      const std::string& c = cells[size_t(column.at(name))];
      char* end = nullptr;
      const double v = std::strtod(c.c_str(), &end);
      if (c.empty() || end != c.c_str() + c.size() || !std::isfinite(v))
        fail(line_no, "a finite number in column " + name, "\"" + c.substr(0, 40) + "\"");
      return v;
    };
    Row r;
    r.q = Vec2<double>(number("x_mm"), number("y_mm"));
    const profile::ClosedProfile::Projection pr = part.profile.Project(r.q);
    r.t = pr.t;
    if (deviations) {
      if (pr.distance_mm > on_profile_mm)
        fail(line_no, "a nominal point on the exact profile of " + part.name + " (within " + Format(on_profile_mm * 1e3, 3) +
                          " um)",
             Format(pr.distance_mm, 4) + " mm from it");
      if (column.count("nx") && column.count("ny")) {
        const Vec2<double> n(number("nx"), number("ny"));
        if (!(std::abs(n.norm() - 1.0) <= 1e-3 && n.dot(pr.normal) >= 0.99))
          fail(line_no, "the outward unit normal of the profile there (" + Format(pr.normal.x(), 6) + ", " +
                            Format(pr.normal.y(), 6) + ") within 8 deg",
               "(" + Format(n.x(), 6) + ", " + Format(n.y(), 6) + ")");
      }
      r.d = number("deviation_mm");
      if (!(std::abs(r.d) <= far_mm))
        fail(line_no, "a deviation within " + Format(far_mm, 4) + " mm (1 mm or 10% of the part's size)",
             Format(r.d, 6) + " mm");
      m.points.push_back(pr.foot);
    } else {
      r.d = pr.deviation_mm;
      if (!(pr.distance_mm <= far_mm))
        fail(line_no, "a point within " + Format(far_mm, 4) + " mm of the exact profile of " + part.name +
                          " (1 mm or 10% of the part's size; in its part frame: " + part.frame + ")",
             "(" + Format(r.q.x(), 8) + ", " + Format(r.q.y(), 8) + ") " + Format(pr.distance_mm, 4) + " mm from it");
      m.points.push_back(r.q);
    }
    r.s = part.profile.ArcLength(r.t);
    rows.push_back(r);
    m.t.push_back(r.t);
    m.deviation_mm.push_back(r.d);
    m.arc_mm.push_back(r.s);
  }
  if (!header) fail(0, "a header line and measured points", "no header line");
  // The spline's knots: the points in the order of the profile, equal parameters merged (mean).
  std::vector<size_t> order(rows.size());
  std::iota(order.begin(), order.end(), size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return rows[a].t < rows[b].t; });
  std::vector<double> kt, kd, ks;
  std::vector<int> count;
  const double same = 1e-12 * part.profile.period();
  for (size_t i : order) {
    if (!kt.empty() && rows[i].t - kt.back() <= same) {
      kd.back() += rows[i].d;
      ++count.back();
      continue;
    }
    kt.push_back(rows[i].t);
    kd.push_back(rows[i].d);
    ks.push_back(rows[i].s);
    count.push_back(1);
  }
  for (size_t i = 0; i < kd.size(); ++i) kd[i] /= count[i];
  constexpr size_t kMinPoints = 8;
  if (kt.size() < kMinPoints)
    fail(0, "at least " + std::to_string(kMinPoints) + " distinct points around the profile of " + part.name,
         std::to_string(kt.size()));
  const double length = part.profile.length_mm();
  double gap = 0, gap_at = 0;
  for (size_t i = 0; i < ks.size(); ++i) {
    const double g = (i + 1 < ks.size() ? ks[i + 1] : ks[0] + length) - ks[i];
    if (g > gap) gap = g, gap_at = ks[i];
  }
  m.largest_gap_mm = gap;
  if (gap > max_gap_mm)
    fail(0, "points covering the whole profile of " + part.name + " (no arc between neighbours above " +
                Format(max_gap_mm, 4) + " mm of its " + Format(length, 6) + " mm)",
         "an arc of " + Format(gap, 4) + " mm without a point from " + Format(gap_at, 6) + " mm along it");
  m.zone = profile::MeasureZone(m.deviation_mm);
  m.shape = profile::PeriodicSpline(kt, kd, part.profile.period());
  return m;
}

MeasuredBlock MeasuredOf(const MeasuredProfile& m, const InspectedPart& part) {
  auto where = [&](int i) {
    return DeviationAt{m.points[size_t(i)].x(), m.points[size_t(i)].y(), m.arc_mm[size_t(i)], long(i) + 1};
  };
  MeasuredBlock b;
  b.part = m.part;
  b.file = std::filesystem::path(m.file).filename().string();
  b.kind = m.kind;
  b.frame = part.frame;
  b.points = long(m.deviation_mm.size());
  b.profile_length_mm = part.profile.length_mm();
  b.largest_gap_mm = m.largest_gap_mm;
  b.iso1101_profile_deviation_um = m.zone.zone_width_mm * 1e3;
  b.iso1101_note =
      "ISO 1101 profile of a line: the width of the smallest zone symmetric about the exact profile (datum: " +
      part.datum + ") that holds every point, 2 max|d|";
  b.max_deviation_um = m.zone.max_mm * 1e3;
  b.max_deviation_at = where(m.zone.argmax);
  b.min_deviation_um = m.zone.min_mm * 1e3;
  b.min_deviation_at = where(m.zone.argmin);
  b.mean_deviation_um = m.zone.mean_mm * 1e3;
  b.rms_deviation_um = m.zone.rms_mm * 1e3;
  b.deviation_sign = "> 0: material added (outside the exact profile)";
  b.interpolation =
      "periodic cubic spline of the normal deviation over the profile parameter through the points (equal "
      "parameters averaged)";
  return b;
}

InspectionBlock InspectionOf(double spacing_mm, double tolerance_um,
                             const std::vector<std::pair<std::string, long>>& files, bool written,
                             const std::string& datum) {
  InspectionBlock j;
  j.spacing_mm = spacing_mm, j.tolerance_um = tolerance_um;
  if (!written) {
    j.written = false;
    j.why = "geometry_files is false: no geometry files, no inspection points";
    return j;
  }
  std::map<std::string, InspectionBlock::File>& parts = j.parts.emplace();
  for (const auto& [name, n] : files) parts[name] = {"inspection/" + name + ".csv", n};
  j.datum = datum;
  return j;
}

}  // namespace camopt::studies
