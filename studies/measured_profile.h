// The "inspection" and "measured_profile" blocks of the planar-profile analyses (cycloid_ltca,
// lcr_analysis, disc_cam; docs/studies.md, "Inspection points and measured parts"):
//
//   "inspection": {"spacing_mm": 0.5, "tolerance_um": 10}
//       inspection/<part>.csv per profile part: points of the exact profile at arc-length steps
//       <= spacing_mm, their outward normals, and the ISO 1101 profile-of-a-line zone ± t/2.
//   "measured_profile": {"part": "disc_1", "file": "points.csv", "kind": "points"}
//       a measured part back in (file relative to the study file): "points", measured x_mm,y_mm in
//       the part frame, each projected onto the exact profile; "normal_deviation", the inspection
//       CSV with a deviation_mm column (x_mm,y_mm the nominal point, nx,ny optional and checked).
//       result.json's "measured": the ISO 1101 deviation and the kind's headlines as measured.
//
// The geometry (projection, spline, zone) is model/common/profile_deviation.h; here the files.
#pragma once

#include <algorithm>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "model/common/profile_deviation.h"
#include "studies/archive.h"
#include "studies/input.h"

namespace camopt::studies {

/// "inspection" as declared (studies/archive.h).
struct InspectionInput {
  double spacing_mm = 1.0, tolerance_um = 10.0;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("spacing_mm", &spacing_mm,
             Field().Required().In(0.01, 100.0).Unit("mm").Desc(
                 "largest arc length between neighbouring inspection points along the exact profile"));
    a->Visit("tolerance_um", &tolerance_um,
             Field().Required().In(0.01, 10000.0).Unit("µm").Desc(
                 "ISO 1101 profile-of-a-line tolerance t: the zone ± t/2 along the normal of the exact profile"));
  }
};

/// "measured_profile" as declared; `Parts::Names()` the kind's part names.
template <typename Parts>
struct MeasuredProfileInputT {
  std::string part, file, kind;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("part", &part, Field().Required().OneOf(Parts::Names()).Desc(Parts::Description()));
    a->Visit("file", &file,
             Field().Required().Desc("the measurement, a CSV file relative to the study file (docs/studies.md, "
                                     "\"Inspection points and measured parts\")"));
    a->Visit("kind", &kind,
             Field().Required().OneOf({"points", "normal_deviation"}).Desc(
                 "\"points\": x_mm,y_mm measured in the part frame, projected onto the exact profile; "
                 "\"normal_deviation\": x_mm,y_mm on the nominal profile and deviation_mm along its outward normal"));
  }
  static std::vector<CrossFieldRule> CrossFieldRules() {
    return {{{"file"}, "the file exists beside the study and is a readable CSV of the kind",
             "expected a readable CSV file"}};
  }
};

/// One profile part as inspected: its name (the file stem), frame and datum in words, the exact
/// profile in the part frame.
struct InspectedPart {
  std::string name, frame, datum;
  profile::ClosedProfile profile;
};

/// inspection/PART.csv (header comment, then x_mm,y_mm,nx,ny,nominal_mm,upper_mm,lower_mm) and
/// the number of points.
std::string InspectionCsv(const std::string& design, const InspectedPart& part, double spacing_mm,
                          double tolerance_um, long* points);

/// A measured part read and projected onto its exact profile.
struct MeasuredProfile {
  std::string part, file, kind;  ///< as given (file: as resolved)
  std::vector<Vec2<double>> points;      ///< the measured points (kind points), or the nominal points
  std::vector<double> t, deviation_mm;   ///< profile parameter and signed normal deviation of each
  std::vector<double> arc_mm;            ///< arc length of each from the profile's start
  profile::ProfileZone zone;
  profile::PeriodicSpline shape;         ///< d(t), the periodic cubic spline through the points
  double largest_gap_mm = 0;             ///< largest arc between neighbouring points
};

