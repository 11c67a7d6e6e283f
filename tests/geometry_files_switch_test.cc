// "geometry_files": false (docs/studies.md "Geometry files"): every kind that writes geometry
// files writes none of them (no DXF, STEP or STL), and result.json says so with
// "geometry_files": {"written": false}; the same study with the block absent does write them (so
// that the first check can fail). A value that is neither an object nor a boolean is bad input.
#include <iterator>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "studies/cycloid_ltca_study.h"
#include "studies/disc_cam_study.h"
#include "studies/globoidal_cam_study.h"
#include "studies/lcr_analysis_study.h"
#include "tests/test_util.h"

namespace camopt {
namespace {

using camopt::testing::ReadFile;
using camopt::testing::SourcePath;
using nlohmann::json;

json Example(const std::string& name) { return json::parse(ReadFile(SourcePath("studies/examples/" + name))); }

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

// Parses, runs and writes `study` of kind K; returns the outputs and result.json.
template <typename Kind>
std::pair<studies::Outputs, json> RunKind(const json& study) {
  const studies::Node root(&study, "study.json", "");
  const auto st = Kind::Parse(root);
  const auto res = Kind::Run(st, {"study.json", true});
  studies::Outputs out;
  Kind::Write(st, res, out);
  return {out, Kind::ToJson(st, res)};
}

struct LcrAnalysis {
  static auto Parse(const studies::Node& n) { return studies::lcr_analysis::Parse(n); }
  static auto Run(const studies::lcr_analysis::Study& s, const studies::RunContext& c) {
    return studies::lcr_analysis::Run(s, c);
  }
  static void Write(const studies::lcr_analysis::Study& s, const studies::lcr_analysis::Result& r,
                    studies::Outputs& o) {
    studies::lcr_analysis::Write(s, r, o);
  }
  static json ToJson(const studies::lcr_analysis::Study& s, const studies::lcr_analysis::Result& r) {
    return studies::lcr_analysis::ToJson(s, r);
  }
};
struct CycloidLtca {
  static auto Parse(const studies::Node& n) { return studies::cycloid_ltca::Parse(n); }
  static auto Run(const studies::cycloid_ltca::Study& s, const studies::RunContext& c) {
    return studies::cycloid_ltca::Run(s, c);
  }
  static void Write(const studies::cycloid_ltca::Study& s, const studies::cycloid_ltca::Result& r,
                    studies::Outputs& o) {
    studies::cycloid_ltca::Write(s, r, o);
  }
  static json ToJson(const studies::cycloid_ltca::Study& s, const studies::cycloid_ltca::Result& r) {
    return studies::cycloid_ltca::ToJson(s, r);
  }
};
struct DiscCam {
  static auto Parse(const studies::Node& n) { return studies::disc_cam::Parse(n); }
  static auto Run(const studies::disc_cam::Study& s, const studies::RunContext& c) {
    return studies::disc_cam::Run(s, c);
  }
  static void Write(const studies::disc_cam::Study& s, const studies::disc_cam::Result& r, studies::Outputs& o) {
    studies::disc_cam::Write(s, r, o);
  }
  static json ToJson(const studies::disc_cam::Study& s, const studies::disc_cam::Result& r) {
    return studies::disc_cam::ToJson(s, r);
  }
};
struct GloboidalCam {
  static auto Parse(const studies::Node& n) { return studies::globoidal_cam::Parse(n); }
  static auto Run(const studies::globoidal_cam::Study& s, const studies::RunContext& c) {
    return studies::globoidal_cam::Run(s, c);
  }
  static void Write(const studies::globoidal_cam::Study& s, const studies::globoidal_cam::Result& r,
                    studies::Outputs& o) {
    studies::globoidal_cam::Write(s, r, o);
  }
  static json ToJson(const studies::globoidal_cam::Study& s, const studies::globoidal_cam::Result& r) {
    return studies::globoidal_cam::ToJson(s, r);
  }
};

// As given: `cad_files` geometry files; with "geometry_files": false: none, every other file the
// same, and result.json says so.
template <typename Kind>
void ExpectSwitchedOff(json study, int cad_files) {
  const auto [on, on_json] = RunKind<Kind>(study);
  EXPECT_EQ(CadFiles(on), cad_files);
  // The planar kinds list their parts; globoidal_cam names its files under "surface_export".
  if (on_json.contains("geometry_files")) {
    EXPECT_FALSE(on_json.at("geometry_files").contains("written"));
  }
  study["geometry_files"] = false;
  const auto [off, off_json] = RunKind<Kind>(study);
  EXPECT_EQ(CadFiles(off), 0);
  EXPECT_EQ(off_json["geometry_files"], json({{"written", false}}));
  EXPECT_EQ(off.files().size() + cad_files, on.files().size());
  for (const auto& [name, content] : off.files()) EXPECT_TRUE(on.files().count(name)) << name;
}

TEST(GeometryFilesSwitch, LcrAnalysisWritesNoCadFiles) {
  json study = Example("lcr_ii.json");
  study["analysis"]["evaluate"] = {"profile"};
  study["geometry_files"] = {{"step", false}};  // the STEP solids are slow; the switch is what is tested
  ExpectSwitchedOff<LcrAnalysis>(study, 2 * 2);  // input_cam and output_cam .dxf, .stl
}

TEST(GeometryFilesSwitch, CycloidLtcaWritesNoCadFiles) {
  json study = Example("cycloid_ltca_nnm_lcm.json");
  study["analysis"] = {{"crank_angles_deg", {0}}, {"grid", {8, 8}}, {"estimate_error", false}};
  ExpectSwitchedOff<CycloidLtca>(study, 3);  // tooth.dxf, .step, .stl
}

TEST(GeometryFilesSwitch, TrueIsTheDefaults) {
  json study = Example("cycloid_ltca_nnm_lcm.json");
  study["analysis"] = {{"crank_angles_deg", {0}}, {"grid", {8, 8}}, {"estimate_error", false}};
  study["geometry_files"] = {{"step", false}};
  const auto [given, given_json] = RunKind<CycloidLtca>(study);
  study["geometry_files"] = true;
  const auto [on, on_json] = RunKind<CycloidLtca>(study);
  EXPECT_EQ(CadFiles(on), 3);
  EXPECT_EQ(on_json["geometry_files"]["tooth"]["step"], "tooth.step");
  EXPECT_EQ(on.files().at("tooth.dxf"), given.files().at("tooth.dxf"));
}

TEST(GeometryFilesSwitch, DiscCamWritesNoCadFiles) {
  json study = Example("disc_cam_translating.json");
  study["analysis"] = {{"angle_steps", 360}, {"evaluate", {"profile"}}};
  ASSERT_TRUE(study.contains("cam_thickness_mm"));
  ExpectSwitchedOff<DiscCam>(study, 3);  // profile.dxf, .step, .stl
}

TEST(GeometryFilesSwitch, GloboidalCamWritesNoSurfaceFiles) {
  json study = Example("globoidal_cam_paper.json");
  study["analysis"]["evaluate"] = {"geometry", "export"};
  study["export"]["angle_steps"] = 36;
  study["export"]["axis_steps"] = 2;
  ASSERT_EQ(study["export"]["stl"], true);  // false overrides an explicit export.stl
  ExpectSwitchedOff<GloboidalCam>(study, 2);  // working_surfaces.stl, .step
  study["geometry_files"] = false;
  const json j = RunKind<GloboidalCam>(study).second;
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
                                         "expected an object or a boolean");
  }
}

}  // namespace
}  // namespace camopt
