#include "studies/lcr_input.h"

#include <algorithm>
#include <cmath>

#include "studies/format.h"

namespace camopt::studies {

namespace {

lcr::CamSide<double> ParseSide(const Node& s, bool allow_crowning, bool allow_ratings) {
  std::set<std::string> known = {"lobes", "rollers", "turret_radius_mm", "roller_diameter_mm", "roller_length_mm",
                                    "cam_thickness_mm", "cutter_diameter_mm", "bore_diameter_mm"};
  if (allow_crowning) known.insert("crowning");  // read by studies/lcr_contact_input.h
  if (allow_ratings) known.insert({"dynamic_rating_N", "static_rating_N"});  // the roller bearing's C, C0
  s.CheckKnownFields(known);
  lcr::CamSide<double> c;
  c.lobes = s["lobes"].Integer(1);
  c.rollers = s["rollers"].Integer(2);
  if (c.rollers <= c.lobes)
    s["rollers"].Fail("more rollers than lobes (" + std::to_string(c.lobes) + ")");
  c.turret_radius = s["turret_radius_mm"].Positive();
  c.roller_radius = s["roller_diameter_mm"].Positive() / 2;
  c.roller_length = PlausibleLength(s["roller_length_mm"], c.turret_radius, "the turret radius");
  c.cam_thickness = PlausibleLength(s["cam_thickness_mm"], c.turret_radius, "the turret radius");
  // Read by some kinds only (geometry files, the cutter offset): a number > 0 wherever given.
  for (const char* optional : {"cutter_diameter_mm", "bore_diameter_mm", "dynamic_rating_N", "static_rating_N"})
    if (s.Has(optional)) s[optional].Positive();
  return c;
}

}  // namespace

lcr::Reducer<double> ParseReducer(const Node& node, bool allow_crowning, bool allow_bearing_ratings) {
  if (allow_bearing_ratings)
    node.CheckKnownFields({"eccentricity_mm", "input", "output", "eccentric_bearing"});
  else
    node.CheckKnownFields({"eccentricity_mm", "input", "output"});
  lcr::Reducer<double> r;
  r.eccentricity = node["eccentricity_mm"].Positive();
  r.input = ParseSide(node["input"], allow_crowning, allow_bearing_ratings);
  r.output = ParseSide(node["output"], allow_crowning, allow_bearing_ratings);
  const auto problems = lcr::CheckDesign(r);
  if (!problems.empty()) {
    // "input.rollers" -> /reducer/input/rollers
    std::string path = problems.front().field;
    for (char& ch : path)
      if (ch == '.') ch = '/';
    throw StudyError(node.file() + ": " + node.path() + "/" + path + ": " + problems.front().message);
  }
  return r;
}

double ParseCutterDiameter(const Node& side, double roller_diameter) {
  if (!side.Has("cutter_diameter_mm")) return roller_diameter;
  const Node n = side["cutter_diameter_mm"];
  const double d = n.Positive();
  if (d > roller_diameter)
    n.Fail("a cutter diameter <= the roller diameter (" + std::to_string(roller_diameter) + " mm)");
  return d;
}

EccentricBearingRating ParseEccentricBearing(const Node& eb) {
  eb.CheckKnownFields({"dynamic_rating_N", "static_rating_N", "kind"});
  EccentricBearingRating b;
  const std::string kind = eb["kind"].String();
  if (kind != "ball" && kind != "roller") eb["kind"].Fail("one of ball, roller");
  b.ball = kind == "ball";
  b.dynamic_N = eb["dynamic_rating_N"].Positive();
  b.static_N = eb.PositiveOr("static_rating_N", 0.0);
  return b;
}

}  // namespace camopt::studies