/// Reads `node` ("measured_profile"), resolves its file relative to the study file, reads the CSV
/// and projects its points onto `part`'s profile. Points farther than min(1 mm, 10 % of the
/// profile's size) from it, an arc longer than `max_gap_mm` between neighbours (or fewer than 8
/// distinct points), a missing file or column, a number that is not finite: StudyError (exit 2)
/// naming the study file, the JSON path, the CSV file and line, what was expected and found.
MeasuredProfile ReadMeasuredProfile(const Node& node, const InspectedPart& part, double max_gap_mm);

/// Where a deviation extreme is: the measured point, its arc length along the exact profile and
/// its row in the measurement file.
struct DeviationAt {
  double x_mm = 0, y_mm = 0, arc_length_mm = 0;
  long row = 0;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("x_mm", &x_mm, Field().Unit("mm").Desc("in the part frame"));
    a->Visit("y_mm", &y_mm, Field().Unit("mm").Desc("in the part frame"));
    a->Visit("arc_length_mm", &arc_length_mm, Field().Unit("mm").Desc("from the exact profile's start"));
    a->Visit("row", &row, Field().Desc("the point's data row in the measurement file (1: the first)"));
  }
};

/// A headline of the nominal part beside the same headline as measured. `kNullable`: a number
/// that may be infinite (a Hertz stress on a profile that is not convex there, an unlimited life)
/// is written null; otherwise a number that is not finite stops the write (ResultWriter).
template <bool kNullable>
struct NominalMeasuredT {
  double nominal = 0, measured = 0;
  template <typename Archive>
  void Serialize(Archive* a) {
    const Field f = kNullable ? Field().NullWhenNotFinite() : Field();
    a->Visit("nominal", &nominal, Field(f).Desc(kNullable ? "the nominal part's (null: infinite)" : "the nominal part's"));
    a->Visit("measured", &measured, Field(f).Desc(kNullable ? "the measured part's (null: infinite)" : "the measured part's"));
  }
};
using NominalMeasured = NominalMeasuredT<false>;
using NominalMeasuredOrInfinite = NominalMeasuredT<true>;

/// The transmission error of the measured part over the angles evaluated (its output angle less
/// the nominal part's at the same drive angle): its peak-to-peak, largest and smallest value and
/// the note that defines it, flattened into the block that holds it (the keys
/// transmission_error_peak_to_peak_arcsec, _max_arcsec, _min_arcsec and transmission_error_note).
struct MeasuredTransmissionError {
  double transmission_error_peak_to_peak_arcsec = 0, transmission_error_max_arcsec = 0,
         transmission_error_min_arcsec = 0;
  std::string transmission_error_note;
  /// From the transmission error at each angle [rad] (not empty) and the kind's arcsec per radian.
  static MeasuredTransmissionError Of(const std::vector<double>& te_rad, double arcsec_per_rad, std::string note) {
    const auto [lo, hi] = std::minmax_element(te_rad.begin(), te_rad.end());
    return {(*hi - *lo) * arcsec_per_rad, *hi * arcsec_per_rad, *lo * arcsec_per_rad, std::move(note)};
  }
  /// `of_what`: the peak-to-peak's description (which output angle less which).
  template <typename Archive>
  void Serialize(Archive* a, const char* of_what) {
    a->Visit("transmission_error_peak_to_peak_arcsec", &transmission_error_peak_to_peak_arcsec,
             Field().Unit("arcsec").Desc(of_what));
    a->Visit("transmission_error_max_arcsec", &transmission_error_max_arcsec, Field().Unit("arcsec"));
    a->Visit("transmission_error_min_arcsec", &transmission_error_min_arcsec, Field().Unit("arcsec"));
    a->Visit("transmission_error_note", &transmission_error_note, Field().Desc("its definition and sign"));
  }
};

/// A result of the measured part that was not computed, and why.
struct NotComputedRow {
  std::string result, why;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("result", &result, Field().Desc("what is not computed"));
    a->Visit("why", &why, Field().Desc("why not"));
  }
};

