#include "studies/cycloid_parts.h"

#include <cmath>
#include <string>

#include "studies/format.h"

namespace camopt::studies::cycloid_common {

PartsSet CycloidParts(const CycloidPartsInput& in, const PlanarCamFit& tooth) {
  const cycloid::Drive& d = in.drive;
  PartsSet set;
  set.design_name = in.design_name;
  set.density_kg_m3 = in.density_kg_m3;
  set.assembly_crank_angle_rad = in.crank_angle_rad;
  const double rho_kg_mm3 = in.density_kg_m3 * 1e-9;
  const double B = d.face_width_mm;
  const double stack = (in.discs - 1) * in.disc_spacing_mm + B;
  const double phi = in.crank_angle_rad;
  const double output_angle = -phi / d.teeth;  // the discs and the output turn by −φ/n2
  auto circle_area = [](double r) { return kPi * r * r; };

  // The discs.
  std::vector<cad::Hole> holes;
  double holes_area = 0.0;
  if (in.pins) {
    for (int j = 0; j < in.pins->pins; ++j) {
      const double a = 2.0 * kPi * j / in.pins->pins;
      holes.push_back({in.pins->pin_circle_radius_mm * Vec2<double>(std::cos(a), std::sin(a)),
                       2.0 * in.pins->hole_radius_mm});
      holes_area += circle_area(in.pins->hole_radius_mm);
    }
  } else {
    set.notes.push_back("the discs are drawn without output-pin holes: output_mechanism has no pin_radius_mm and "
                        "hole_radius_mm (the compliant mechanism's radii size the holes)");
  }
  const double disc_area = tooth.profile_area_mm2 - circle_area(0.5 * in.bore_diameter_mm) - holes_area;
  for (int k = 1; k <= in.discs; ++k) {
    const double gamma = cycloid::DiscPhaseRotationRad(k, in.discs, d.teeth);
    Part p;
    p.name = "disc_" + std::to_string(k);
    p.description = "cycloid disc " + std::to_string(k) + " of " + std::to_string(in.discs) + ", phase " +
                    Format(360.0 * (k - 1) / in.discs, 6) + " deg about the crank, profile turned " +
                    Format(gamma * 180.0 / kPi + 0.0, 8) + " deg against its holes";
    p.material = in.material;
    p.solid.profile = RotatedChain(tooth.profile.arcs, gamma);
    if (tooth.spline) p.solid.profile_spline = cad::Rotated(*tooth.spline, gamma);
    p.solid.bore_diameter_mm = in.bore_diameter_mm;
    p.solid.holes = holes;
    p.solid.thickness_mm = B;
    if (!tooth.cutter.arcs.empty()) {
      p.cutter_path = RotatedChain(tooth.cutter.arcs, gamma);
      p.cutter_diameter_mm = 2.0 * (d.roller_radius_mm + d.delta_radius_mm);
    }
    p.volume_mm3 = disc_area * B;
    p.mass_kg = rho_kg_mm3 * p.volume_mm3;
    set.parts.push_back(p);
    // In the assembly: centre at e u(φ_k), turned with the output; z from the first disc's face.
    const double phi_k = phi + 2.0 * kPi * (k - 1) / in.discs;
    set.placements.push_back({p.name, set.parts.size() - 1,
                              Eigen::Vector3d(d.eccentricity_mm * std::cos(phi_k), d.eccentricity_mm * std::sin(phi_k),
                                              (k - 1) * in.disc_spacing_mm),
                              output_angle});
  }

  // The ring pins, over the discs' stack.
  {
    Part p;
    p.name = "ring_pins";
    p.description = "ring pin, diameter " + Format(2 * d.roller_radius_mm, 6) + " mm on the pin circle radius " +
                    Format(d.roller_position_radius_mm, 6) + " mm";
    p.material = in.material;
    p.count = d.rollers;
    p.designation = in.pin_designation;
    p.solid.profile = CircleChain(Vec2<double>::Zero(), d.roller_radius_mm);
    p.solid.thickness_mm = stack;
    p.volume_mm3 = circle_area(d.roller_radius_mm) * stack;
    p.mass_kg = rho_kg_mm3 * p.volume_mm3;
    set.parts.push_back(p);
    for (int i = 0; i < d.rollers; ++i) {
      const double psi = 2.0 * kPi * i / d.rollers;
      set.placements.push_back({"ring_pin " + std::to_string(i + 1), set.parts.size() - 1,
                                Eigen::Vector3d(d.roller_position_radius_mm * std::cos(psi),
                                                d.roller_position_radius_mm * std::sin(psi), 0.0),
                                0.0});
    }
  }
  // The housing's outline: a ring whose bore is the pins' outer tangent circle.
  {
    Part p;
    p.name = "housing";
    const double inner = d.roller_position_radius_mm + d.roller_radius_mm;
    const double outer = inner + 2.0 * d.roller_radius_mm;
    p.description = "ring-pin housing outline, bore " + Format(2 * inner, 6) + " mm, outside " + Format(2 * outer, 6) + " mm";
    p.note = "outline only: the pins' grooves, flanges and fixing holes are not drawn";
    p.material = in.material;
    p.solid.profile = CircleChain(Vec2<double>::Zero(), outer);
    p.solid.bore_diameter_mm = 2.0 * inner;
    p.solid.thickness_mm = stack;
    p.volume_mm3 = (circle_area(outer) - circle_area(inner)) * stack;
    p.mass_kg = rho_kg_mm3 * p.volume_mm3;
    set.parts.push_back(p);
    set.placements.push_back({"housing", set.parts.size() - 1, Eigen::Vector3d::Zero(), 0.0});
  }
  // The output pins (and their rollers), at R_w u(2πj/Z_w − φ/n2).
  if (in.pins) {
    const cycloid::OutputPins& o = *in.pins;
    Part p;
    p.name = "output_pins";
    p.description = "output pin, diameter " + Format(2 * o.pin_radius_mm, 6) + " mm on the circle radius " +
                    Format(o.pin_circle_radius_mm, 6) + " mm";
    p.material = in.material;
    p.count = o.pins;
    p.solid.profile = CircleChain(Vec2<double>::Zero(), o.pin_radius_mm);
    p.solid.thickness_mm = in.output_pin_length_mm;
    p.volume_mm3 = circle_area(o.pin_radius_mm) * in.output_pin_length_mm;
    p.mass_kg = rho_kg_mm3 * p.volume_mm3;
    set.parts.push_back(p);
    const size_t pin_part = set.parts.size() - 1;
    size_t roller_part = 0;
    if (o.roller_radius_mm > 0) {
      Part r;
      r.name = "output_pin_rollers";
      r.description = "roller on an output pin, outside " + Format(2 * o.roller_radius_mm, 6) + " mm, bore " +
                      Format(2 * o.pin_radius_mm, 6) + " mm, over the discs' stack";
      r.material = in.material;
      r.count = o.pins;
      r.solid.profile = CircleChain(Vec2<double>::Zero(), o.roller_radius_mm);
      r.solid.bore_diameter_mm = 2.0 * o.pin_radius_mm * (1.0 + 1e-6);  // a running fit, not a shared face
      r.solid.thickness_mm = stack;
      r.volume_mm3 = (circle_area(o.roller_radius_mm) - circle_area(0.5 * r.solid.bore_diameter_mm)) * stack;
      r.mass_kg = rho_kg_mm3 * r.volume_mm3;
      set.parts.push_back(r);
      roller_part = set.parts.size() - 1;
    }
    for (int j = 0; j < o.pins; ++j) {
      const double a = 2.0 * kPi * j / o.pins + output_angle;
      const Eigen::Vector3d at(o.pin_circle_radius_mm * std::cos(a), o.pin_circle_radius_mm * std::sin(a), 0.0);
      set.placements.push_back({"output_pin " + std::to_string(j + 1), pin_part, at, 0.0});
      if (o.roller_radius_mm > 0)
        set.placements.push_back({"output_pin_roller " + std::to_string(j + 1), roller_part, at, 0.0});
    }
  }
  // The crank: one eccentric per disc, its centre e from the crank's axis, filling the disc's bore.
  if (in.bore_diameter_mm > 0) {
    Part p;
    p.name = "crank";
    p.description = "crank eccentric, diameter " + Format(in.bore_diameter_mm, 6) + " mm, eccentricity " +
                    Format(d.eccentricity_mm, 6) + " mm (one per disc, each at its disc's phase)";
    p.note = "the eccentric is drawn at the discs' bore diameter: the crank bearing between them (its designation in "
             "this row) and the shaft are not drawn";
    p.material = in.material;
    p.designation = in.crank_bearing_designation;
    p.count = in.discs;
    // Slightly under the bore, so that the eccentric and the disc never share a face.
    const double r = 0.5 * in.bore_diameter_mm * (1.0 - 1e-6);
    p.solid.profile = CircleChain(Vec2<double>(d.eccentricity_mm, 0.0), r);
    p.solid.bore_centre = Vec2<double>::Zero();  // the crank's axis (no bore)
    p.solid.thickness_mm = B;
    p.volume_mm3 = circle_area(r) * B;
    p.mass_kg = rho_kg_mm3 * p.volume_mm3;
    set.parts.push_back(p);
    for (int k = 1; k <= in.discs; ++k) {
      const double phi_k = phi + 2.0 * kPi * (k - 1) / in.discs;
      set.placements.push_back({"crank eccentric " + std::to_string(k), set.parts.size() - 1,
                                Eigen::Vector3d(0.0, 0.0, (k - 1) * in.disc_spacing_mm), phi_k});
    }
  } else {
    set.notes.push_back("no crank: the discs have no bore (drive.bore_diameter_mm) for its eccentric");
  }
  return set;
}

}  // namespace camopt::studies::cycloid_common
