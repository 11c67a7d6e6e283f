// Parsing and output helpers shared by the cycloid study kinds (cycloid_ltca,
// cycloid_crowning_tuning, cycloid_min_size): the shared parse of drive, modification, material, crowning and grid,
// and the pressure-map drawing. Header-only; each kind is its own <kind>_study.h/.cc.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include "model/cycloid/bearing_loads.h"
#include "model/cycloid/crowning.h"
#include "model/cycloid/loaded_tca.h"
#include "model/cycloid/output_mechanism.h"
#include "model/cycloid/tooth_profile.h"
#include "studies/archive.h"
#include "studies/bearing_life_io.h"
#include "studies/cycloid_input.h"
#include "studies/design_issue_paths.h"
#include "studies/format.h"
#include "studies/input.h"
#include "studies/material_input.h"

namespace camopt::studies::cycloid_common {

// Plausibility against the drive's own scale (before any work). Real drives have a shortening
// coefficient K1 = e·N/R_p of 0.5–0.9 and pins filling 30–80% of their half pitch R_p·sin(π/N);
// profile modifications are corrections of micrometres. Far outside these the input is a unit or
// typing mistake, and the profile's features fall below what the geometry files can resolve
// (a pin circle of 2^31 mm with a 4.5 mm eccentricity; a Δa of 1e9 µm, a disc 2 km wide).
constexpr double kMinShortening = 0.05;      // K1
constexpr double kMinPinToHalfPitch = 0.02;  // r_p / (R_p sin(π/N))

inline void CheckPlausible(const Node& root, const cycloid::Drive& drive) {
  const Node d = root["drive"];
  const double rp = drive.roller_radius_mm, R = drive.roller_position_radius_mm, e = drive.eccentricity_mm;
  const int n = drive.rollers;
  if (root.Has("modification")) {
    const Node m = root["modification"];
    if (std::abs(drive.delta_position_mm) >= rp)
      m["delta_position_um"].FailWith("a profile modification of " + Format(drive.delta_position_mm * 1e3, 6) +
                                      " um is not below the pin radius " + Format(rp * 1e3, 6) +
                                      " um: modifications are corrections of micrometres (the field is in um)");
    if (std::abs(drive.delta_radius_mm) >= rp)
      m["delta_radius_um"].FailWith("a profile modification of " + Format(drive.delta_radius_mm * 1e3, 6) +
                                    " um is not below the pin radius " + Format(rp * 1e3, 6) +
                                    " um: modifications are corrections of micrometres (the field is in um)");
  }
  const double k1 = e * n / R;
  if (k1 < kMinShortening)
    d["eccentricity_mm"].FailWith("the shortening coefficient e * rollers / roller_position_radius_mm = " +
                                  Format(k1, 4) + " is below " + Format(kMinShortening, 3) +
                                  " (real drives: 0.5-0.9): the teeth vanish; with these rollers an "
                                  "eccentricity of at least " + Format(kMinShortening * R / n, 4) +
                                  " mm, or a pin circle of at most " + Format(e * n / kMinShortening, 4) +
                                  " mm, would fit");
  const double half_pitch = R * std::sin(kPi / n);
  if (rp < kMinPinToHalfPitch * half_pitch)
    d["roller_radius_mm"].FailWith("the pin radius " + Format(rp, 4) + " mm is below " +
                                   Format(100 * kMinPinToHalfPitch, 3) + "% of the half pitch " +
                                   Format(half_pitch, 4) + " mm (real drives: 30-80%): at least " +
                                   Format(kMinPinToHalfPitch * half_pitch, 4) + " mm would fit");
  // Last (a pin circle off by a unit explains a width that looks off against it): the disc's width
  // against the pin circle, the 1e-6…1e6 of every length of a study (a width of 1e308 mm made the
  // loads per unit width infinite, 5e-324 mm every crowning absurd).
  PlausibleLength(d["face_width_mm"], R, "the pin circle radius");
}

/// The drive of the declared "drive" and "modification" (µm) of a study at `root`, checked: a
/// one-tooth difference, a plausible drive (CheckPlausible), a feasible one (cycloid::CheckDrive).
inline cycloid::Drive MakeDrive(const Node& root, const DriveInput& in, const std::optional<ModificationInput>& mod) {
  const Node d = root["drive"];
  cycloid::Drive drive;
  drive.teeth = in.teeth;
  drive.rollers = in.rollers;
  if (drive.rollers != drive.teeth + 1) d["rollers"].Fail("teeth + 1 (a one-tooth-difference drive)");
  drive.roller_position_radius_mm = in.roller_position_radius_mm;
  drive.roller_radius_mm = in.roller_radius_mm;
  drive.eccentricity_mm = in.eccentricity_mm;
  drive.face_width_mm = in.face_width_mm;
  if (mod) {
    drive.delta_position_mm = mod->delta_position_um.value_or(0.0) * 1e-3;
    drive.delta_radius_mm = mod->delta_radius_um.value_or(0.0) * 1e-3;
  }
  CheckPlausible(root, drive);  // first: a unit mistake explains whatever else fails
  FailOnFirst(cycloid::CheckDrive(drive), root, CycloidIssuePaths());
  return drive;
}

/// "drive" and the optional "modification" (µm) of a study (read with their declarations).
inline cycloid::Drive ParseDrive(const Node& root) {
  std::optional<ModificationInput> mod;
  if (root.Has("modification")) mod = Read<ModificationInput>(root["modification"]);
  return MakeDrive(root, Read<DriveInput>(root["drive"]), mod);
}

inline cycloid::Material ParseMaterial(const Node& root) {
  const Node n = root["material"];
  n.CheckKnownFields({"youngs_modulus_GPa", "poisson_ratio"});
  return studies::ParseMaterial(n);
}

/// The crowning of the declared "crowning" at root (absent: none): the fields of its type, each
/// required one given (a missing one fails as missing), the others refused as unknown; checked
/// against the face width (cycloid::CheckCrowning).
inline cycloid::Crowning MakeCrowning(const Node& root, const std::optional<CrowningInput>& in, double face_width_mm) {
  cycloid::Crowning c;
  if (!in) return c;
  const Node n = root["crowning"];
  const auto required = [&](const std::optional<double>& v, const char* field) {
    if (!v) (void)n[field];  // "missing required field"
    return *v;
  };
  if (in->type == "none") {
    n.CheckKnownFields({"type"});
    c.type = cycloid::CrowningType::kNone;
  } else if (in->type == "full") {
    n.CheckKnownFields({"type", "radius_mm"});
    c.type = cycloid::CrowningType::kFull;
    c.radius_mm = required(in->radius_mm, "radius_mm");
  } else if (in->type == "partial") {
    n.CheckKnownFields({"type", "radius_mm", "flat_length_mm"});
    c.type = cycloid::CrowningType::kPartial;
    c.radius_mm = required(in->radius_mm, "radius_mm");
    c.flat_length_mm = required(in->flat_length_mm, "flat_length_mm");
  } else {  // "logarithmic" (the declaration allows no other)
    n.CheckKnownFields({"type", "coefficient_mm", "effective_length_mm", "end_drop_mm", "flat_length_mm"});
    c.type = cycloid::CrowningType::kLogarithmic;
    c.coefficient_mm = required(in->coefficient_mm, "coefficient_mm");
    c.effective_length_mm = in->effective_length_mm.value_or(0.0);
    c.end_drop_mm = in->end_drop_mm.value_or(0.0);
    c.flat_length_mm = in->flat_length_mm.value_or(0.0);
  }
  if (const std::string why = cycloid::CheckCrowning(c, face_width_mm); !why.empty())
    n.FailWith(why);
  return c;
}

/// "crowning" of a study that tunes or sizes some of its fields (declared by CrowningStartInput):
/// its type and the start (or fixed) values of its fields. A field named in `variables` may be
/// left out (it is 0 here; the variable sets it); a required field of the type (cycloid_ltca's)
/// that is neither given nor a variable is "missing". No "crowning": none. CheckCrowning is left to
/// the caller, which knows the values the variables take.
inline cycloid::Crowning MakeCrowningStart(const Node& root, const std::optional<CrowningStartInput>& in,
                                           const std::set<std::string>& variables) {
  cycloid::Crowning c;
  if (!in) return c;
  const Node n = root["crowning"];
  auto value = [&](const std::optional<double>& v, const char* field, bool required) {
    if (v) return *v;
    if (required && !variables.count(field)) n[field].NonNegative();  // "missing field"
    return 0.0;
  };
  if (in->type == "none") {
    n.CheckKnownFields({"type"});
  } else if (in->type == "full") {
    n.CheckKnownFields({"type", "radius_mm"});
    c.type = cycloid::CrowningType::kFull;
    c.radius_mm = value(in->radius_mm, "radius_mm", true);
  } else if (in->type == "partial") {
    n.CheckKnownFields({"type", "radius_mm", "flat_length_mm"});
    c.type = cycloid::CrowningType::kPartial;
    c.radius_mm = value(in->radius_mm, "radius_mm", true);
    c.flat_length_mm = value(in->flat_length_mm, "flat_length_mm", true);
  } else {  // "logarithmic" (the declaration allows no other)
    n.CheckKnownFields({"type", "coefficient_mm", "effective_length_mm", "end_drop_mm", "flat_length_mm"});
    c.type = cycloid::CrowningType::kLogarithmic;
    c.coefficient_mm = value(in->coefficient_mm, "coefficient_mm", true);
    c.effective_length_mm = value(in->effective_length_mm, "effective_length_mm", false);
    c.end_drop_mm = value(in->end_drop_mm, "end_drop_mm", false);
    c.flat_length_mm = value(in->flat_length_mm, "flat_length_mm", false);
  }
  return c;
}

/// MakeCrowningStart of the study's "crowning", read with its declaration.
inline cycloid::Crowning ParseCrowningStart(const Node& root, const std::set<std::string>& variables) {
  std::optional<CrowningStartInput> in;
  if (root.Has("crowning")) in = Read<CrowningStartInput>(root["crowning"]);
  return MakeCrowningStart(root, in, variables);
}

/// The file's word for a crowning type ("none", "full", "partial", "logarithmic").
inline const char* CrowningTypeName(cycloid::CrowningType type) {
  switch (type) {
    case cycloid::CrowningType::kFull: return "full";
    case cycloid::CrowningType::kPartial: return "partial";
    case cycloid::CrowningType::kLogarithmic: return "logarithmic";
    case cycloid::CrowningType::kNone: break;
  }
  return "none";
}

/// A crowning as the "crowning" object of a cycloid_ltca study declares it (CrowningInput: its
/// type and that type's fields; ParseCrowning reads it back), for result.json and the study files a
/// sizing writes.
inline CrowningInput CrowningInputOf(const cycloid::Crowning& c) {
  CrowningInput j;
  j.type = CrowningTypeName(c.type);
  switch (c.type) {
    case cycloid::CrowningType::kNone: break;
    case cycloid::CrowningType::kFull: j.radius_mm = c.radius_mm; break;
    case cycloid::CrowningType::kPartial: j.radius_mm = c.radius_mm, j.flat_length_mm = c.flat_length_mm; break;
    case cycloid::CrowningType::kLogarithmic:
      j.coefficient_mm = c.coefficient_mm, j.effective_length_mm = c.effective_length_mm;
      j.end_drop_mm = c.end_drop_mm, j.flat_length_mm = c.flat_length_mm;
      break;
  }
  return j;
}

/// "grid": [p, q] (profile cells, axial cells), default 40 × 40.
inline void ParseGrid(const Node& analysis, cycloid::LoadedOptions& o) {
  if (!analysis.Has("grid")) return;
  const Node g = analysis["grid"];
  const auto e = g.Elements();
  if (e.size() != 2) g.Fail("an array [profile_cells, axial_cells]");
  o.profile_cells = e[0].Integer(4);
  o.axial_cells = e[1].Integer(4);
  if (o.profile_cells > 512 || o.axial_cells > 512) g.Fail("at most 512 cells each way");
}

/// v with a fixed number of decimals (printf's %.Nf) for labels in drawings; studies::Format
/// (studies/format.h) gives significant digits.
inline std::string Fixed(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

/// An SVG heat map of the pressure of each contacting pair, side by side: x across the
/// profile (stretched to a readable width), y along the face width.
inline std::string PressureMapsSvg(const cycloid::MeshLoad& mesh, const std::string& title) {
  const int cell_w = 6, cell_h = 8;
  const int panel_gap = 30, top = 50, left = 20;
  double pmax = 0;
  for (const auto& p : mesh.pairs) pmax = std::max(pmax, p.max_pressure_MPa);
  int width = left;
  for (const auto& p : mesh.pairs) width += p.grid.nx * cell_w + panel_gap;
  width = std::max(width + 80, 400);
  int ny = 0;
  for (const auto& p : mesh.pairs) ny = std::max(ny, p.grid.ny);
  const int height = top + std::max(ny * cell_h, 100) + 70;
  std::ostringstream s;
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
    << "\" font-family=\"sans-serif\" font-size=\"11\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  s << "<text x=\"" << left << "\" y=\"20\" font-size=\"14\">" << title << "</text>\n";
  s << "<text x=\"" << left << "\" y=\"38\">max " << Fixed(pmax, 0)
    << " MPa; x across the profile (stretched), y along the face width</text>\n";
  auto colour = [&](double p) {
    if (p <= 0 || pmax <= 0) return std::string("#f4f4f4");
    // "Jet": blue → cyan → green → yellow → red from 0 to the maximum.
    const double t = std::clamp(p / pmax, 0.0, 1.0);
    const double r = std::clamp(std::min(4.0 * t - 1.5, -4.0 * t + 4.5), 0.0, 1.0);
    const double g = std::clamp(std::min(4.0 * t - 0.5, -4.0 * t + 3.5), 0.0, 1.0);
    const double b = std::clamp(std::min(4.0 * t + 0.5, -4.0 * t + 2.5), 0.0, 1.0);
    char buf[16];
    std::snprintf(buf, sizeof buf, "#%02x%02x%02x", int(255 * r), int(255 * g), int(255 * b));
    return std::string(buf);
  };
  int x0 = left;
  for (const auto& p : mesh.pairs) {
    for (int iy = 0; iy < p.grid.ny; ++iy)
      for (int ix = 0; ix < p.grid.nx; ++ix) {
        const double v = p.pressure_MPa.empty() ? 0.0 : p.pressure_MPa[size_t(iy) * p.grid.nx + ix];
        s << "<rect x=\"" << x0 + ix * cell_w << "\" y=\"" << top + (p.grid.ny - 1 - iy) * cell_h
          << "\" width=\"" << cell_w << "\" height=\"" << cell_h << "\" fill=\"" << colour(v) << "\"/>\n";
      }
    s << "<text x=\"" << x0 << "\" y=\"" << top + p.grid.ny * cell_h + 16 << "\">roller "
      << p.roller + 1 << ": " << Fixed(p.load_N, 0) << " N, " << Fixed(p.max_pressure_MPa, 0)
      << " MPa</text>\n";
    s << "<text x=\"" << x0 << "\" y=\"" << top + p.grid.ny * cell_h + 30 << "\">"
      << Fixed(2 * p.grid.nx * p.grid.dx * 0.5, 3) << " x " << Fixed(p.grid.ny * p.grid.dy, 1)
      << " mm</text>\n";
    x0 += p.grid.nx * cell_w + panel_gap;
  }
  // Colour bar with its unit, right of the panels: 0 (bottom) to the maximum (top).
  const int bar_x = width - 70, bar_h = std::max(ny * cell_h, 100), steps = 50;
  for (int k = 0; k < steps; ++k) {
    const double p = pmax * (k + 0.5) / steps;
    s << "<rect x=\"" << bar_x << "\" y=\"" << Fixed(top + bar_h * (steps - 1 - k) / double(steps), 2)
      << "\" width=\"14\" height=\"" << Fixed(bar_h / double(steps) + 0.3, 2) << "\" fill=\"" << colour(p)
      << "\"/>\n";
  }
  s << "<rect x=\"" << bar_x << "\" y=\"" << top << "\" width=\"14\" height=\"" << bar_h
    << "\" fill=\"none\" stroke=\"black\" stroke-width=\"0.5\"/>\n";
  for (int k = 0; k <= 4; ++k)
    s << "<text x=\"" << bar_x + 18 << "\" y=\"" << Fixed(top + bar_h * (1 - k / 4.0) + 4, 2) << "\">"
      << Fixed(pmax * k / 4, 0) << "</text>\n";
  s << "<text x=\"" << bar_x << "\" y=\"" << top - 16 << "\">p [MPa]</text>\n";
  s << "</svg>\n";
  return s.str();
}

/// The bearing life of a cycloid study (docs/life.md, "Cycloid"): the duty cycle, the crank
/// bearing's and (optionally) the ring pins' ratings, and the output mechanism.
struct LifeSpec {
  std::vector<OperatingLine> lines;
  RollingBearingRating crank_bearing;
  bool pins_rated = false;
  RollingBearingRating pins;  ///< per ring pin (a roller on a needle or roller sleeve), p = 10/3
  cycloid::OutputMechanism output;
  /// "lubricant.contamination_factor" e_C: given when a rated bearing has C_u and D_pw (a_ISO).
  std::optional<double> contamination_factor;
};

/// The fields of cycloid_ltca's "output_mechanism" beyond the life's (the compliant pins and holes;
/// studies/cycloid_ltca_study.cc reads them).
inline const std::set<std::string>& OutputMechanismFields() {
  static const std::set<std::string> f = {"pins", "pin_radius_mm", "hole_radius_mm", "roller_radius_mm",
                                          "pin_support", "pin_span_mm"};
  return f;
}

/// "output_mechanism": {"pin_circle_radius_mm" > 0 (inside the disc's root radius), "pin_count"
/// >= 3 (optional: the continuous limit without it)}. `extended` (cycloid_ltca): the fields of
/// OutputMechanismFields are known too, and "pins" is the pin count ("pin_count" its older name;
/// not both).
inline cycloid::OutputMechanism ParseOutputMechanism(const Node& n, const cycloid::Drive& d, bool extended = false) {
  std::set<std::string> known = {"pin_count", "pin_circle_radius_mm"};
  if (extended) known.insert(OutputMechanismFields().begin(), OutputMechanismFields().end());
  n.CheckKnownFields(known);
  cycloid::OutputMechanism m;
  if (extended && n.Has("pins") && n.Has("pin_count"))
    n["pin_count"].FailWith("give the pin count once: \"pins\" (\"pin_count\" is its older name)");
  const char* count = extended && n.Has("pins") ? "pins" : "pin_count";
  m.pin_count = n.Has(count) ? n[count].Integer(3) : 0;
  m.pin_circle_radius_mm = n["pin_circle_radius_mm"].Positive();
  const double root_radius = d.roller_position_radius_mm + d.delta_position_mm - d.eccentricity_mm -
                             d.roller_radius_mm - d.delta_radius_mm;
  if (!(m.pin_circle_radius_mm < root_radius))
    n["pin_circle_radius_mm"].Fail("a pin circle inside the disc's root radius " + Format(root_radius, 6) + " mm");
  return m;
}

/// The output mechanism with clearance and compliance (model/cycloid/output_mechanism.h): the
/// "output_mechanism" object with pin_radius_mm and hole_radius_mm; the face width and E* of
/// `pins` are filled from the drive and the material by the model that uses it.
struct CompliantOutputSpec {
  cycloid::OutputPins pins;
  cycloid::PinSupport support = cycloid::PinSupport::kCantilever;
  double span_mm = 0;  ///< the pin's span (cantilever: flange to free end)
};

/// Reads the compliant fields of "output_mechanism" `n` (declared by CompliantOutputMechanismInput,
/// read as `om`; `rigid` its pin count and circle from ParseOutputMechanism): the pin and hole
/// radii, a roller, the support and the span. Checked: the hole takes the pin's orbit at the
/// eccentricity `e_mm` (the largest the study may have), the holes inside the root circle of `d`
/// and apart, the span >= `stack_mm` (`stack_words` says what it is; the span's default).
/// @throws StudyError naming the field and what would fit.
inline CompliantOutputSpec ParseCompliantOutputPins(const Node& n, const CompliantOutputMechanismInput& om,
                                                    const cycloid::OutputMechanism& rigid, const cycloid::Drive& d,
                                                    double e_mm, double stack_mm, const std::string& stack_words) {
  CompliantOutputSpec o;
  o.pins.pins = rigid.pin_count;
  o.pins.pin_circle_radius_mm = rigid.pin_circle_radius_mm;
  if (!om.pin_radius_mm) (void)n["pin_radius_mm"];  // "missing required field"
  if (!om.hole_radius_mm) (void)n["hole_radius_mm"];
  o.pins.pin_radius_mm = *om.pin_radius_mm;
  o.pins.hole_radius_mm = *om.hole_radius_mm;
  o.pins.roller_radius_mm = om.roller_radius_mm.value_or(0.0);
  if (om.roller_radius_mm && !(o.pins.roller_radius_mm > o.pins.pin_radius_mm))
    n["roller_radius_mm"].Fail("a roller radius > pin_radius_mm " + Format(o.pins.pin_radius_mm, 6) + " mm");
  const double e = e_mm, rc = o.pins.contact_radius_mm();
  const std::string what = om.roller_radius_mm ? "roller_radius_mm" : "pin_radius_mm";
  if (!(o.pins.hole_radius_mm >= rc + e))
    n["hole_radius_mm"].Fail("a hole radius >= " + what + " + e = " + Format(rc, 6) + " + " + Format(e, 6) + " = " +
                             Format(rc + e, 6) + " mm (the pin must follow the disc's orbit of radius e); a " +
                             what + " of at most " + Format(o.pins.hole_radius_mm - e, 6) + " mm would fit this hole");
  // Neighbouring holes must not overlap, and the holes must stay inside the disc's root circle.
  const double root_radius = d.roller_position_radius_mm + d.delta_position_mm - d.eccentricity_mm -
                             d.roller_radius_mm - d.delta_radius_mm;
  if (!(o.pins.pin_circle_radius_mm + o.pins.hole_radius_mm < root_radius))
    n["hole_radius_mm"].Fail("holes inside the disc's root circle: pin_circle_radius_mm + hole_radius_mm < " +
                             Format(root_radius, 6) + " mm; a hole radius below " +
                             Format(root_radius - o.pins.pin_circle_radius_mm, 6) + " mm would fit");
  const double chord = 2.0 * o.pins.pin_circle_radius_mm * std::sin(kPi / o.pins.pins);
  if (!(2.0 * o.pins.hole_radius_mm < chord))
    n["hole_radius_mm"].Fail("holes that do not overlap: 2 hole_radius_mm < " + Format(chord, 6) +
                             " mm (the holes' pitch); a hole radius below " + Format(0.5 * chord, 6) + " mm would fit");
  o.support = om.pin_support.value_or("cantilever") == "both_ends" ? cycloid::PinSupport::kBothEnds
                                                                     : cycloid::PinSupport::kCantilever;
  o.span_mm = om.pin_span_mm.value_or(stack_mm);
  if (o.span_mm < stack_mm) n["pin_span_mm"].Fail("a span >= " + stack_words + " = " + Format(stack_mm, 6) + " mm");
  return o;
}

/// "output_mechanism" with clearance and compliance when it gives the pins' or the holes' radius
/// (then ParseCompliantOutputPins, the pin count required), else nullopt (and the compliant-only
/// fields refused). `root` the study's root.
inline std::optional<CompliantOutputSpec> ParseCompliantOutput(const Node& root,
                                                               const std::optional<CompliantOutputMechanismInput>& om,
                                                               const cycloid::Drive& d, double e_mm, double stack_mm,
                                                               const std::string& stack_words) {
  const bool compliant = om && (om->pin_radius_mm || om->hole_radius_mm);
  if (!compliant) {
    if (om) {
      const Node n = root["output_mechanism"];
      for (const char* f : {"roller_radius_mm", "pin_support", "pin_span_mm"})
        if (n.Has(f)) n[f].FailWith(std::string(f) + " needs the pins' and holes' radii (pin_radius_mm, hole_radius_mm)");
    }
    return std::nullopt;
  }
  const Node n = root["output_mechanism"];
  const cycloid::OutputMechanism rigid = ParseOutputMechanism(n, d, true);
  if (rigid.pin_count == 0) n["pins"].Integer(3);  // "missing field": the compliant model counts its pins
  return ParseCompliantOutputPins(n, *om, rigid, d, e_mm, stack_mm, stack_words);
}

template <typename InputT>
LifeSpec ParseLifeRatings(const Node& root, const InputT& in, const cycloid::Drive& d, const std::string& why,
                          bool extended_output);

/// The life fields of a cycloid study `in` (its declared "duty_cycle", "crank_bearing", "pins"):
/// "load.input_speed_rpm" or "duty_cycle" (ParseDutyCycle, the one-line form at `torque_Nmm`),
/// "crank_bearing" (required with a life), "pins" (optional), "output_mechanism" (required with a
/// life: the crank bearing's load needs R_w). Without a speed or a duty cycle the ratings are still
/// checked and nullopt is returned. The kinds that report a_ISO declare the rating blocks with C_u
/// and D_pw (BearingRatingInput<true>), which need lubricant.contamination_factor
/// (CheckModifiedLifeInputs).
/// @throws StudyError naming the JSON path.
template <typename InputT>
std::optional<LifeSpec> ParseLife(const Node& root, const InputT& in, const cycloid::Drive& d, double torque_Nmm,
                                  bool extended_output = false) {
  constexpr bool kModifiedLife = std::is_same_v<std::remove_cvref_t<decltype(in.pins)>, std::optional<BearingRatingInput<true>>>;
  if constexpr (kModifiedLife) {
    std::vector<Node> rated;
    auto given = [](const auto& block) { return block && (block->fatigue_load_limit_N || block->pitch_diameter_mm); };
    if (given(in.crank_bearing)) rated.push_back(root["crank_bearing"]);
    if (given(in.pins)) rated.push_back(root["pins"]);
    for (const Node& node : rated) ParseModifiedLifeRating(node);
    CheckModifiedLifeInputs(root, rated);
  }
  std::string why;
  std::optional<std::vector<OperatingLine>> lines = ParseDutyCycle(root, in.duty_cycle, torque_Nmm, &why);
  if (!lines) {
    const std::string unused = "checked: no speed or duty cycle is given, so no life is computed";
    if (in.crank_bearing) (void)RatingOf(*in.crank_bearing, root["crank_bearing"], unused);
    if (in.pins) (void)RatingOf(*in.pins, root["pins"], BearingKind::kRoller, unused);
    if (root.Has("output_mechanism")) ParseOutputMechanism(root["output_mechanism"], d, extended_output);
    return std::nullopt;
  }
  LifeSpec life = ParseLifeRatings(root, in, d, why, extended_output);
  life.lines = std::move(*lines);
  return life;
}

/// The rated elements of ParseLife without the duty cycle (lines empty): "crank_bearing" (required),
/// "pins" (optional), "output_mechanism" (required); `why` says what needs them.
template <typename InputT>
LifeSpec ParseLifeRatings(const Node& root, const InputT& in, const cycloid::Drive& d, const std::string& why,
                          bool extended_output) {
  LifeSpec life;
  auto missing = [&](const std::string& key, const std::string& expected) {
    const std::string path = (root.path() == "/" ? std::string() : root.path()) + "/" + key;
    throw StudyError(root.file() + ": " + path + ": expected " + expected + ", found nothing", root.file(), path,
                     expected, "nothing");
  };
  if (!in.crank_bearing)
    missing("crank_bearing", "{\"kind\": \"ball\" | \"roller\", \"dynamic_rating_N\", \"static_rating_N\"} (" +
                                 why + ")");
  life.crank_bearing = RatingOf(*in.crank_bearing, root["crank_bearing"], why);
  if (in.pins) {
    life.pins_rated = true;
    life.pins = RatingOf(*in.pins, root["pins"], BearingKind::kRoller, why);
  }
  if (life.crank_bearing.modified || (life.pins_rated && life.pins.modified))
    life.contamination_factor = root["lubricant"]["contamination_factor"].Number();  // CheckModifiedLifeInputs
  if (!root.Has("output_mechanism"))
    missing("output_mechanism", "{\"pin_circle_radius_mm\", \"pin_count\"} (" + why +
                                    ": the crank bearing's load depends on the output pins' circle)");
  life.output = ParseOutputMechanism(root["output_mechanism"], d, extended_output);
  return life;
}

}  // namespace camopt::studies::cycloid_common