/// result.json's "measured" without the kind's headlines: part, file, kind, points, the ISO 1101
/// deviation, the largest and smallest deviation and where, mean, RMS, the interpolation, and
/// what was not computed for the measured part. Each kind's block derives from it and visits its
/// own headlines after these (CycloidMeasured, LcrMeasured, DiscCamMeasured).
struct MeasuredBlock {
  std::string part, file, kind, frame;
  long points = 0;
  double profile_length_mm = 0, largest_gap_mm = 0, iso1101_profile_deviation_um = 0;
  std::string iso1101_note;
  double max_deviation_um = 0;
  DeviationAt max_deviation_at;
  double min_deviation_um = 0;
  DeviationAt min_deviation_at;
  double mean_deviation_um = 0, rms_deviation_um = 0;
  std::string deviation_sign, interpolation;
  std::vector<NotComputedRow> not_computed;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("part", &part, Field().Desc("measured_profile.part"));
    a->Visit("file", &file, Field().Desc("the measurement file's name"));
    a->Visit("kind", &kind, Field().OneOf({"points", "normal_deviation"}).Desc("measured_profile.kind"));
    a->Visit("frame", &frame, Field().Desc("the part frame the points are in"));
    a->Visit("points", &points, Field().Desc("the measured points"));
    a->Visit("profile_length_mm", &profile_length_mm, Field().Unit("mm").Desc("the exact profile's length"));
    a->Visit("largest_gap_mm", &largest_gap_mm,
             Field().Unit("mm").Desc("the largest arc between neighbouring points"));
    a->Visit("iso1101_profile_deviation_um", &iso1101_profile_deviation_um,
             Field().Unit("µm").Desc("ISO 1101 profile of a line: 2 max|d|"));
    a->Visit("iso1101_note", &iso1101_note, Field().Desc("the zone and its datum in words"));
    a->Visit("max_deviation_um", &max_deviation_um, Field().Unit("µm").Desc("the largest signed normal deviation d"));
    a->Visit("max_deviation_at", &max_deviation_at, Field().Desc("its point"));
    a->Visit("min_deviation_um", &min_deviation_um, Field().Unit("µm").Desc("the smallest signed normal deviation d"));
    a->Visit("min_deviation_at", &min_deviation_at, Field().Desc("its point"));
    a->Visit("mean_deviation_um", &mean_deviation_um, Field().Unit("µm").Desc("the points' mean d"));
    a->Visit("rms_deviation_um", &rms_deviation_um, Field().Unit("µm").Desc("the points' RMS d"));
    a->Visit("deviation_sign", &deviation_sign, Field().Desc("the sign convention of d"));
    a->Visit("interpolation", &interpolation, Field().Desc("how d(t) is interpolated between the points"));
    a->Visit("not_computed", &not_computed, Field().Desc("the results not computed for the measured part, and why"));
  }
};
/// The common part of "measured" (MeasuredBlock) for `m` on `part`.
MeasuredBlock MeasuredOf(const MeasuredProfile& m, const InspectedPart& part);

/// result.json's "inspection": spacing, tolerance and each part's file and point count, the datum
/// the files are measured from; without geometry files, why there are none.
struct InspectionBlock {
  struct File {
    std::string file;
    long points = 0;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("file", &file, Field().Desc("the part's inspection CSV"));
      a->Visit("points", &points, Field().Desc("its points"));
    }
  };
  double spacing_mm = 0, tolerance_um = 0;
  std::optional<bool> written;
  std::optional<std::string> why;
  std::optional<std::map<std::string, File>> parts;
  std::optional<std::string> datum;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("spacing_mm", &spacing_mm, Field().Unit("mm").Desc("inspection.spacing_mm"));
    a->Visit("tolerance_um", &tolerance_um, Field().Unit("µm").Desc("inspection.tolerance_um"));
    a->Visit("written", &written, Field().Desc("false: no geometry files, no inspection points"));
    a->Visit("why", &why, Field().Desc("with written false"));
    a->Visit("parts", &parts, Field().Desc("each inspected part by name"));
    a->Visit("datum", &datum, Field().Desc("what the files are measured from"));
  }
};
/// The block; `datum` is set when the files are written.
InspectionBlock InspectionOf(double spacing_mm, double tolerance_um,
                             const std::vector<std::pair<std::string, long>>& files, bool written,
                             const std::string& datum);

}  // namespace camopt::studies
