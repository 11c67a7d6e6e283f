// Study kind "cycloid_min_size" (studies/cycloid_min_size_study.h): parse, check the ranges against
// the closed-form limits, size through sizing/cycloid_min_size.h, write.
#include "studies/cycloid_min_size_study.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "model/cycloid/geometry_limits.h"
#include "model/cycloid/tooth_profile.h"
#include "optimizers/solver.h"
#include "studies/cycloid_life.h"
#include "studies/cycloid_ltca_study.h"
#include "studies/cycloid_study_common.h"
#include "studies/format.h"
#include "studies/kind.h"
#include "studies/ratings.h"
#include "studies/report.h"
#include "studies/verification_json.h"
#include "studies/work_limits.h"
#include "studies/writers.h"
#include "studies/archive.h"

namespace camopt::studies::cycloid_min_size {

using sizing::CycloidSizingLimits;

namespace {

// ---------------------------------------------------------------------------------------------
// Parsing.

// The section of the file that holds a sized field when it is not a variable.
const char* SectionOf(const std::string& name) {
  if (name == "eccentricity_mm" || name == "roller_position_radius_mm" || name == "roller_radius_mm" ||
      name == "face_width_mm")
    return "drive";
  if (name == "delta_position_um" || name == "delta_radius_um") return "modification";
  return "crowning";
}

bool IsDriveField(const std::string& name) { return std::string(SectionOf(name)) == "drive"; }

// One sized field as the file gives it: a range (lo < hi, a variable) or a value (lo = hi), in the
// field's own unit (µm for the modifications), with the nodes its bounds came from (messages).
struct Field {
  std::string name;
  bool given = false;     ///< in the file (variables or its section); else its default
  bool variable = false;  ///< a range with lo < hi
  double lo = 0, hi = 0, start = 0;
  std::optional<Node> node, lo_node, hi_node;  ///< the entry and the nodes of its bounds
};

// "[lo, hi]": two numbers, lo <= hi. An empty range (lo > hi) is refused with the range that fits.
std::pair<double, double> RangeOf(const Node& n) {
  const nlohmann::json& j = n.json();
  if (!j.is_array() || j.size() != 2 || !j[0].is_number() || !j[1].is_number()) n.Fail("[lower, upper], two numbers");
  const double lo = n[0].Number(), hi = n[1].Number();
  if (lo > hi)
    n.FailWith("expected [lower, upper] with lower <= upper, found " + Describe(j) + " (an empty range); [" +
               Format(hi) + ", " + Format(lo) + "] would fit");
  return {lo, hi};
}

// An entry of "variables": a number (fixed), [lo, hi] (start at the middle) or
// {"range": [lo, hi], "start": value}. lo = hi is a fixed value.
Field ParseVariable(const Node& n, const std::string& name) {
  Field f;
  f.name = name;
  f.given = true;
  f.node = n;
  const nlohmann::json& j = n.json();
  if (j.is_number()) {
    f.lo = f.hi = f.start = n.Number();
    f.lo_node = f.hi_node = n;
  } else if (j.is_array()) {
    std::tie(f.lo, f.hi) = RangeOf(n);
    f.start = 0.5 * (f.lo + f.hi);
    f.lo_node = n[0];
    f.hi_node = n[1];
  } else if (j.is_object()) {
    n.CheckKnownFields({"range", "start"});
    const Node r = n["range"];
    std::tie(f.lo, f.hi) = RangeOf(r);
    f.lo_node = r[0];
    f.hi_node = r[1];
    f.start = 0.5 * (f.lo + f.hi);
    if (n.Has("start")) {
      f.start = n["start"].Number();
      if (f.start < f.lo || f.start > f.hi)
        n["start"].Fail("a start within the range [" + Format(f.lo) + ", " + Format(f.hi) + "]");
    }
  } else {
    n.Fail("a number (a fixed value), [lo, hi] (a range, starting at its middle) or "
           "{\"range\": [lo, hi], \"start\": value}");
  }
  f.variable = f.hi > f.lo;
  if (!f.variable) f.start = f.lo;
  return f;
}

// A field given in its section ("drive", "modification", "crowning"): a fixed value.
Field SectionField(const Node& n, const std::string& name, double value) {
  Field f;
  f.name = name;
  f.given = true;
  f.node = f.lo_node = f.hi_node = n;
  f.lo = f.hi = f.start = value;
  return f;
}

// The bounds each field's own kind requires (what the schema states per field): lengths of the
// drive > 0, modification ranges <= 0, crowning parameters >= 0 (an end drop range > 0, a radius > 0).
void CheckFieldBounds(const Field& f) {
  if (!f.given) return;
  const Node& lo = *f.lo_node;
  const Node& hi = *f.hi_node;
  if (IsDriveField(f.name) && !(f.lo > 0)) lo.Fail("a number > 0");
  if (f.name == "delta_position_um" || f.name == "delta_radius_um") {
    if (f.variable && f.hi > 0) hi.Fail("an upper bound <= 0 (a positive modification interferes)");
    return;
  }
  if (std::string(SectionOf(f.name)) != "crowning") return;
  if (f.name == "radius_mm") {
    if (!(f.lo > 0)) lo.Fail("a number > 0");
  } else if (f.name == "end_drop_mm" && f.variable) {
    if (!(f.lo > 0)) lo.Fail("a lower bound > 0 (0 means an unbounded drop)");
  } else if (!(f.lo >= 0)) {
    lo.Fail("a number >= 0");
  }
}

void SetDriveField(cycloid::Drive& d, const std::string& name, double v) {
  if (name == "eccentricity_mm") d.eccentricity_mm = v;
  if (name == "roller_position_radius_mm") d.roller_position_radius_mm = v;
  if (name == "roller_radius_mm") d.roller_radius_mm = v;
  if (name == "face_width_mm") d.face_width_mm = v;
  if (name == "delta_position_um") d.delta_position_mm = v * 1e-3;
  if (name == "delta_radius_um") d.delta_radius_mm = v * 1e-3;
}

void SetCrowningField(cycloid::Crowning& c, const std::string& name, double v) {
  if (name == "coefficient_mm") c.coefficient_mm = v;
  if (name == "effective_length_mm") c.effective_length_mm = v;
  if (name == "end_drop_mm") c.end_drop_mm = v;
  if (name == "flat_length_mm") c.flat_length_mm = v;
  if (name == "radius_mm") c.radius_mm = v;
}

double CrowningFieldOf(const cycloid::Crowning& c, const std::string& name) {
  if (name == "coefficient_mm") return c.coefficient_mm;
  if (name == "effective_length_mm") return c.effective_length_mm;
  if (name == "end_drop_mm") return c.end_drop_mm;
  if (name == "flat_length_mm") return c.flat_length_mm;
  return c.radius_mm;
}

void ParseTarget(const Node& root, const Input::Target& in, Study& s) {
  const Node t = root["target"];
  const bool teeth = bool(in.teeth), ratio = bool(in.speed_ratio);
  if (teeth == ratio)
    t.FailWith(teeth ? "give one of \"teeth\" and \"speed_ratio\", not both (for this drive they are the same number z)"
                     : "missing required field: \"teeth\" (z, the disc's teeth) or \"speed_ratio\" (z)");
  int z = 0;
  if (teeth) {
    z = *in.teeth;
  } else {
    // A one-tooth-difference drive with the ring (z + 1 pins) fixed and the output taken from the
    // disc turns the output 1/z of the input, in the opposite sense: the reduction is z.
    const Node r = t["speed_ratio"];
    const double v = *in.speed_ratio;
    if (v != std::round(v) || v < 2 || v > 1e9) {
      const double fit = std::clamp(std::round(std::abs(v)), 2.0, 1e9);
      r.FailWith("expected a whole-number reduction z >= 2 (ring of z + 1 pins fixed, output from the disc: the "
                 "output turns 1/z of the input, in the opposite sense), found " + Describe(r.json()) + "; " +
                 Format(fit, 10) + " would fit");
    }
    z = int(v);
    s.ratio_given = true;
  }
  s.spec.drive.teeth = z;
  s.spec.drive.rollers = z + 1;
  s.design_torque_Nm = in.design_torque_Nm;
  s.spec.design_torque_Nmm = s.design_torque_Nm * 1000.0;
  if (in.overload_torque_Nm) {
    s.overload_torque_Nm = *in.overload_torque_Nm;
    if (s.overload_torque_Nm < s.design_torque_Nm)
      t["overload_torque_Nm"].Fail("a torque >= design_torque_Nm (" + Format(s.design_torque_Nm) + " N·m)");
    s.spec.overload_torque_Nmm = s.overload_torque_Nm * 1000.0;
  }
}

void ParseLimits(const Node& root, const Input::Limits& in, Study& s) {
  const Node l = root["limits"];
  CycloidSizingLimits& lim = s.spec.limits;
  lim.life_h = in.life_h.value_or(0.0);  // needs the speed: checked in ParseLife
  lim.contact_stress_MPa = in.contact_stress_MPa;
  if (in.min_edge_margin_um) {
    if (s.overload_torque_Nm == 0)
      l["min_edge_margin_um"].FailWith("needs target.overload_torque_Nm: the edge margin is checked on the overload "
                                       "cycle (give the torque at which the contact must stay off the face ends)");
    lim.min_edge_margin_um = *in.min_edge_margin_um;
  }
  if (in.min_curtate_margin) lim.min_curtate_margin = *in.min_curtate_margin;
  lim.min_profile_radius_mm = in.min_profile_radius_mm;
  lim.min_pin_gap_mm = in.min_pin_gap_mm;
  lim.min_backlash_arcsec = in.min_backlash_arcsec;
  lim.max_backlash_arcsec = in.max_backlash_arcsec.value_or(kInf);
  if (!(lim.max_backlash_arcsec > lim.min_backlash_arcsec))
    l["max_backlash_arcsec"].Fail("a backlash > min_backlash_arcsec (" + Format(lim.min_backlash_arcsec) + " arcsec)");
  lim.max_lte_peak_to_peak_arcsec = in.max_lte_peak_to_peak_arcsec.value_or(kInf);
  if (in.bore_diameter_mm) {
    s.bore_diameter_mm = *in.bore_diameter_mm;
    lim.bore_radius_mm = 0.5 * s.bore_diameter_mm;
  }
  if (in.min_web_mm) {
    if (!in.bore_diameter_mm)
      l["min_web_mm"].FailWith("needs bore_diameter_mm: the web is the ring between the bore and the tooth roots");
    lim.min_web_mm = *in.min_web_mm;
  }
}

void ParseAnalysis(const Input::Analysis& in, Study& s) {
  if (in.grid) s.spec.options.profile_cells = (*in.grid)[0], s.spec.options.axial_cells = (*in.grid)[1];
  s.spec.angles_per_period = in.crank_angles_per_mesh_period;
  s.spec.options.tolerance = in.tolerance;
}

void ParseOptimizer(const Input::Optimizer& in, Study& s) {
  optimizers::SolverOptions& so = s.options.solver;
  s.backend = optimizers::ToString(ToBackend(in.backend));
  s.options.starts = in.starts;
  so.max_evaluations = in.max_evaluations;
  s.options.verify_rounds = in.verify_rounds;
  so.backend = ToBackend(s.backend);
  // The evaluation budget bounds the run, never the clock: the same study gives the same design.
  so.max_seconds = 1e9;
  // The contact model is discretised: its peaks move by a fraction of a MPa between neighbouring
  // designs (cells entering the contact), so Ipopt's multipliers jump at the kinks and its
  // optimality test may never pass although the design no longer moves: it also stops once 3
  // iterations in a row meet the rows within 1 (MPa, µm, arcsec) and change the size by less than
  // 1e-4 (relative: 4 µm on a 40 mm ring), a tenth of the 0.1% by which the verification aims at
  // the accurate limit; at 1e-6 Ipopt circles a kink for a hundred iterations after the size has
  // settled (docs/optimization.md; the settings of tests/cycloid_min_size_test.cc).
  so.tolerance = 1e-6;
  so.constraint_tolerance = 1e-3;
  so.stall_iterations = 3;
  so.stall_violation = 1.0;
  so.stall_change = 1e-4;
}

// The sizing fields: "variables" and the sections. Fills s.spec.drive, s.spec.crowning and
// s.spec.variables; returns every field by name (for the checks that follow).
std::map<std::string, Field> ParseDesign(const Node& root, const Input& in, Study& s) {
  const std::vector<std::string> names = sizing::CycloidSizingVariableNames();
  const Node v = root["variables"];
  if (v.json().empty()) v.Fail("an object of sized fields {\"field\": [lo, hi] or a number, ...}");
  std::set<std::string> in_variables;
  for (const auto& [key, _] : v.json().items()) in_variables.insert(key);

  // The sections: "drive" and "modification" hold fixed fields; "crowning" its type and fixed fields.
  s.spec.crowning = cycloid_common::MakeCrowningStart(root, in.crowning, in_variables);
  const cycloid::Crowning section_crowning = s.spec.crowning;

  std::map<std::string, Field> fields;
  for (const std::string& name : names) {
    const std::string section = SectionOf(name);
    const bool in_section = root.Has(section) && root[section].Has(name);
    Field f;
    f.name = name;
    if (in_variables.count(name)) {
      if (in_section)
        root[section][name].FailWith("given twice: also in /variables/" + name +
                                     "; give it once (a range or a number in \"variables\", or a number here)");
      if (const std::string why = sizing::CycloidSizingVariableAllowed(name, s.spec.crowning.type); !why.empty())
        v[name].FailWith("not with the crowning type \"" +
                         std::string(cycloid_common::CrowningTypeName(s.spec.crowning.type)) + "\": " + why +
                         " (choose the crowning with \"crowning\": {\"type\": ...})");
      f = ParseVariable(v[name], name);
    } else if (in_section) {
      const Node n = root[section][name];
      const double value = section == "drive"          ? n.Positive()
                           : section == "modification" ? n.Number()
                                                       : CrowningFieldOf(section_crowning, name);
      f = SectionField(n, name, value);
    } else if (section == "drive") {
      v.FailWith("missing " + name + ": give it in \"variables\" (a range [lo, hi] or a number) or in \"drive\"");
    } else {
      // Not given: a modification is 0; a crowning field keeps ParseCrowningStart's default.
      f.lo = f.hi = f.start = section == "crowning" ? CrowningFieldOf(section_crowning, name) : 0.0;
    }
    CheckFieldBounds(f);
    if (section == "crowning")
      SetCrowningField(s.spec.crowning, name, f.start);
    else
      SetDriveField(s.spec.drive, name, f.start);
    if (f.variable) {
      objectives::Variable var;
      var.name = name;
      var.lower = f.lo;
      var.upper = f.hi;
      var.initial = f.start;
      var.scale = f.hi - f.lo;
      s.spec.variables.push_back(var);
    }
    fields[name] = f;
  }
  if (s.spec.variables.empty())
    v.FailWith("nothing to size: every field is fixed; give at least one as a range [lo, hi] with lo < hi");
  return fields;
}

// Every design in the box must be a plausible drive (cycloid_common::CheckPlausible for the whole
// box): a shortening coefficient e N / a' >= kMinShortening at its smallest, pins of at least
// kMinPinToHalfPitch of the half pitch, modifications below the pin radius, a face width on the pin
// circle's scale. Outside these the input is a unit or typing mistake.
void CheckPlausibleBox(const std::map<std::string, Field>& f, int n) {
  const Field &e = f.at("eccentricity_mm"), &a = f.at("roller_position_radius_mm"), &rho = f.at("roller_radius_mm"),
              &b = f.at("face_width_mm"), &da = f.at("delta_position_um"), &dr = f.at("delta_radius_um");
  for (const Field* m : {&da, &dr})
    if (m->given && std::max(std::abs(m->lo), std::abs(m->hi)) * 1e-3 >= rho.lo)
      m->node->FailWith("a profile modification of " + Format(std::max(std::abs(m->lo), std::abs(m->hi)), 6) +
                        " um is not below the smallest pin radius " + Format(rho.lo * 1e3, 6) +
                        " um: modifications are corrections of micrometres (the field is in um)");
  const double a_hi = a.hi + da.hi * 1e-3;
  const double k1 = e.lo * n / a_hi;
  if (k1 < cycloid_common::kMinShortening)
    e.lo_node->FailWith("the smallest shortening coefficient e * rollers / a' = " + Format(k1, 4) + " (e = " +
                        Format(e.lo) + " mm, a' = " + Format(a_hi) + " mm) is below " +
                        Format(cycloid_common::kMinShortening, 3) +
                        " (real drives: 0.5-0.9): the teeth vanish; an eccentricity of at least " +
                        Format(cycloid_common::kMinShortening * a_hi / n, 4) + " mm would fit");
  const double half_pitch = a.hi * std::sin(kPi / n);
  if (rho.lo < cycloid_common::kMinPinToHalfPitch * half_pitch)
    rho.lo_node->FailWith("the pin radius " + Format(rho.lo, 4) + " mm is below " +
                          Format(100 * cycloid_common::kMinPinToHalfPitch, 3) + "% of the half pitch " +
                          Format(half_pitch, 4) + " mm at the largest pin circle (real drives: 30-80%): at least " +
                          Format(cycloid_common::kMinPinToHalfPitch * half_pitch, 4) + " mm would fit");
  for (const Node* bound : {&*b.lo_node, &*b.hi_node}) PlausibleLength(*bound, a.hi, "the largest pin circle radius");
}

// The crowning's conditions (cycloid::CheckCrowning) at the most favourable values of the ranges:
// each is linear in the face width and the crowning's fields, so if even its best corner breaks it,
// every design of the box does (bad input, with the bound that would fit); designs of the box that
// break it elsewhere are kept out by the sizing problem's crowning rows. The start design's
// crowning must be valid: the solve begins there.
void CheckCrowningBox(const Node& root, const std::map<std::string, Field>& f, const Study& s) {
  const Field &b = f.at("face_width_mm"), &len = f.at("effective_length_mm"), &flat = f.at("flat_length_mm"),
              &radius = f.at("radius_mm");
  const auto at = [&](const Field& x) { return x.given ? *x.hi_node : root["crowning"]; };
  switch (s.spec.crowning.type) {
    case cycloid::CrowningType::kNone: break;
    case cycloid::CrowningType::kFull:
      if (!(radius.hi > 0.5 * b.lo))
        at(radius).FailWith("every crowning radius of the ranges is at most half the face width (radius " +
                            Format(radius.hi) + " mm, face width " + Format(b.lo) + " mm at the most favourable "
                            "corner); a radius above " + Format(0.5 * b.lo) + " mm would fit");
      break;
    case cycloid::CrowningType::kPartial:
      if (!(flat.lo <= b.hi))
        at(flat).FailWith("every flat length of the ranges exceeds the face width (" + Format(flat.lo) + " > " +
                          Format(b.hi) + " mm); a flat length of at most " + Format(b.hi) + " mm would fit");
      if (!(radius.hi > 0.5 * (b.lo - flat.hi)))
        at(radius).FailWith("every crowning radius of the ranges is at most half the crowned length (radius " +
                            Format(radius.hi) + " mm, crowned length " + Format(b.lo - flat.hi) +
                            " mm at the most favourable corner); a radius above " + Format(0.5 * (b.lo - flat.hi)) +
                            " mm would fit");
      break;
    case cycloid::CrowningType::kLogarithmic:
      if (len.variable && !(len.lo > 0))
        len.lo_node->Fail("a lower bound > 0 (0, L = the face width, is a fixed value only)");
      if ((len.variable || len.hi > 0) && !(len.hi >= b.lo))
        at(len).FailWith("every effective length of the ranges is below the face width (" + Format(len.hi) + " < " +
                         Format(b.lo) + " mm); an effective length of at least " + Format(b.lo) +
                         " mm (or 0: L = the face width) would fit");
      if (!(flat.lo < b.hi))
        at(flat).FailWith("every flat length of the ranges reaches the face width (" + Format(flat.lo) + " >= " +
                          Format(b.hi) + " mm); a flat length below " + Format(b.hi) + " mm would fit");
      break;
  }
  if (const std::string why = cycloid::CheckCrowning(s.spec.crowning, s.spec.drive.face_width_mm); !why.empty())
    (root.Has("crowning") ? root["crowning"] : root["variables"])
        .FailWith("the start design's crowning is invalid (face width " + Format(s.spec.drive.face_width_mm) +
                  " mm): " + why + "; give starts inside the valid region ({\"range\": [lo, hi], \"start\": value})");
}

// The closed-form limits of geometry_limits.h at the most favourable corner of the box: the smallest
// e, the largest a and Δa, the smallest ρ and Δρ. The curtate margin 1 − e N / a' grows with a' and
// falls with e; the smallest convex radius of the generating curve, a'·g(e N / a') with g
// decreasing ((C3), (C4)), grows with a' and falls with e, and the tooth's is that minus ρ'; the
// pin gap 2 a sin(π/N) − 2ρ and the web a' − e − ρ' − r_b grow with a and fall with ρ. If even this
// corner breaks a limit, every design in the box does: bad input, with the bound that would fit.
void CheckClosedFormCorner(const Node& root, const std::map<std::string, Field>& f, const Study& s) {
  const Field &e = f.at("eccentricity_mm"), &a = f.at("roller_position_radius_mm"), &rho = f.at("roller_radius_mm"),
              &da = f.at("delta_position_um"), &dr = f.at("delta_radius_um");
  const CycloidSizingLimits& lim = s.spec.limits;
  cycloid::Drive d = s.spec.drive;
  d.eccentricity_mm = e.lo;
  d.roller_position_radius_mm = a.hi;
  d.roller_radius_mm = rho.lo;
  d.delta_position_mm = da.hi * 1e-3;
  d.delta_radius_mm = dr.lo * 1e-3;
  const int n = d.rollers;
  const double a_mod = a.hi + d.delta_position_mm;  // a'
  const std::string corner = "e = " + Format(e.lo) + " mm, a = " + Format(a.hi) + " mm, rho = " + Format(rho.lo) +
                             " mm" + (da.hi != 0 ? ", delta_a = " + Format(da.hi) + " um" : "") +
                             (dr.lo != 0 ? ", delta_rho = " + Format(dr.lo) + " um" : "");
  const double curtate = cycloid::CurtateMargin(d);
  if (curtate < lim.min_curtate_margin)
    e.lo_node->FailWith(
        "every design in the ranges is too curtate: even the most favourable corner (" + corner +
        ") has 1 - e (z + 1) / a' = " + Format(curtate, 4) + ", below min_curtate_margin " +
        Format(lim.min_curtate_margin, 4) + "; an eccentricity of at most " +
        Format((1 - lim.min_curtate_margin) * a_mod / n, 5) + " mm, or a pin circle radius of at least " +
        Format(e.lo * n / (1 - lim.min_curtate_margin) - d.delta_position_mm, 5) + " mm, would fit");
  const double gap = cycloid::PinGapMargin(d, lim.min_pin_gap_mm);
  if (gap < 0)
    rho.lo_node->FailWith(
        "the pins overlap in every design of the ranges: even the largest pin circle and the smallest pins (a = " +
        Format(a.hi) + " mm, rho = " + Format(rho.lo) + " mm) leave a gap 2 a sin(pi / rollers) - 2 rho = " +
        Format(gap + lim.min_pin_gap_mm, 4) + " mm, below min_pin_gap_mm " + Format(lim.min_pin_gap_mm) +
        "; a pin radius of at most " + Format(0.5 * (2 * a.hi * std::sin(kPi / n) - lim.min_pin_gap_mm), 5) +
        " mm, or a pin circle radius of at least " +
        Format((2 * rho.lo + lim.min_pin_gap_mm) / (2 * std::sin(kPi / n)), 5) + " mm, would fit");
  const double undercut = cycloid::UndercutMargin(d, lim.min_profile_radius_mm);
  if (undercut < 0) {
    // The largest pin radius that fits at this corner; when none does, the largest eccentricity
    // (the margin falls monotonically with e: bisection on the closed form).
    const double rho_fit = cycloid::MinConvexCentreRadius(d) - d.delta_radius_mm - lim.min_profile_radius_mm;
    std::string fit;
    if (rho_fit > 0) {
      fit = "a pin radius of at most " + Format(rho_fit, 5) + " mm would fit";
    } else {
      double lo = 0, hi = e.lo;
      for (int k = 0; k < 100; ++k) {
        cycloid::Drive t = d;
        t.eccentricity_mm = 0.5 * (lo + hi);
        (cycloid::UndercutMargin(t, lim.min_profile_radius_mm) >= 0 ? lo : hi) = t.eccentricity_mm;
      }
      fit = lo > 0 ? "an eccentricity of at most " + Format(lo, 5) + " mm would fit" : "no eccentricity fits";
    }
    rho.lo_node->FailWith("every tooth in the ranges is undercut: even the most favourable corner (" + corner +
                          ") has a smallest tooth radius of " + Format(cycloid::MinConvexProfileRadius(d), 4) +
                          " mm, below min_profile_radius_mm " + Format(lim.min_profile_radius_mm) + "; " + fit);
  }
  if (lim.bore_radius_mm > 0) {
    const double web = cycloid::WebMargin(d, lim.bore_radius_mm, lim.min_web_mm);
    if (web < 0) {
      const double fit = 2 * (cycloid::RootRadius(d) - lim.min_web_mm);
      root["limits"]["bore_diameter_mm"].FailWith(
          "no design of the ranges has room for the bore: even the most favourable corner (" + corner +
          ") has a root radius a' - e - rho' of " + Format(cycloid::RootRadius(d), 5) + " mm, less than the bore radius " +
          Format(lim.bore_radius_mm) + " mm plus min_web_mm " + Format(lim.min_web_mm) + "; " +
          (fit > 0 ? "a bore of at most " + Format(fit, 5) + " mm diameter would fit" : "no bore fits"));
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Running.

// A limit row's study key (its name without the sample index).
std::string LimitKeyOfRow(const std::string& row) {
  const std::string base = row.substr(0, row.find('['));
  if (base == sizing::kSizingPeakPressure) return "contact_stress_MPa";
  if (base == sizing::kSizingEndDistance) return "min_edge_margin_um";
  if (base == sizing::kSizingBacklash) return "min_backlash_arcsec / max_backlash_arcsec";
  if (base == sizing::kSizingLte) return "max_lte_peak_to_peak_arcsec";
  if (base == sizing::kSizingCurtate) return "min_curtate_margin";
  if (base == sizing::kSizingUndercut) return "min_profile_radius_mm";
  if (base == sizing::kSizingPinGap) return "min_pin_gap_mm";
  if (base == sizing::kSizingWeb) return "min_web_mm";
  if (base == sizing::kSizingCrowningFit) return "crowning_on_the_face";
  if (base == sizing::kSizingLife) return "life_h";
  if (base == sizing::kSizingStatic) return "min_static_safety";
  return base;
}

// Why the answer is not what was asked (exit 3), or "" when it is: the limit that blocks, its value
// at the design the solve ended on, and the value of that limit at which that design fits.
std::string BlockingMessage(const Study& s, const sizing::CycloidMinSizeOutcome& o) {
  if (o.x.empty())
    return "no design meets the limits: the optimizer ended without a design (" +
           (o.result.message.empty() ? std::string(optimizers::ToString(o.result.status)) : o.result.message) +
           "); widen the ranges or relax the limits";
  if (o.verified && o.converged) return "";
  const std::string size = "the closest design (outer diameter " + Format(o.check.accurate.outer_diameter_mm, 5) + " mm)";
  std::string rows_violated;
  {
    std::set<std::string> seen;
    for (const std::string& row : o.result.violated)
      if (seen.insert(LimitKeyOfRow(row)).second) rows_violated += (rows_violated.empty() ? "" : ", ") + LimitKeyOfRow(row);
  }
  if (o.verified)
    return "the optimizer stopped at " + std::string(optimizers::ToString(o.result.status)) +
           (rows_violated.empty() ? "" : " (the fast model's " + rows_violated + " broken)") + " at a design (outer diameter " +
           Format(o.check.accurate.outer_diameter_mm, 5) +
           " mm) that the accurate model verifies: it meets every limit but is not known to be the smallest; "
           "give more optimizer.starts or optimizer.max_evaluations, or start elsewhere";
  // The check that breaks its limit by the largest share of the larger of the limit and the
  // value (Verification::worst divides by the limit alone, which makes any broken limit of 0, an
  // edge margin or a backlash, the worst whatever its size).
  const objectives::VerifiedLimit* w = nullptr;
  double share = 0;
  for (const objectives::VerifiedLimit& c : o.verification.checks) {
    if (c.holds()) continue;
    const double part = c.excess() / std::max({std::abs(c.limit_value), std::abs(c.accurate_value), c.estimated_error, 1e-12});
    if (!w || part > share) w = &c, share = part;
  }
  if (w) {
    // The value of the limit at which that design holds: its accurate value within its error.
    const double fit = w->upper ? w->accurate_value - w->estimated_error : w->accurate_value + w->estimated_error;
    const std::string head = o.converged ? "the optimum of the fast model is not verified: "
                                         : "no design meets the limits (the optimizer stopped at an infeasible point, " +
                                               std::string(optimizers::ToString(o.result.status)) + "): ";
    return head + w->limit + (w->where.empty() ? "" : " (" + w->where + ")") + " blocks; at " + size + " it is " +
           Format(w->accurate_value, 5) + " +- " + Format(w->estimated_error, 2) + " by the accurate model against the limit " +
           Format(w->limit_value, 5) + "; that design fits with " + w->limit + " = " + Format(fit, 5) +
           (o.verification.history.empty() ? "" : " (after " + std::to_string(o.verification.history.size()) +
                                                      " tightening rounds)");
  }
  // No accurate check breaks: the closed-form rows the solver left violated.
  const sizing::CycloidSizingEvaluation& a = o.check.accurate;
  const CycloidSizingLimits& lim = s.spec.limits;
  struct Row {
    const char* key;
    double value, limit;
  };
  const Row rows[] = {{"min_curtate_margin", a.curtate_margin, lim.min_curtate_margin},
                      {"min_profile_radius_mm", a.min_profile_radius_mm, lim.min_profile_radius_mm},
                      {"min_pin_gap_mm", a.pin_gap_margin_mm + lim.min_pin_gap_mm, lim.min_pin_gap_mm},
                      {"min_web_mm", a.web_margin_mm + lim.min_web_mm, lim.min_web_mm}};
  for (const Row& r : rows)
    if (r.value < r.limit && (std::string(r.key) != "min_web_mm" || lim.bore_radius_mm > 0))
      return "no design meets the limits (the optimizer stopped at " + std::string(optimizers::ToString(o.result.status)) +
             "): " + r.key + " blocks; at " + size + " it is " + Format(r.value, 5) + " against the limit " +
             Format(r.limit, 5) + "; that design fits with " + r.key + " = " + Format(r.value, 5);
  return "no design meets the limits: the optimizer stopped at " + std::string(optimizers::ToString(o.result.status)) +
         (rows_violated.empty() ? "" : " with " + rows_violated + " broken") + " at " + size + " (" + o.result.message + ")";
}

// The bearing life (docs/life.md, "Cycloid"): "load.input_speed_rpm" (at the design torque) or a
// "duty_cycle", the ratings and the output mechanism as cycloid_ltca reads them; "limits.life_h"
// needs them. The output pins' circle is checked against the start's root radius (it is fixed:
// the report says when the sized disc's root falls inside it).
void ParseSizingLife(const Node& root, const Input& in, Study& s) {
  std::optional<cycloid_common::LifeSpec> life =
      cycloid_common::ParseLife(root, in, s.spec.drive, s.spec.design_torque_Nmm, true);
  // "ratings" (docs/ratings.md, Ratings as sizing limits): the rated point as the life rows' one
  // cycle (load.input_speed_rpm then only sets the lubricated losses' speed).
  s.ratings = in.ratings;
  if (in.torsional_dynamics) {
    (void)ParseTorsionalDynamics(root["torsional_dynamics"], *in.torsional_dynamics);  // its own rules, exit 2
    s.torsional_dynamics = in.torsional_dynamics;
  }
  if (in.ratings) {
    CheckSizingRatingsAlone(root, in.limits.life_h.has_value(), in.duty_cycle.has_value());
    if (!life) life = cycloid_common::ParseLifeRatings(root, in, s.spec.drive, "a rated torque is asked: ratings is given",
                                                       true);
    const double ratio = double(s.spec.drive.teeth) / double(s.spec.drive.rollers - s.spec.drive.teeth);
    life->lines = {in.ratings->RatedLine(ratio)};
    s.spec.limits.life_h = in.ratings->rated_life_h;
    if (in.ratings->momentary_torque_Nm) {
      // The momentary torque (docs/ratings.md, Ratings as sizing limits): the crank bearing and the
      // pins with a static rating keep s0 >= momentary_static_safety there (one more cycle).
      if (!(life->crank_bearing.static_N > 0) && !(life->pins_rated && life->pins.static_N > 0))
        root["ratings"]["momentary_torque_Nm"].FailWith(
            "a momentary torque needs a static rating to hold: crank_bearing.static_rating_N or "
            "pins.static_rating_N, found neither");
      s.spec.limits.min_static_safety = in.ratings->momentary_static_safety;
      s.spec.limits.static_torque_Nmm = *in.ratings->momentary_torque_Nm * 1000.0;
    }
  }
  if (s.spec.limits.life_h > 0 && !life)
    root["limits"]["life_h"].FailWith("a life limit needs the speed: expected load.input_speed_rpm (> 0) or a "
                                      "duty_cycle beside limits.life_h, found neither");
  if (!life) return;
  sizing::CycloidSizingLife l;
  l.lines = life->lines;
  l.crank_kind = life->crank_bearing.kind;
  l.crank_dynamic_N = life->crank_bearing.dynamic_N;
  l.crank_static_N = life->crank_bearing.static_N;
  l.pins_rated = life->pins_rated;
  l.pins_dynamic_N = life->pins.dynamic_N;
  l.pins_static_N = life->pins.static_N;
  l.output = life->output;
  s.spec.life = l;
}

// The output mechanism with clearance and compliance (cycloid_ltca's, studies/cycloid_study_common.h)
// and the limits that need it. The pins are fixed; the holes are made for the sized eccentricity
// with the radial clearance the file gives at the start, c = hole_radius_mm − r_c − e (>= 0),
// r_h = r_c + e + c; the span covers the largest face width; the holes' place in the root circle is
// a row of the sizing (kSizingOutputHoles), checked here at the start.
// The lubricated losses (docs/lubrication.md): the blocks as cycloid_ltca reads them, at the design
// torque and load.input_speed_rpm; the output pins' forces from the rigid mechanism, their contacts
// (with pin and hole radii) with the holes following the sized eccentricity as the compliant
// mechanism's; limits.max_oil_temperature_C needs the housing's balance.
void ParseSizingLubrication(const Node& root, const Input& in, Study& s) {
  const std::optional<double> speed = in.load ? in.load->input_speed_rpm : std::nullopt;
  const std::optional<LubricationCommon> common =
      ParseLubricationCommon(root, in.lubricant, in.surfaces, std::nullopt, speed, root.Has("duty_cycle"));
  if (!common) return;
  const Node node = root["lubricant"];
  if (!root.Has("output_mechanism"))
    node.FailWith("the lubricated losses need \"output_mechanism\" (its pins carry the torque out and load the crank "
                  "bearing): give at least pin_circle_radius_mm");
  auto l = SizingLubricationOf<sizing::CycloidSizingLubrication>(root, in.limits.max_oil_temperature_C, *common);
  l.spec.ring_pins_rotate = common->rollers_rotate;
  const CycloidBearingFrictionInput bearings = in.bearing_friction.value_or(CycloidBearingFrictionInput{});
  if (bearings.ring_pins) l.spec.ring_pin_bearing = bearings.ring_pins->ToBearing();
  if (bearings.output_rollers) l.spec.output_roller_bearing = bearings.output_rollers->ToBearing();
  if (bearings.crank) l.spec.crank_bearing = bearings.crank->ToBearing();
  l.mechanism = cycloid_common::ParseOutputMechanism(root["output_mechanism"], s.spec.drive, true);
  if (s.spec.output) {
    const cycloid::OutputPins& p = s.spec.output->pins;
    l.pins = cycloid::OutputPinContact{p.pin_radius_mm, 0.0, p.roller_radius_mm};
    l.hole_clearance_mm = s.spec.output->clearance_mm;
  }
  s.spec.lubrication = l;
  s.spec.limits.min_efficiency = in.limits.min_efficiency.value_or(0.0);
  s.spec.limits.max_oil_temperature_C = in.limits.max_oil_temperature_C.value_or(kInf);
  s.lubrication_blocks = {in.lubricant, in.surfaces, in.bearing_friction};
}

void ParseSizingOutput(const Node& root, const Input& in, const std::map<std::string, Field>& fields, Study& s) {
  const Field& b = fields.at("face_width_mm");
  const std::optional<cycloid_common::CompliantOutputSpec> o = cycloid_common::ParseCompliantOutput(
      root, in.output_mechanism, s.spec.drive, s.spec.drive.eccentricity_mm, b.variable ? b.hi : s.spec.drive.face_width_mm,
      "the largest face width");
  const Input::Limits& l = in.limits;
  const std::pair<const char*, bool> needs[] = {
      {"min_torsional_stiffness_Nm_per_arcmin", bool(l.min_torsional_stiffness_Nm_per_arcmin)},
      {"max_lost_motion_arcmin", bool(l.max_lost_motion_arcmin)},
      {"output_pin_stress_MPa", bool(l.output_pin_stress_MPa)},
      {"eccentric_bearing_load_N", bool(l.eccentric_bearing_load_N)}};
  for (const auto& [key, given] : needs)
    if (given && !o)
      root["limits"][key].FailWith(std::string(key) + " needs the output mechanism with clearance and compliance: "
                                   "output_mechanism with pins, pin_circle_radius_mm, pin_radius_mm and hole_radius_mm");
  if (!o) return;
  sizing::CycloidSizingOutput out;
  out.pins = o->pins;
  out.support = o->support;
  out.span_mm = in.output_mechanism->pin_span_mm ? o->span_mm : 0.0;  // absent: the face width, sized or not
  out.clearance_mm = o->pins.clearance_mm(s.spec.drive.eccentricity_mm);
  s.spec.output = out;
  CycloidSizingLimits& lim = s.spec.limits;
  lim.min_torsional_stiffness_Nm_per_arcmin = l.min_torsional_stiffness_Nm_per_arcmin.value_or(0.0);
  lim.max_lost_motion_arcmin = l.max_lost_motion_arcmin.value_or(kInf);
  lim.output_pin_stress_MPa = l.output_pin_stress_MPa.value_or(kInf);
  lim.eccentric_bearing_load_N = l.eccentric_bearing_load_N.value_or(kInf);
}

}  // namespace

Study Parse(const Node& root) {
  const Input in = Read<Input>(root);
  Study s;
  s.name = in.name;
  ParseTarget(root, in.target, s);
  ParseLimits(root, in.limits, s);
  s.spec.material = in.material.ToMaterial();
  ParseAnalysis(in.analysis, s);
  ParseOptimizer(in.optimizer, s);
  if (in.objective == "volume") s.spec.objective = sizing::CycloidSizeObjective::kVolume;
  const std::map<std::string, Field> fields = ParseDesign(root, in, s);
  CheckPlausibleBox(fields, s.spec.drive.rollers);
  CheckCrowningBox(root, fields, s);
  CheckClosedFormCorner(root, fields, s);
  ParseSizingLife(root, in, s);
  ParseSizingOutput(root, in, fields, s);
  ParseSizingLubrication(root, in, s);
  if (in.objective == "efficiency") {
    if (!s.spec.lubrication)
      root["objective"].FailWith("the efficiency objective needs \"lubricant\" (the oil whose losses it minimises) and "
                                 "load.input_speed_rpm");
    s.spec.objective = sizing::CycloidSizeObjective::kPowerLoss;
  }
  return s;
}

nlohmann::ordered_json Input::Variables::VariableSchema(const std::string& name) {
  using ojson = nlohmann::ordered_json;
  // The bound of the field's values, of a range's items and of the start; a range's own bound on
  // one end (prefixItems), and the description's tail.
  ojson bound = ojson::object(), prefix;
  std::string tail;
  if (name == "delta_position_um" || name == "delta_radius_um") {
    prefix = ojson::array({ojson::object(),
                           {{"maximum", 0}, {"description", "upper bound <= 0 (a positive modification interferes)"}}});
    tail = "[um]; a range's upper bound <= 0";
  } else if (name == "coefficient_mm" || name == "flat_length_mm") {
    bound = {{"minimum", 0}};
    tail = ">= 0 [mm]";
  } else if (name == "effective_length_mm") {
    bound = {{"minimum", 0}};
    prefix = ojson::array(
        {{{"exclusiveMinimum", 0}, {"description", "lower bound > 0 (0, L = the face width, is a fixed value only)"}}});
    tail = ">= the face width [mm], or 0 (L = the face width; a fixed value only)";
  } else if (name == "end_drop_mm") {
    bound = {{"minimum", 0}};
    prefix = ojson::array({{{"exclusiveMinimum", 0}, {"description", "lower bound > 0 (0 means an unbounded drop)"}}});
    tail = ">= 0 [mm]; a range's lower bound > 0";
  } else {  // the drive's lengths and the crowning radius
    bound = {{"exclusiveMinimum", 0}};
    tail = name == "radius_mm" ? "> 0 [mm], more than half the crowned length" : "> 0 [mm]";
  }
  ojson item = {{"type", "number"}};
  item.update(bound);
  ojson range = {{"type", "array"}, {"items", item}, {"minItems", 2}, {"maxItems", 2}};
  if (!prefix.is_null()) range["prefixItems"] = prefix;
  range["description"] = "[lower, upper] with lower <= upper (equal: a fixed value)";
  ojson start = {{"type", "number"}};
  start.update(bound);
  start["description"] = "the start, within the range";
  ojson v = {{"type", {"number", "array", "object"}}};
  v.update(bound);
  v["items"] = item;
  if (!prefix.is_null()) v["prefixItems"] = prefix;
  v["minItems"] = 2;
  v["maxItems"] = 2;
  v["properties"] = {{"range", range}, {"start", start}};
  v["required"] = {"range"};
  v["additionalProperties"] = false;
  v["description"] = "a number (fixed), [lower, upper] (a range, starting at its middle) or {\"range\": [lower, upper], "
                     "\"start\": value}; " + tail;
  return v;
}

nlohmann::ordered_json Input::SchemaRules() {
  // Each sized field once: in variables or in its block (drive, modification, crowning); the
  // drive's fields in one of the two; a crowning variable needs the crowning type that has it, and
  // each type's fields are given or variables; a life (a speed or a duty cycle) needs the crank
  // bearing and the output mechanism, one speed form, and limits.life_h a speed; min_edge_margin_um
  // needs the overload torque.
  using oj = nlohmann::ordered_json;
  auto required = [](std::vector<std::string> keys) {
    oj r = oj::object();
    r["required"] = keys;
    return r;
  };
  auto in = [](const std::string& block, oj rule) {  // {"properties": {block: rule}}
    oj r = oj::object();
    r["properties"][block] = std::move(rule);
    return r;
  };
  auto given = [&](const std::string& block, const std::string& field) {  // block present with field
    oj r = required({block});
    r["properties"][block] = required({field});
    return r;
  };
  auto when = [](oj condition, oj then) {
    oj r = oj::object();
    r["if"] = std::move(condition);
    r["then"] = std::move(then);
    return r;
  };
  auto any_of = [](oj alternatives) {
    oj r = oj::object();
    r["anyOf"] = std::move(alternatives);
    return r;
  };
  auto negated = [](oj rule) {
    oj r = oj::object();
    r["not"] = std::move(rule);
    return r;
  };
  auto crowning_type = [&](const std::vector<std::string>& types) {
    oj type = oj::object();
    type["properties"]["type"]["enum"] = types;
    oj r = required({"crowning"});
    r["properties"]["crowning"] = type;
    return r;
  };
  const oj speed = oj::array({required({"duty_cycle"}), given("load", "input_speed_rpm")});
  oj all = oj::array();
  all.push_back(when(given("limits", "min_edge_margin_um"), in("target", required({"overload_torque_Nm"}))));
  for (const auto& [block, field] : Variables::kSized)
    all.push_back(when(in("variables", required({field})), in(block, negated(required({field})))));
  for (const auto& [block, field] : Variables::kSized)
    if (std::string(block) == "drive")
      all.push_back(any_of(oj::array({in("variables", required({field})), given("drive", field)})));
  for (const auto& [block, field] : Variables::kSized) {
    if (std::string(block) != "crowning") continue;
    std::vector<std::string> types;  // the crowning types that have the field, sorted
    for (const auto& t : cycloid_common::CrowningTypes())
      if (std::string(t.type) != "none" &&
          std::none_of(t.refused.begin(), t.refused.end(), [f = field](const char* r) { return std::string(r) == f; }))
        types.push_back(t.type);
    std::sort(types.begin(), types.end());
    all.push_back(when(in("variables", required({field})), crowning_type(types)));
  }
  for (const auto& t : cycloid_common::CrowningTypes())
    for (const char* field : t.required)
      all.push_back(when(crowning_type({t.type}),
                         any_of(oj::array({in("crowning", required({field})), in("variables", required({field}))}))));
  all.push_back(when(any_of(speed), required({"crank_bearing", "output_mechanism"})));
  all.push_back(when(required({"ratings"}), required({"crank_bearing", "output_mechanism"})));
  all.push_back(when(given("ratings", "momentary_torque_Nm"),
                     any_of(oj::array({given("crank_bearing", "static_rating_N"), given("pins", "static_rating_N")}))));
  all.push_back(when(required({"ratings"}), negated(any_of(oj::array({required({"duty_cycle"}), given("limits", "life_h")})))));
  all.push_back(when(required({"duty_cycle"}), in("load", negated(required({"input_speed_rpm"})))));
  all.push_back(when(given("limits", "life_h"), any_of(speed)));
  for (const char* key : {"min_torsional_stiffness_Nm_per_arcmin", "max_lost_motion_arcmin", "output_pin_stress_MPa",
                          "eccentric_bearing_load_N"})
    all.push_back(when(given("limits", key), given("output_mechanism", "pin_radius_mm")));
  all.push_back(when(required({"lubricant"}), required({"output_mechanism"})));
  all.push_back(when(oj::parse(R"({"required": ["objective"], "properties": {"objective": {"const": "efficiency"}}})"),
                     required({"lubricant"})));
  all.push_back(when(given("limits", "max_oil_temperature_C"), in("lubricant", required({"thermal"}))));
  oj rules = oj::object();
  rules["allOf"] = all;
  AddLubricationSchemaRules(rules);
  return rules;
}

namespace {

// result.json's members of r from the study and the outcome (below).
void FillResult(const Study& s, Result& r);

// The reported design's torsional dynamics by cycloid_ltca's model (docs/torsional_dynamics.md) on
// its own study (best_cycloid_ltca.json, without the ratings it would also solve), and the dynamic
// overload limit as one more check of the verification: the sweep's largest overload factor within
// the limit plus its sampling error. The optimizer does not steer by it: a design above it is not
// verified (exit 3, the limit named), and the design cannot be re-solved toward it.
void CheckTorsionalDynamics(const Study& s, Result& r, const RunContext& ctx) {
  nlohmann::json j = BestCycloidLtcaStudy(s, r);
  j.erase("ratings");
  const std::optional<double> max_factor = s.torsional_dynamics->max_dynamic_factor;
  const bool limited = max_factor.has_value();
  objectives::VerifiedLimit c;
  c.limit = "max_dynamic_factor";
  c.where = "the sweep's largest dynamic overload factor (cycloid_ltca's torsional model on the reported design)";
  c.limit_value = max_factor.value_or(0.0);
  c.accurate_value = std::numeric_limits<double>::quiet_NaN();
  c.fast_value = std::numeric_limits<double>::quiet_NaN();
  c.upper = true;
  try {
    const cycloid_ltca::Study ls = cycloid_ltca::Parse(Node(&j, ctx.study_file, ""));
    RunContext quiet = ctx;
    quiet.quiet = true;
    const cycloid_ltca::Result lr = cycloid_ltca::Run(ls, quiet);
    if (!lr.torsional) throw std::runtime_error(lr.torsional_failed);
    r.torsional = TorsionalDynamicsBlock::Of(*ls.torsional, *lr.torsional);
    if (lr.torsional->peak_index >= 0) {
      const auto& peak = lr.torsional->sweep[size_t(lr.torsional->peak_index)];
      c.accurate_value = peak.overload_factor;
      c.estimated_error = peak.overload_sampling_error;
    }
  } catch (const std::exception& e) {
    r.torsional = StageError{e.what()};
    r.warnings.push_back(std::string("torsional dynamics of the reported design not solved: ") + e.what());
  }
  if (!limited) return;
  r.outcome.verification.checks.push_back(c);
  r.outcome.verified = r.outcome.verification.verified();
}

}  // namespace

Result Run(const Study& s, const RunContext& ctx) {
  Result r;
  const auto t0 = std::chrono::steady_clock::now();
  Progress progress("cycloid_min_size", ctx.quiet);
  sizing::CycloidMinSizeOptions options = s.options;
  options.progress = [&](double fraction, const std::string& stage) { progress.Update(0.9 * fraction, stage); };
  try {
    r.outcome = sizing::SolveCycloidMinSize(s.spec, options);
  } catch (const std::invalid_argument& e) {
    // A spec the sizing model refuses that the parse let through: bad input all the same.
    throw StudyError(ctx.study_file + ": /variables: the sizing model refuses the study: " + e.what());
  }
  if (!r.outcome.x.empty()) {
    // The stress over the cycle and the pressure maps of the reported design at the accurate
    // settings (twice the cells each way, twice the crank angles: sizing/cycloid_min_size.h).
    cycloid::LoadedOptions accurate = s.spec.options;
    accurate.profile_cells *= 2;
    accurate.axial_cells *= 2;
    accurate.keep_pressure = true;
    const int n = s.spec.drive.rollers;
    r.best_cycle_angles_rad = cycloid::UniformCrankAngles(2 * s.spec.angles_per_period, 2.0 * kPi / n);
    try {
      const cycloid::LoadedTca tca(r.outcome.drive, r.outcome.crowning, s.spec.material, accurate);
      r.best_cycle = cycloid::RunCycle(tca, s.spec.design_torque_Nmm, r.best_cycle_angles_rad, [&](double f) {
        progress.Update(0.9 + 0.1 * f, "the best design's cycle at the accurate settings");
      });
    } catch (const std::invalid_argument& e) {
      r.best_cycle_angles_rad.clear();
      r.warnings.push_back("no stress_over_cycle or pressure_map: the loaded contact analysis refuses the design (" +
                           std::string(e.what()) + ")");
    }
    const sizing::CycloidAccurateCheck& k = r.outcome.check;
    if (s.spec.life) {
      const cycloid::Drive& d = r.outcome.drive;
      const double root_radius = d.roller_position_radius_mm + d.delta_position_mm - d.eccentricity_mm -
                                 d.roller_radius_mm - d.delta_radius_mm;
      if (!(s.spec.life->output.pin_circle_radius_mm < root_radius))
        r.warnings.push_back("output_mechanism.pin_circle_radius_mm " +
                             Format(s.spec.life->output.pin_circle_radius_mm, 5) + " mm is not inside the sized disc's "
                             "root radius " + Format(root_radius, 5) + " mm: the output pins are fixed in the sizing "
                             "(not a variable); choose a smaller pin circle for this drive");
    }
    if (k.stress_error_MPa > 0.05 * k.accurate.stress_MPa)
      r.warnings.push_back("best.accurate.max_contact_stress_MPa: estimated discretisation error " +
                           Format(k.stress_error_MPa, 3) + " MPa exceeds 5% of the value " +
                           Format(k.accurate.stress_MPa, 5) +
                           " MPa (refine analysis.grid or analysis.crank_angles_per_mesh_period)");
  }
  if (!r.outcome.x.empty() && s.torsional_dynamics) CheckTorsionalDynamics(s, r, ctx);
  progress.Done();
  r.blocking_message = BlockingMessage(s, r.outcome);
  FillResult(s, r);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

namespace {

// The values of one model at the reported design (accurate or fast), by their result.json names.
Result::Model ModelOf(const Study& s, const sizing::CycloidSizingEvaluation& e) {
  Result::Model j;
  j.max_contact_stress_MPa = Finite(e.stress_MPa, "stress");
  j.max_pair_load_N = Finite(e.max_pair_load_N, "pair load");
  if (s.spec.overload_torque_Nmm > 0) j.edge_margin_at_overload_um = Finite(e.edge_margin_um, "edge margin");
  if (!e.unloaded_te_arcsec.empty()) {
    const auto [lo, hi] = std::minmax_element(e.unloaded_te_arcsec.begin(), e.unloaded_te_arcsec.end());
    j.backlash_min_arcsec = Finite(*lo, "backlash");
    j.backlash_max_arcsec = Finite(*hi, "backlash");
  }
  j.lte_peak_to_peak_arcsec = Finite(e.lte_peak_to_peak_arcsec, "LTE");
  if (s.spec.output) {  // cycloid_ltca's names (its "stiffness" at the design torque, crank 0)
    j.torsional_stiffness_Nm_per_arcmin = e.stiffness_Nm_per_arcmin;
    j.lost_motion_arcmin = e.lost_motion_arcmin;
    j.output_pin_bending_stress_MPa = e.max_output_pin_stress_MPa;
    j.eccentric_bearing_load_N = e.max_crank_bearing_load_N;
  }
  if (s.spec.lubrication) {  // one disc at the design torque and the input speed (docs/lubrication.md)
    j.efficiency = e.efficiency;
    j.power_loss_W = e.power_loss_W;
    j.oil_temperature_C = e.oil_temperature_C;
    if (!e.lubrication_why.empty()) j.lubrication_error = e.lubrication_why;
  }
  j.converged = e.converged;
  return j;
}

nlohmann::json DriveJson(const cycloid::Drive& d) {
  return {{"teeth", d.teeth},
          {"rollers", d.rollers},
          {"roller_position_radius_mm", d.roller_position_radius_mm},
          {"roller_radius_mm", d.roller_radius_mm},
          {"eccentricity_mm", d.eccentricity_mm},
          {"face_width_mm", d.face_width_mm}};
}

nlohmann::json ModificationJson(const cycloid::Drive& d) {
  return {{"delta_position_um", d.delta_position_mm * 1e3}, {"delta_radius_um", d.delta_radius_mm * 1e3}};
}

std::string ObjectiveUnit(const Study& s) {
  return s.spec.objective == sizing::CycloidSizeObjective::kVolume      ? "mm3"
         : s.spec.objective == sizing::CycloidSizeObjective::kPowerLoss ? "W of loss"
                                                                             : "mm";
}

// The unit of a limit, from its key (the suffix of the study's field name).
std::string LimitUnit(const std::string& key) {
  if (key == "crowning_on_the_face") return "mm";  // the crowning rows (sizing::kSizingCrowningFit)
  if (key == "min_torsional_stiffness_Nm_per_arcmin") return "N·m/arcmin";
  if (key == "max_lost_motion_arcmin") return "arcmin";
  if (key == "eccentric_bearing_load_N") return "N";
  if (key == "output_holes_fit_mm") return "mm";
  if (key == "max_oil_temperature_C") return "°C";
  for (const char* u : {"MPa", "um", "mm", "arcsec", "h"}) {
    const std::string suffix = std::string("_") + u;
    if (key.size() > suffix.size() && key.compare(key.size() - suffix.size(), suffix.size(), suffix) == 0) return u;
  }
  return "1";
}

// The study's value of a limit, by its key (NaN for an unknown key).
double LimitValue(const Study& s, const std::string& key) {
  const CycloidSizingLimits& l = s.spec.limits;
  if (key == "contact_stress_MPa") return l.contact_stress_MPa;
  if (key == "min_edge_margin_um") return l.min_edge_margin_um;
  if (key == "min_curtate_margin") return l.min_curtate_margin;
  if (key == "min_profile_radius_mm") return l.min_profile_radius_mm;
  if (key == "min_pin_gap_mm") return l.min_pin_gap_mm;
  if (key == "min_backlash_arcsec") return l.min_backlash_arcsec;
  if (key == "max_backlash_arcsec") return l.max_backlash_arcsec;
  if (key == "max_lte_peak_to_peak_arcsec") return l.max_lte_peak_to_peak_arcsec;
  if (key == "min_web_mm") return l.min_web_mm;
  if (key == "bore_diameter_mm") return 2 * l.bore_radius_mm;
  if (key == "life_h") return l.life_h;
  if (key == "min_static_safety") return l.min_static_safety;
  if (key == "min_torsional_stiffness_Nm_per_arcmin") return l.min_torsional_stiffness_Nm_per_arcmin;
  if (key == "max_lost_motion_arcmin") return l.max_lost_motion_arcmin;
  if (key == "output_pin_stress_MPa") return l.output_pin_stress_MPa;
  if (key == "eccentric_bearing_load_N") return l.eccentric_bearing_load_N;
  if (key == "output_holes_fit_mm") return 0.0;
  if (key == "min_efficiency") return l.min_efficiency;
  if (key == "max_oil_temperature_C") return l.max_oil_temperature_C;
  return NAN;
}

// best.life (docs/life.md, "Cycloid"): the lives of the accurate model as cycloid_ltca's "life",
// with pass/fail against limits.life_h.
cycloid_common::SizingLifeBlock SizingLifeOf(const Study& s, const cycloid::Drive& d,
                                              const sizing::CycloidSizingEvaluation& acc) {
  const sizing::CycloidSizingLife& life = *s.spec.life;
  const double limit = s.spec.limits.life_h;
  cycloid_common::SizingLifeBlock lj;
  if (limit > 0) lj.life_h = limit;
  lj.shortest_L10h = acc.shortest_life_h;
  double least = kInf;
  for (const sizing::CycloidBearingLife& b : acc.lives) {
    lj.SetElementLife(b.name, b.life.L10h);
    if (lj.shortest_bearing.empty() || b.life.L10h < least) lj.shortest_bearing = b.name, least = b.life.L10h;
    LifeTableRow row = BearingLifeRow(b.name, b.ball, b.life.equivalent_load_N, b.life.max_load_N,
                                      b.life.revolutions_per_input_revolution, b.dynamic_N, b.static_N, b.s0,
                                      b.life.L10h, limit);
    row.line_equivalent_load_N = b.life.line_equivalent_load_N;
    lj.table.push_back(std::move(row));
  }
  lj.duty_cycle = DutyCycleEchoOf(life.lines);
  const double root_radius = d.roller_position_radius_mm + d.delta_position_mm - d.eccentricity_mm -
                             d.roller_radius_mm - d.delta_radius_mm;
  lj.output_mechanism.pin_count = cycloid_common::LifeOutputMechanism::PinCount(life.output.pin_count);
  lj.output_mechanism.pin_circle_radius_mm = life.output.pin_circle_radius_mm;
  lj.output_mechanism.inside_root_radius = life.output.pin_circle_radius_mm < root_radius;
  lj.efficiency = s.spec.lubrication ? "best.accurate.efficiency (the lubricated losses, docs/lubrication.md)"
                                     : "not computed without \"lubricant\" (docs/lubrication.md)";
  lj.model = "ISO 281:2007 basic rating life L10 over the duty cycle (Palmgren-Miner) on the accurate model's "
             "cycles, computed as cycloid_ltca does (docs/life.md, Cycloid)";
  return lj;
}

Result::StartOutcome StartOf(const optimizers::SolverResult& r) {
  return {optimizers::ToString(r.status), r.message, r.objective, r.max_violation, r.first_order_residual,
          r.value_evaluations, r.gradient_evaluations, r.iterations, r.x};
}

// The accurate settings of the verification and the plots (sizing/cycloid_min_size.h: twice
// the cells each way, twice the crank angles), as cycloid_ltca's "analysis" block.
Result::Settings AccurateSettings(const Study& s) {
  Result::Settings a;
  a.grid = {std::min(512, 2 * s.spec.options.profile_cells), std::min(512, 2 * s.spec.options.axial_cells)};
  a.crank_angles_per_mesh_period = std::min(10000, 2 * s.spec.angles_per_period);
  a.tolerance = s.spec.options.tolerance;
  return a;
}
nlohmann::json AccurateAnalysisJson(const Study& s) { return WriteResult(AccurateSettings(s)); }

// The former ToJson's arithmetic, in its order (the same Finite checks first to fail).
void FillResult(const Study& s, Result& r) {
  const sizing::CycloidMinSizeOutcome& o = r.outcome;
  r.name = s.name;
  r.target.teeth = s.spec.drive.teeth;
  r.target.rollers = s.spec.drive.rollers;
  r.target.speed_ratio = s.spec.drive.teeth;
  r.target.design_torque_Nm = s.design_torque_Nm;
  if (s.overload_torque_Nm > 0) r.target.overload_torque_Nm = s.overload_torque_Nm;
  r.objective = s.spec.objective == sizing::CycloidSizeObjective::kVolume      ? "volume"
                : s.spec.objective == sizing::CycloidSizeObjective::kPowerLoss ? "efficiency"
                                                                                    : "outer_diameter";
  r.variables.clear();
  for (const objectives::Variable& v : s.spec.variables) r.variables.push_back({v.name, v.lower, v.upper, v.initial});
  r.verified = o.verification.verified();
  r.verification = VerificationBlock::Of(o.verification);
  if (o.x.empty()) {
    r.best.reset();
  } else {
    const sizing::CycloidSizingEvaluation& acc = o.check.accurate;
    Result::Best& b = r.best.emplace();
    b.outer_diameter_mm = Finite(2 * (o.drive.roller_position_radius_mm + o.drive.roller_radius_mm), "outer diameter");
    b.envelope_volume_mm3 =
        Finite(kPi * std::pow(o.drive.roller_position_radius_mm + o.drive.roller_radius_mm, 2) * o.drive.face_width_mm,
               "volume");
    b.drive = {o.drive.teeth,           o.drive.rollers,         o.drive.roller_position_radius_mm,
               o.drive.roller_radius_mm, o.drive.eccentricity_mm, o.drive.face_width_mm};
    b.modification = {o.drive.delta_position_mm * 1e3, o.drive.delta_radius_mm * 1e3};
    b.crowning = cycloid_common::CrowningInputOf(o.crowning);
    for (size_t k = 0; k < s.spec.variables.size() && k < o.x.size(); ++k)
      b.variables[s.spec.variables[k].name] = Finite(o.x[k], s.spec.variables[k].name);
    // Variables the optimum presses against a bound of their range: widening it would shrink the
    // drive further (the bounds' own multipliers are not reported).
    for (size_t k = 0; k < s.spec.variables.size() && k < o.x.size(); ++k) {
      const objectives::Variable& v = s.spec.variables[k];
      // Ipopt stays a little inside its bounds (bound_push): 0.1% of the range.
      const double tol = 1e-3 * (v.upper - v.lower);
      if (o.x[k] <= v.lower + tol) b.variables_at_bounds.push_back({v.name, "lower", v.lower});
      else if (o.x[k] >= v.upper - tol) b.variables_at_bounds.push_back({v.name, "upper", v.upper});
    }
    // The closed-form limits (geometry_limits.h): exact, the same for both models.
    b.curtate_margin = Finite(acc.curtate_margin, "curtate margin");
    b.undercut_margin_mm = Finite(acc.undercut_margin_mm, "undercut margin");
    b.min_profile_radius_mm = Finite(acc.min_profile_radius_mm, "profile radius");
    b.pin_gap_margin_mm = Finite(acc.pin_gap_margin_mm, "pin gap margin");
    if (s.spec.limits.bore_radius_mm > 0) b.web_margin_mm = Finite(acc.web_margin_mm, "web margin");
    b.accurate = ModelOf(s, acc);
    b.fast = ModelOf(s, o.check.fast);
    Result::EstimatedError& err = b.estimated_error;
    err.max_contact_stress_MPa = Finite(o.check.stress_error_MPa, "error");
    err.backlash_arcsec = Finite(o.check.backlash_error_arcsec, "error");
    err.lte_peak_to_peak_arcsec = Finite(o.check.lte_error_arcsec, "error");
    if (s.spec.overload_torque_Nmm > 0) err.edge_margin_at_overload_um = Finite(o.check.edge_margin_error_um, "error");
    if (s.spec.output) {
      b.output_holes_margin_mm = Finite(acc.output_holes_margin_mm, "holes margin");
      err.torsional_stiffness_Nm_per_arcmin = o.check.stiffness_error;
      err.lost_motion_arcmin = o.check.lost_motion_error_arcmin;
      err.output_pin_bending_stress_MPa = o.check.output_pin_stress_error_MPa;
      err.eccentric_bearing_load_N = o.check.crank_bearing_error_N;
    }
    if (s.spec.lubrication) {
      err.efficiency = o.check.efficiency_error;
      err.oil_temperature_C = o.check.oil_temperature_error_C;
      const sizing::CycloidSizingLubrication& l = *s.spec.lubrication;
      b.lubrication = Result::Lubrication{
          l.input_speed_rpm, s.design_torque_Nm, l.temperature_C ? "given" : "thermal balance",
          "one disc's mean loss over a revolution's pattern at the design torque (the LTCA's pair loads, "
          "the rigid output pins' forces), Pan-Hamrock line film, friction by regime, Palmgren bearings; "
          "best_cycloid_ltca.json gives the loss split, the film and the efficiency map "
          "(docs/lubrication.md)"};
    }
    b.accurate_model = o.check.model;
    if (s.spec.life) {
      b.life = SizingLifeOf(s, o.drive, acc);
      // Met as the verification holds them: the accurate value within its estimated error (one
      // verdict for the exit code, `verified` and these flags).
      auto holds = [&](const std::string& limit) {
        for (const objectives::VerifiedLimit& c : o.check.checks)
          if (c.limit == limit) return c.holds();
        return false;
      };
      const bool momentary_met = !(s.ratings && s.ratings->momentary_torque_Nm) || holds("min_static_safety");
      if (s.ratings)
        b.ratings = SizedRatingsOf(
            *s.ratings, double(o.drive.teeth) / double(o.drive.rollers - o.drive.teeth), acc.shortest_life_h,
            holds("life_h") && momentary_met, std::nullopt, "",
            "solved by cycloid_ltca from best_cycloid_ltca.json (its ratings block), one LTCA cycle per trial torque: "
            "the loaded contact's loads are not proportional to the torque");
      err.shortest_L10h = Finite(o.check.life_error_h, "error");
      if (s.ratings && s.ratings->momentary_torque_Nm) {
        // The momentary torque: s0 at it on the accurate model; the drive's own momentary torque is
        // cycloid_ltca's root search (the loads are not proportional to the torque).
        b.ratings->SetMomentary(*s.ratings->momentary_torque_Nm, s.ratings->momentary_static_safety,
                                acc.min_static_safety, std::nullopt, std::nullopt,
                                "solved by cycloid_ltca from best_cycloid_ltca.json (its ratings block)", momentary_met);
        err.min_static_safety = o.check.static_safety_error;
      }
    }
    if (r.torsional) b.torsional_dynamics = *r.torsional;
  }
  // What each limit that binds at the optimum costs: d(objective)/d(limit) from the multipliers.
  r.binding_limits.clear();
  for (const auto& [key, cost] : o.limit_cost)
    r.binding_limits.push_back({key, LimitValue(s, key), Finite(cost, "limit cost"),
                                ObjectiveUnit(s) + " per " + LimitUnit(key),
                                MakeLimitSlopeResult(o.limit_slope.count(key) ? &o.limit_slope.at(key) : nullptr)});
  // Counts only: the time split (values, gradients, verification) goes to the terminal, so that two
  // runs write identical files.
  Result::Optimizer& opt = r.optimizer;
  opt.Set(s.backend, o.converged, o.result, s.options.solver.max_evaluations, s.options.verify_rounds, o.evaluations,
          o.gradient_evaluations);
  opt.starts = s.options.starts;
  opt.binding_rows = o.result.active;
  opt.start_outcomes.clear();
  for (const optimizers::SolverResult& st : o.starts) opt.start_outcomes.push_back(StartOf(st));
  r.analysis.grid = {s.spec.options.profile_cells, s.spec.options.axial_cells};
  r.analysis.crank_angles_per_mesh_period = s.spec.angles_per_period;
  r.analysis.tolerance = s.spec.options.tolerance;
  r.analysis.accurate = AccurateSettings(s);
  if (!r.blocking_message.empty()) r.notes = std::vector<std::string>{r.blocking_message};
}

// A design (drive and crowning) of this sizing as a complete cycloid_ltca study: the accurate
// settings, the design torque, the life's and the output mechanism's blocks of the study.
nlohmann::json CycloidLtcaStudyOf(const Study& s, const cycloid::Drive& design, const cycloid::Crowning& crowning,
                                  const std::string& prefix) {
  nlohmann::json a;
  a["study"] = "cycloid_ltca";
  a["name"] = prefix + (s.name.empty() ? std::string("cycloid_min_size") : s.name);
  nlohmann::json drive = DriveJson(design);
  if (s.bore_diameter_mm > 0) drive["bore_diameter_mm"] = s.bore_diameter_mm;
  a["drive"] = drive;
  a["modification"] = ModificationJson(design);
  a["crowning"] = WriteJson(cycloid_common::CrowningInputOf(crowning));
  a["material"] = {{"youngs_modulus_GPa", s.spec.material.youngs_modulus_MPa / 1000.0},
                   {"poisson_ratio", s.spec.material.poisson_ratio}};
  a["load"] = {{"torque_Nm", s.design_torque_Nm}};
  a["analysis"] = AccurateAnalysisJson(s);
  if (s.spec.life) {  // the same lives through cycloid_ltca (docs/life.md)
    const sizing::CycloidSizingLife& life = *s.spec.life;
    a["duty_cycle"] = DutyCycleJson(life.lines);
    nlohmann::json cb = {{"kind", life.crank_kind == BearingKind::kBall ? "ball" : "roller"},
                         {"dynamic_rating_N", life.crank_dynamic_N}};
    if (life.crank_static_N > 0) cb["static_rating_N"] = life.crank_static_N;
    a["crank_bearing"] = cb;
    if (life.pins_rated) {
      nlohmann::json pj = {{"dynamic_rating_N", life.pins_dynamic_N}};
      if (life.pins_static_N > 0) pj["static_rating_N"] = life.pins_static_N;
      a["pins"] = pj;
    }
    nlohmann::json om = {{"pin_circle_radius_mm", life.output.pin_circle_radius_mm}};
    if (life.output.pin_count > 0) om["pin_count"] = life.output.pin_count;
    a["output_mechanism"] = om;
  }
  if (s.torsional_dynamics) a["torsional_dynamics"] = WriteJson(*s.torsional_dynamics);
  if (s.ratings)  // cycloid_ltca solves the design's ratings (docs/ratings.md)
    a["ratings"] = {{"rated_life_h", s.ratings->rated_life_h},
                    {"rated_output_speed_rpm", s.ratings->rated_output_speed_rpm},
                    {"momentary_static_safety", s.ratings->momentary_static_safety}};
  if (s.spec.output) {  // the compliant output mechanism and the datasheet at the design torque
    const sizing::CycloidSizingOutput& out = *s.spec.output;
    nlohmann::json om = {{"pins", out.pins.pins},
                         {"pin_circle_radius_mm", out.pins.pin_circle_radius_mm},
                         {"pin_radius_mm", out.pins.pin_radius_mm},
                         {"hole_radius_mm", out.pins.contact_radius_mm() + design.eccentricity_mm + out.clearance_mm}};
    if (out.pins.roller_radius_mm > 0) om["roller_radius_mm"] = out.pins.roller_radius_mm;
    om["pin_support"] = out.support == cycloid::PinSupport::kBothEnds ? "both_ends" : "cantilever";
    if (out.span_mm > 0) om["pin_span_mm"] = out.span_mm;
    a["output_mechanism"] = om;
    a["stiffness"] = {{"rated_torque_Nm", s.design_torque_Nm}};
  }
  if (s.spec.lubrication) {  // the lubricated losses at the same speed (cycloid_ltca takes one speed, no duty cycle)
    s.lubrication_blocks.WriteTo(a);
    a["load"]["input_speed_rpm"] = s.spec.lubrication->input_speed_rpm;
    a.erase("duty_cycle");
    if (!a.contains("output_mechanism")) {
      const cycloid::OutputMechanism& m = s.spec.lubrication->mechanism;
      a["output_mechanism"] = {{"pin_circle_radius_mm", m.pin_circle_radius_mm}};
      if (m.pin_count > 0) a["output_mechanism"]["pin_count"] = m.pin_count;
    }
  }
  // The limits the design was sized for that cycloid_ltca's verdict checks, so that a re-run checks
  // them again (the others — stiffness, lost motion, backlash, edge margin, life — are in the
  // sizing's result.json verification).
  const CycloidSizingLimits& lim = s.spec.limits;
  nlohmann::json limits = nlohmann::json::object();
  if (std::isfinite(lim.contact_stress_MPa)) limits["contact_stress_MPa"] = lim.contact_stress_MPa;
  if (lim.min_profile_radius_mm > 0) limits["min_profile_radius_mm"] = lim.min_profile_radius_mm;
  if (lim.min_pin_gap_mm > 0) limits["min_pin_gap_mm"] = lim.min_pin_gap_mm;
  if (s.spec.output && std::isfinite(lim.output_pin_stress_MPa))
    limits["output_pin_stress_MPa"] = lim.output_pin_stress_MPa;
  if (s.spec.output && std::isfinite(lim.eccentric_bearing_load_N))
    limits["eccentric_bearing_load_N"] = lim.eccentric_bearing_load_N;
  if (s.spec.lubrication && lim.min_efficiency > 0) limits["min_efficiency"] = lim.min_efficiency;
  if (s.spec.lubrication && std::isfinite(lim.max_oil_temperature_C))
    limits["max_oil_temperature_C"] = lim.max_oil_temperature_C;
  if (!limits.empty()) a["limits"] = limits;
  return a;
}

}  // namespace

namespace {

// sized_disc.svg: the sized disc's modified profile (model/cycloid/tooth_profile.h, eqs. 3–4) and
// its pins at crank angle 0 over the start design's, dashed grey, with the main dimensions of both.
void AddSizedDiscDrawing(const Study& s, const cycloid::Drive& sized, Outputs& out) {
  const cycloid::Drive& start = s.spec.drive;
  auto layers = [](const cycloid::Drive& d, const std::string& prefix, const std::string& colour, double width,
                   const std::string& dash) {
    Drawing::Layer disc{prefix + "disc profile", colour, {}, {}, true, width, dash};
    Drawing::Layer pins{prefix + "pins", colour == "black" ? "#1f77b4" : colour, {}, {}, true, width, dash};
    Polyline pl;
    const int samples = 40 * d.teeth;
    for (int k = 0; k < samples; ++k) {
      const auto p = cycloid::ToothProfile<double>(d, 2.0 * kPi * k / samples).point;
      pl.emplace_back(p.x(), p.y());
    }
    disc.polylines.push_back(pl);
    for (int i = 0; i < d.rollers; ++i) {
      const auto c = cycloid::RollerCentreInDisc<double>(d, i, 0.0, 0.0);
      pins.circles.push_back({c.x(), c.y(), d.roller_radius_mm});
    }
    return std::vector<Drawing::Layer>{disc, pins};
  };
  Drawing d;
  d.title = s.name + ": the sized disc and pins over the start design";
  for (const auto& l : layers(start, "start design: ", "#999999", 0.8, "6,4")) d.layers.push_back(l);
  for (const auto& l : layers(sized, "sized: ", "black", 1.2, "")) d.layers.push_back(l);
  auto line = [](const char* what, double a, double b) {
    return std::string(what) + ": start " + Format(a, 5) + " mm, sized " + Format(b, 5) + " mm";
  };
  d.dimensions = {line("pin circle diameter", 2 * start.roller_position_radius_mm, 2 * sized.roller_position_radius_mm),
                  line("pin diameter", 2 * start.roller_radius_mm, 2 * sized.roller_radius_mm),
                  line("eccentricity", start.eccentricity_mm, sized.eccentricity_mm),
                  line("face width", start.face_width_mm, sized.face_width_mm)};
  out.Add("sized_disc.svg", SvgDrawing(d));
}

}  // namespace

nlohmann::json BestCycloidLtcaStudy(const Study& s, const Result& r) {
  const sizing::CycloidMinSizeOutcome& o = r.outcome;
  if (o.x.empty()) return nullptr;
  return CycloidLtcaStudyOf(s, o.drive, o.crowning,
                            o.verified && o.converged ? "best of "
                            : o.verified     ? "verified design (not proven the smallest) of "
                                             : "closest design (not verified) of ");
}

nlohmann::json StartCycloidLtcaStudy(const Study& s) {
  return CycloidLtcaStudyOf(s, s.spec.drive, s.spec.crowning, "start of ");
}

void Write(const Study& s, const Result& r, Outputs& out) {
  out.SetResult(r);
  const sizing::CycloidMinSizeOutcome& o = r.outcome;
  out.SetStatus(SizingStatus(!o.x.empty(), o.verification.ran, o.verified, o.converged), r.blocking_message);
  // A stress limit on a tooth whose edge peak is singular is checked on a number that grows as the
  // cells shrink: its "verified" would hold only at the grid it was checked on.
  if (IsVerified(*out.status()) && std::isfinite(s.spec.limits.contact_stress_MPa) &&
      cycloid::EdgePeakIsSingular(s.spec.crowning.type))
    out.SetStatus(Status::kNotVerifiable,
                  "the contact stress limit is checked on the edge peak of a " +
                      std::string(s.spec.crowning.type == cycloid::CrowningType::kNone ? "straight" : "partially crowned") +
                      " tooth, which does not converge as the cells shrink (it grows at the face ends); crown the "
                      "teeth (crowning.type \"logarithmic\" or \"full\") and keep the contact off the face ends "
                      "(limits.min_edge_margin_um with an overload torque)");
  if (r.outcome.x.empty()) return;
  out.AddJson("best_cycloid_ltca.json", BestCycloidLtcaStudy(s, r));
  AddSizedDiscDrawing(s, r.outcome.drive, out);
  const cycloid::CycleResult& c = r.best_cycle;
  if (c.meshes.empty()) return;
  Table t;
  std::vector<double> angle, stress, pairs, lte;
  for (size_t k = 0; k < c.meshes.size(); ++k) {
    angle.push_back(r.best_cycle_angles_rad[k] * 180.0 / kPi);
    stress.push_back(c.meshes[k].max_pressure_MPa);
    pairs.push_back(c.meshes[k].pairs_in_contact);
    lte.push_back(c.lte_arcsec.at(k));
  }
  t.Add("crank_angle_deg", angle);
  t.Add("max_contact_stress_MPa", stress);
  t.Add("pairs_in_contact", pairs);
  t.Add("lte_arcsec", lte);
  out.Add("stress_over_cycle.csv", ToCsv(t));
  PlotOptions po;
  po.title = "Peak contact stress of the best design over one mesh period (design torque, accurate settings)";
  po.x_label = "crank angle [deg]";
  po.y_label = "peak contact stress [MPa]";
  po.guides = {{"contact_stress_MPa limit", s.spec.limits.contact_stress_MPa}};
  out.Add("stress_over_cycle.svg", SvgLinePlot({{"largest over the rollers", angle, stress}}, po));
  const cycloid::MeshLoad& worst = c.meshes[c.max_pressure_index];
  out.Add("pressure_map.svg",
          cycloid_common::PressureMapsSvg(worst, "Contact pressure of the best design at crank angle " +
                                                     Format(worst.crank_angle_rad * 180 / kPi, 4) + " deg"));
}

std::string Summary(const Study& s, const Result& r) {
  const sizing::CycloidMinSizeOutcome& o = r.outcome;
  std::ostringstream m;
  char buf[300];
  if (!o.x.empty()) {
    std::snprintf(buf, sizeof buf, "cycloid_min_size: %s outer diameter %.3f mm (%d teeth), %.2f s\n",
                  o.verified && o.converged ? "best" : o.verified ? "verified (not proven the smallest)" : "closest (not verified)",
                  2 * (o.drive.roller_position_radius_mm + o.drive.roller_radius_mm), s.spec.drive.teeth, r.seconds);
    m << buf;
  }
  std::snprintf(buf, sizeof buf,
                "cycloid_min_size: %d LTCA value runs (%.2f s), %d gradient runs (%.2f s), verification %.2f s\n",
                o.evaluations, o.value_seconds, o.gradient_evaluations, o.gradient_seconds, o.verification_seconds);
  m << buf;
  for (const auto& [key, cost] : o.limit_cost) {
    std::snprintf(buf, sizeof buf, "cycloid_min_size: %s binds: %+.4g %s per %s\n", key.c_str(), cost,
                  ObjectiveUnit(s).c_str(), LimitUnit(key).c_str());
    m << buf;
  }
  return m.str();
}

namespace {

// The declared input of a study, for the knobs and the estimate below, which run before Parse.
Input ReadInput(const nlohmann::json& study, const std::string& file) { return Read<Input>(Node(&study, file, "")); }

// Fidelity for `camopt run --convergence` (studies/convergence.h): the fast model's crank angles
// and contact grid (the accurate check follows them at twice each) and the optimizer's budget.
Fidelity Knobs(const nlohmann::json&) {
  const Input defaults;
  const cycloid::LoadedOptions grid;
  Fidelity f;
  f.knobs.push_back({"crank_angles_per_mesh_period", {"/analysis/crank_angles_per_mesh_period"},
                     defaults.analysis.crank_angles_per_mesh_period, 2, true, 0,
                     "uniform crank angles per mesh period (fast model)"});
  f.knobs.push_back({"grid", {"/analysis/grid"}, {grid.profile_cells, grid.axial_cells}, 2, true, 0,
                     "contact cells across the profile and along the face (fast model)"});
  f.knobs.push_back({"max_evaluations", {"/optimizer/max_evaluations"}, defaults.optimizer.max_evaluations, 2, true, 0,
                     "optimizer budget per solve (Ipopt: iterations; SLSQP: evaluations)"});
  f.headlines = {"/best/outer_diameter_mm", "/best/accurate/max_contact_stress_MPa"};
  return f;
}

// The work limit (studies/work_limits.h). Every solve (the starts, then one per tightening round
// of the verified-optimum loop) may use its whole budget, each iteration about two value runs of
// both cycles (the line search) and a gradient (about 0.65 value runs per variable, as in
// cycloid_crowning_tuning); each round's accurate check runs both cycles on twice the angles and
// four times the cells, and the fast ones beside them; the stress plot one more accurate design
// cycle. Measured on the examples (16 × 16 cells, 4 angles): 4.5e6 (16 pins) to 9e6 (30 pins) of
// these units a second, and the solves use a fifth of their budget or less; the cap is about a
// minute of the full budget.
WorkEstimate EstimateWork(const nlohmann::json& study, const std::string& file, double factor) {
  const Input in = ReadInput(study, file);
  const Input::Target& t = in.target;
  const double teeth = t.teeth ? double(*t.teeth) : t.speed_ratio ? std::abs(*t.speed_ratio) : 15;
  const double rollers = std::isfinite(teeth) ? teeth + 1 : 16;
  const std::array<int, 2> grid = in.analysis.grid.value_or(cycloid_common::DefaultGrid());
  const double cells = double(grid[0]) * grid[1];
  const double angles = in.analysis.crank_angles_per_mesh_period;
  // The compliant output mechanism adds the torsional curve: two one-angle cycles (T_r/2, 0.03 T_r).
  const bool torsion = in.output_mechanism && in.output_mechanism->pin_radius_mm;
  const double torques = (t.overload_torque_Nm ? 2 : 1) + (torsion ? 2.0 / angles : 0.0);
  // The variables that vary (a range or {"range": ...}); a fixed number costs nothing.
  double variables = 0;
  for (const auto& v : study.at("variables")) variables += v.is_array() || v.is_object() ? 1 : 0;
  const double starts = in.optimizer.starts, rounds = in.optimizer.verify_rounds;
  const double budget = in.optimizer.max_evaluations;
  const double cycle = angles * rollers * cells;
  const double solves = budget * (starts + rounds) * (2 + 0.65 * variables) * torques * cycle;
  const double checks = (1 + rounds) * (1 + 2 * 4) * torques * cycle + 2 * 4 * cycle;
  return LargestTerm({{solves, "/optimizer/max_evaluations",
                       WorkNumber(budget) + " iterations × " + WorkNumber(starts + rounds) + " solves × (2 + 0.65 × " +
                           WorkNumber(variables) + " variables) × " + WorkNumber(torques) +
                           (torsion ? " torques (with the torsional curve's two one-angle cycles) × " : " torques × ") +
                           WorkNumber(angles) + " crank angles × " + WorkNumber(rollers) + " rollers × " +
                           WorkNumber(cells) + " grid cells"},
                      {checks, "/analysis/grid",
                       "verification: " + WorkNumber(1 + rounds) +
                           " accurate checks on twice the angles and four times the cells"}},
                     5e8 * factor, "contact cell solves", 1);
}

// The studio's start design: the study's start as a cycloid_ltca study.
nlohmann::json StartStudy(const Node& root, const nlohmann::json&) { return StartCycloidLtcaStudy(Parse(root)); }

CAMOPT_REGISTER_KIND(Kind<Input, Result, Study>{
    .name = "cycloid_min_size",
    .title = "camopt study: the smallest cycloid drive for a ratio and a torque",
    .run = Run, .parse = Parse, .write = Write, .summary = Summary, .knobs = Knobs, .estimate = EstimateWork,
    .report = std::vector<Headline>{
        // "outer diameter", not "smallest": the objective may be the volume or the lubricated loss.
        {"outer diameter", "/best/outer_diameter_mm", "mm"},
        {"teeth (disc) / pins", "/target/teeth", ""},
        {"pin circle radius", "/best/drive/roller_position_radius_mm", "mm"},
        {"pin radius", "/best/drive/roller_radius_mm", "mm"},
        {"eccentricity", "/best/drive/eccentricity_mm", "mm"},
        {"face width", "/best/drive/face_width_mm", "mm"},
        {"peak contact stress (accurate model)", "/best/accurate/max_contact_stress_MPa", "MPa",
         "study:/limits/contact_stress_MPa", NAN, true, "/best/estimated_error/max_contact_stress_MPa"},
        {"edge margin at the overload torque", "/best/accurate/edge_margin_at_overload_um", "um",
         "study:/limits/min_edge_margin_um", 0.0, false, "/best/estimated_error/edge_margin_at_overload_um"},
        {"smallest backlash", "/best/accurate/backlash_min_arcsec", "arcsec", "study:/limits/min_backlash_arcsec", 0.0,
         false, "/best/estimated_error/backlash_arcsec"},
        {"largest backlash", "/best/accurate/backlash_max_arcsec", "arcsec", "study:/limits/max_backlash_arcsec", NAN,
         true, "/best/estimated_error/backlash_arcsec"},
        {"loaded transmission error, peak to peak", "/best/accurate/lte_peak_to_peak_arcsec", "arcsec",
         "study:/limits/max_lte_peak_to_peak_arcsec", NAN, true, "/best/estimated_error/lte_peak_to_peak_arcsec"},
        {"torsional stiffness (50-100% of the design torque, crank 0)", "/best/accurate/torsional_stiffness_Nm_per_arcmin",
         "N m/arcmin", "study:/limits/min_torsional_stiffness_Nm_per_arcmin", NAN, false,
         "/best/estimated_error/torsional_stiffness_Nm_per_arcmin"},
        {"lost motion (±3% of the design torque)", "/best/accurate/lost_motion_arcmin", "arcmin",
         "study:/limits/max_lost_motion_arcmin", NAN, true, "/best/estimated_error/lost_motion_arcmin"},
        {"output-pin bending stress", "/best/accurate/output_pin_bending_stress_MPa", "MPa",
         "study:/limits/output_pin_stress_MPa", NAN, true, "/best/estimated_error/output_pin_bending_stress_MPa"},
        {"eccentric bearing load, largest", "/best/accurate/eccentric_bearing_load_N", "N",
         "study:/limits/eccentric_bearing_load_N", NAN, true, "/best/estimated_error/eccentric_bearing_load_N"},
        {"efficiency (lubricated, design torque)", "/best/accurate/efficiency", "", "study:/limits/min_efficiency", NAN,
         false, "/best/estimated_error/efficiency"},
        {"oil temperature", "/best/accurate/oil_temperature_C", "°C", "study:/limits/max_oil_temperature_C", NAN, true,
         "/best/estimated_error/oil_temperature_C"},
        {"lubricated loss", "/best/accurate/power_loss_W", "W"},
        {"shortest bearing life L10h (accurate model)", "/best/life/shortest_L10h", "h", "study:/limits/life_h", NAN,
         false, "/best/estimated_error/shortest_L10h"},
        {"bearing life L10h at the rated torque and speed", "/best/ratings/L10h_at_required_torque", "h",
         "study:/ratings/rated_life_h", NAN, false, "/best/estimated_error/shortest_L10h"},
        {"static safety s0 at the momentary torque (accurate model)", "/best/ratings/s0_at_required_momentary_torque", "",
         "/best/ratings/momentary_static_safety", NAN, false, "/best/estimated_error/min_static_safety"},
        {"curtate margin", "/best/curtate_margin", "", "study:/limits/min_curtate_margin", 0.05, false},
        {"smallest tooth radius", "/best/min_profile_radius_mm", "mm", "study:/limits/min_profile_radius_mm", 0.0, false},
        {"verified", "/verified", ""},
    },
    .asked = std::vector<AskedBlock>{
        {{"/duty_cycle", "/load/input_speed_rpm"}, "/best/life", "the sized design's bearing lives"},
        {{"/lubricant"}, "/best/accurate/efficiency", "the sized design's lubricated losses",
         {}, "/best/accurate/lubrication_error"},
    },
    .init_example = "cycloid_min_size_quick",
    .sizing_of = "cycloid_ltca",
    .start_study = StartStudy});
}  // namespace

}  // namespace camopt::studies::cycloid_min_size
