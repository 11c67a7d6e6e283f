// "geometry_files": false (docs/studies.md "Geometry files"): every kind that writes geometry
// files writes none of them (no DXF, STEP or STL), and result.json says so with
// "geometry_files": {"written": false}; the same study with the block absent does write them (so
// that the first check can fail). A value that is neither an object nor a boolean is bad input.
#include <iterator>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "studies/cycloid_ltca_study.h"
#include "studies/disc_cam_study.h"
#include "studies/globoidal_cam_study.h"
#include "studies/lcr_analysis_study.h"
#include "tests/test_util.h"

namespace camopt {
namespace geometry_files_switch_test {

using camopt::testing::Example;
using nlohmann::json;

// The CAD files among a run's outputs.
int CadFiles(const studies::Outputs& out) {
  int n = 0;
  for (const auto& [name, content] : out.files()) {
    const size_t dot = name.rfind('.');
    const std::string ext = dot == std::string::npos ? "" : name.substr(dot);
    n += ext == ".dxf" || ext == ".step" || ext == ".stl";
  }
  return n;
}

// One study kind's entry points (studies/<kind>_study.h).
template <typename Study, typename Result>
struct Kind {
  Study (*parse)(const studies::Node&);
  Result (*run)(const Study&, const studies::RunContext&);
  void (*write)(const Study&, const Result&, studies::Outputs&);
};
template <typename Study, typename Result>
Kind(Study (*)(const studies::Node&), Result (*)(const Study&, const studies::RunContext&),
     void (*)(const Study&, const Result&, studies::Outputs&)) -> Kind<Study, Result>;

#define CAMOPT_KIND(ns) Kind{&studies::ns::Parse, &studies::ns::Run, &studies::ns::Write}

// Parses, runs and writes `study`; returns the outputs and the result.json they hold.
template <typename K>
std::pair<studies::Outputs, json> RunKind(const K& kind, const json& study) {
  const studies::Node root(&study, "study.json", "");
  const auto st = kind.parse(root);
  const auto res = kind.run(st, {"study.json", true});
  studies::Outputs out;
  kind.write(st, res, out);
  if (!out.result()) throw std::logic_error("the kind's Write handed no result to Outputs::SetResult");
  return {out, *out.result()};
}

// As given: `cad_files` geometry files; with "geometry_files": false: none, every other file the
// same, and result.json says so.
template <typename K>
void ExpectSwitchedOff(const K& kind, json study, int cad_files, int other_files = 0) {
  const auto [on, on_json] = RunKind(kind, study);
  EXPECT_EQ(CadFiles(on), cad_files);
  // The planar kinds list their parts; globoidal_cam names its files under "surface_export".
  if (on_json.contains("geometry_files")) {
    EXPECT_FALSE(on_json.at("geometry_files").contains("written"));
  }
  study["geometry_files"] = false;
  const auto [off, off_json] = RunKind(kind, study);
  EXPECT_EQ(CadFiles(off), 0);
  EXPECT_EQ(off_json["geometry_files"], json({{"written", false}}));
  EXPECT_EQ(off.files().size() + cad_files + other_files, on.files().size());
  for (const auto& [name, content] : off.files()) EXPECT_TRUE(on.files().count(name)) << name;
}

TEST(GeometryFilesSwitch, LcrAnalysisWritesNoCadFiles) {
  json study = Example("lcr_ii.json");
  study["analysis"]["evaluate"] = {"profile"};
  study["geometry_files"] = {{"step", false}};  // the STEP solids are slow; the switch is what is tested
  ExpectSwitchedOff(CAMOPT_KIND(lcr_analysis), study, 2 * 2);  // input_cam and output_cam .dxf, .stl
}

TEST(GeometryFilesSwitch, CycloidLtcaWritesNoCadFiles) {
  json study = Example("cycloid_ltca_nnm_lcm.json");
  study["analysis"] = {{"crank_angles_deg", {0}}, {"grid", {8, 8}}, {"estimate_error", false}};
  // tooth.dxf, .step, .stl; the parts disc_1, ring_pins and housing .dxf, .step, .stl (the study has no
  // output mechanism or bore: no pins or crank), assembly.step; and bom.csv.
  ExpectSwitchedOff(CAMOPT_KIND(cycloid_ltca), study, 3 + 3 * 3 + 1, 1);
}

TEST(GeometryFilesSwitch, TrueIsTheDefaults) {
  json study = Example("cycloid_ltca_nnm_lcm.json");
  study["analysis"] = {{"crank_angles_deg", {0}}, {"grid", {8, 8}}, {"estimate_error", false}};
  study["geometry_files"] = {{"step", false}};
  const auto [given, given_json] = RunKind(CAMOPT_KIND(cycloid_ltca), study);
  study["geometry_files"] = true;
  const auto [on, on_json] = RunKind(CAMOPT_KIND(cycloid_ltca), study);
  EXPECT_EQ(CadFiles(on), 3 + 3 * 3 + 1);
  EXPECT_EQ(on_json["geometry_files"]["tooth"]["step"], "tooth.step");
  EXPECT_EQ(on_json["parts"]["assembly"], "assembly.step");
  EXPECT_EQ(on.files().at("tooth.dxf"), given.files().at("tooth.dxf"));
}

TEST(GeometryFilesSwitch, DiscCamWritesNoCadFiles) {
  json study = Example("disc_cam_translating.json");
  study["analysis"] = {{"angle_steps", 360}, {"evaluate", {"profile"}}};
  ASSERT_TRUE(study.contains("cam_thickness_mm"));
  ExpectSwitchedOff(CAMOPT_KIND(disc_cam), study, 3);  // profile.dxf, .step, .stl
}

TEST(GeometryFilesSwitch, GloboidalCamWritesNoSurfaceFiles) {
  json study = Example("globoidal_cam_paper.json");
  study["analysis"]["evaluate"] = {"geometry", "export"};
  study["export"]["angle_steps"] = 36;
  study["export"]["axis_steps"] = 2;
  ASSERT_EQ(study["export"]["stl"], true);  // false overrides an explicit export.stl
  ExpectSwitchedOff(CAMOPT_KIND(globoidal_cam), study, 2);  // working_surfaces.stl, .step
  study["geometry_files"] = false;
  const json j = RunKind(CAMOPT_KIND(globoidal_cam), study).second;
  EXPECT_EQ(j.at("surface_export").at("stl"), "");
  EXPECT_EQ(j.at("surface_export").at("step"), "");
  EXPECT_EQ(j.at("surface_export").at("point_cloud"), "working_surfaces.csv");
}

TEST(GeometryFilesSwitch, BadValueIsAnInputError) {
  const json bad_values[] = {json("no"), json(0), json::array({false})};
  for (size_t i = 0; i < std::size(bad_values); ++i) {
    json study = Example("cycloid_ltca_nnm_lcm.json");
    study["geometry_files"] = bad_values[i];
    camopt::testing::ExpectStudyRejected(study, "geometry-files-" + std::to_string(i), "/geometry_files",
                                         "expected true, false or an object");
  }
}

}  // namespace geometry_files_switch_test
}  // namespace camopt
