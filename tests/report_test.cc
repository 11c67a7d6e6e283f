// Plots that show the answer (limits, markers, error bars, marked points, legend above the data,
// numbered drawings) and report.html (headlines with limits and pass/fail, warnings, every plot
// inline, self-contained, deterministic). That the page renders in a browser is
// tests/report_render_test.py (ctest Report.renders_in_chromium).
#include <cstdio>
#include <regex>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "studies/report.h"
#include "studies/study.h"
#include "studies/writers.h"

namespace camopt::studies {
namespace report_test {

int Count(const std::string& text, const std::string& what) {
  int n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
  return n;
}

TEST(SvgLinePlot, LimitOutsideTheDataWidensTheAxisAndIsDrawnDashedInTheLegend) {
  PlotOptions o{"t", "x [mm]", "stress [MPa]"};
  o.guides = {{"stress limit", 2000.0}, {"no limit", INFINITY}};
  const std::string svg = SvgLinePlot({{"stress", {0, 1, 2}, {1000, 1200, 1100}}}, o);
  // The data ends at 1200; the axis reaches the limit: a tick label 2000 exists.
  EXPECT_NE(svg.find(">2000</text>"), std::string::npos);
  EXPECT_NE(svg.find("stress limit"), std::string::npos);
  EXPECT_EQ(svg.find("no limit"), std::string::npos);  // an infinite limit draws nothing
  EXPECT_EQ(Count(svg, "stroke-dasharray=\"6,3\""), 2);  // the line and its legend sample
}

TEST(SvgLinePlot, LegendSitsAboveThePlotArea) {
  const std::string svg = SvgLinePlot({{"a", {0, 1}, {0, 1}}, {"b", {0, 1}, {1, 0}}}, {"t", "x", "y"});
  // The frame is the rect with fill none; its top edge is below every legend text baseline.
  std::smatch frame;
  ASSERT_TRUE(std::regex_search(svg, frame, std::regex("<rect x=\"[0-9.]+\" y=\"([0-9.]+)\" width=\"[0-9.]+\" "
                                                       "height=\"[0-9.]+\" fill=\"none\"")));
  const double top = std::stod(frame[1]);
  for (const char* label : {">a</text>", ">b</text>"}) {
    const size_t at = svg.find(label);
    ASSERT_NE(at, std::string::npos);
    const size_t y = svg.rfind(" y=\"", at);
    EXPECT_LT(std::stod(svg.substr(y + 4)), top) << label;
  }
}

TEST(SvgLinePlot, SecondSeriesIsDashedSoThatItShowsOnTopOfAnEqualFirst) {
  const std::string svg =
      SvgLinePlot({{"first", {0, 1, 2}, {1, 2, 3}}, {"second", {0, 1, 2}, {1, 2, 3}}}, {"t", "x", "y"});
  EXPECT_EQ(Count(svg, "<path d=\" M"), 2);
  EXPECT_EQ(Count(svg, "stroke-dasharray=\"8,4\""), 2);  // the second series and its legend sample
}

TEST(SvgLinePlot, MeasuredPointsAsMarkersWithErrorBars) {
  Series measured{"measured", {1, 2, 3}, {10, 20, 30}, {1, 2, 3}, SeriesStyle::kMarkers};
  const std::string svg = SvgLinePlot({measured}, {"t", "x", "y"});
  EXPECT_EQ(Count(svg, "<circle"), 3 + 1);      // three markers and the legend sample
  EXPECT_EQ(Count(svg, "<path d=\"M"), 3);      // one error bar (with caps) per point
  EXPECT_EQ(Count(svg, "<path d=\" M"), 0);     // no line through the measurements
  EXPECT_NE(svg.find(">35</text>"), std::string::npos);  // 30 + 3 is inside the axis range
}

TEST(SvgLinePlot, MarkersFlagIsAScatterPlot) {
  Series cloud{"cases", {1, 2, 3}, {3, 1, 2}};
  cloud.markers = true;
  const std::string svg = SvgLinePlot({cloud}, {"t", "x", "y"});
  EXPECT_EQ(Count(svg, "<circle"), 3 + 1);   // three markers and the legend sample
  EXPECT_EQ(Count(svg, "<path d=\" M"), 0);  // no line
}

TEST(SvgLinePlot, MarkedPointIsLabelledOnThePlotAndInTheLegend) {
  PlotOptions o{"t", "x", "y"};
  o.points = {{"optimum", 2, 1}};
  const std::string svg = SvgLinePlot({{"curve", {0, 1, 2, 3}, {3, 2, 1, 2}}}, o);
  EXPECT_EQ(Count(svg, ">optimum</text>"), 2);
}

TEST(SvgLinePlot, SinglePointSeriesIsAMarker) {
  const std::string svg = SvgLinePlot({{"curve", {0, 1}, {0, 1}}, {"one", {0.5}, {0.5}}}, {"t", "x", "y"});
  // The frame, the second series' square marker and its legend sample.
  EXPECT_EQ(Count(svg, "<rect x="), 3);
  EXPECT_EQ(Count(svg, "<path d=\" M"), 1);  // only the first series is a line
}

TEST(SvgDrawing, LabelsAreDrawnOnTop) {
  Drawing d;
  d.title = "rollers";
  Drawing::Layer rollers{"ROLLERS", "blue", {}, {{0, 0, 1}, {5, 0, 1}}, true, 1.0};
  d.layers = {rollers};
  d.labels = {{0, 0, "1"}, {5, 0, "2"}};
  const std::string svg = SvgDrawing(d);
  const size_t last_circle = svg.rfind("<circle");
  EXPECT_GT(svg.find(">1</text>"), last_circle);
  EXPECT_GT(svg.find(">2</text>"), last_circle);
}

TEST(SvgDrawing, ScaleBarExtentAndMainDimensionsUnderTheDrawing) {
  // A 100 mm × 60 mm rectangle on the default 800 px canvas: 740 px for the larger span, so
  // 7.4 px per mm, and the round length nearest 100/5 mm is 20 mm: a bar of 148 px ending 30 px
  // from the right edge.
  Drawing d;
  d.title = "plate";
  Drawing::Layer plate{"PLATE", "black", {{{0, 0}, {100, 0}, {100, 60}, {0, 60}}}, {}, true, 1.0};
  d.layers = {plate};
  d.dimensions = {"width 100 mm", "height 60 mm"};
  const std::string svg = SvgDrawing(d);
  EXPECT_NE(svg.find("<path d=\"M622.00,837.00 L622.00,842.00 L770.00,842.00 L770.00,837.00\""), std::string::npos)
      << svg;
  EXPECT_NE(svg.find(">20 mm</text>"), std::string::npos);
  EXPECT_NE(svg.find(">extent 100.0 × 60.0 mm</text>"), std::string::npos);
  EXPECT_NE(svg.find(">width 100 mm</text>"), std::string::npos);
  EXPECT_NE(svg.find(">height 60 mm</text>"), std::string::npos);
  // The canvas grows by the footer: 800 + 30 (title) + 30 + 2 × 16.
  EXPECT_NE(svg.find("height=\"892\""), std::string::npos);
  // 3 mm wide: the bar is 0.5 mm (the round length nearest 0.6).
  d.layers[0].polylines = {{{0, 0}, {3, 0}, {3, 1}, {0, 1}}};
  EXPECT_NE(SvgDrawing(d).find(">0.5 mm</text>"), std::string::npos);
}

TEST(SvgLinePlot, ATitleLongerThanThePlotIsSqueezedToFitNotClipped) {
  PlotOptions o{"short", "x", "y"};
  const std::string short_title = SvgLinePlot({{"s", {0, 1}, {0, 1}}}, o);
  EXPECT_EQ(short_title.find("textLength"), std::string::npos);
  // 120 characters at ~8.3 px each is ~1000 px on an 800 px plot: squeezed to 780 px.
  o.title = std::string(120, 'W');
  const std::string long_title = SvgLinePlot({{"s", {0, 1}, {0, 1}}}, o);
  EXPECT_NE(long_title.find("textLength=\"780.00\" lengthAdjust=\"spacingAndGlyphs\">" + o.title), std::string::npos);
  // A drawing's title likewise, on its own canvas.
  Drawing d;
  d.title = o.title;
  EXPECT_NE(SvgDrawing(d, 600).find("textLength=\"580.00\""), std::string::npos);
}

TEST(SvgBarChart, BarsFromZeroToTheirValueWithTheLimitAndNotesUnder) {
  // Bars of 10 and 40 on an axis to 40 (ticks of 10): 550 px of plot from x = 210 on 800 px, so
  // the 10 bar is 137.5 px and the 40 bar 550 px; the 25 limit is a dashed line at 210 + 343.75.
  BarChartOptions o;
  o.title = "shares";
  o.x_label = "share [%]";
  o.guides = {{"limit", 25.0}};
  o.notes = {"first note", std::string(200, 'a') + " " + std::string(50, 'b')};
  const std::string svg = SvgBarChart({{"one", 10.0, "10 %"}, {"two", 40.0, "40 % of the chain", true}}, o);
  EXPECT_NE(svg.find("width=\"137.50\""), std::string::npos) << svg;
  EXPECT_NE(svg.find("width=\"550.00\" height=\"18.00\" fill=\"#d62728\""), std::string::npos);  // highlighted
  EXPECT_NE(svg.find("<line x1=\"553.75\" x2=\"553.75\""), std::string::npos);
  EXPECT_NE(svg.find(">limit</text>"), std::string::npos);
  EXPECT_NE(svg.find(">40</text>"), std::string::npos);  // the axis ends at a round 40
  // The 40 bar's text does not fit right of it: drawn inside, in white.
  EXPECT_NE(svg.find("text-anchor=\"end\" fill=\"white\">40 % of the chain"), std::string::npos);
  EXPECT_NE(svg.find(">first note</text>"), std::string::npos);
  // A note longer than the canvas is wrapped at its space: the 200 a's and the 50 b's on two lines.
  EXPECT_NE(svg.find(">" + std::string(200, 'a') + "</text>"), std::string::npos);
  EXPECT_NE(svg.find(">" + std::string(50, 'b') + "</text>"), std::string::npos);
}

Outputs SampleOutputs(double stress) {
  Outputs out;
  out.SetResultJson({{"max_stress_MPa", stress},
                              {"limit_MPa", 1500.0},
                              {"margin_mm", 0.2},
                              {"warnings", {"roller <b> is small"}},
                              {"status", "converged"}});
  PlotOptions o{"stress", "x [deg]", "stress [MPa]"};
  out.Add("a.svg", SvgLinePlot({{"s", {0, 1}, {1, 2}}}, o));
  out.Add("b.svg", SvgLinePlot({{"s", {0, 1}, {2, 1}}}, o));
  out.Add("c.csv", "x\n1\n");
  return out;
}

// A kind's report rows (KindDescriptor::report), given to HtmlReport and EvaluateHeadlines directly.
const std::vector<Headline> kTestHeadlines = {{"largest stress", "/max_stress_MPa", "MPa", "/limit_MPa"},
                                              {"margin", "/margin_mm", "mm", "study:/limits/margin_mm", 0.0, false},
                                              {"not in this result", "/absent", "N"},
                                              {"status", "/status", ""}};

TEST(HtmlReport, HeadlinesWithLimitsPassOrFail) {
  const nlohmann::json study = {{"study", "report_test_kind"}, {"name", "sample"}, {"limits", {{"margin_mm", 0.5}}}};
  const std::string html = HtmlReport("report_test_kind", &kTestHeadlines, study, SampleOutputs(1400));
  // 1400 ≤ 1500 passes; 0.2 ≥ 0.5 (the study's limit) fails.
  EXPECT_NE(html.find("1 of 2 limits exceeded"), std::string::npos);
  EXPECT_EQ(Count(html, ">pass</td>"), 1);
  EXPECT_EQ(Count(html, ">FAIL</td>"), 1);
  EXPECT_NE(html.find("≤ 1500 MPa"), std::string::npos);
  EXPECT_NE(html.find("0.2 mm</td><td class=\"n\">≥ 0.5 mm</td><td class=\"n\">-0.3 mm"), std::string::npos);
  EXPECT_NE(html.find("100 MPa"), std::string::npos);  // the stress margin
  EXPECT_EQ(html.find("not in this result"), std::string::npos);
  EXPECT_NE(html.find(">converged<"), std::string::npos);
  const std::string all_pass =
      HtmlReport("report_test_kind", &kTestHeadlines, {{"name", "sample"}}, SampleOutputs(1400));
  EXPECT_NE(all_pass.find("All 2 limits met"), std::string::npos);  // margin limit defaults to 0
}

TEST(HtmlReport, AValueBelowItsResolutionOrItsErrorIsShownAsZero) {
  static const std::vector<Headline> headlines = {{"offset", "/offset_mm", "mm", "", NAN, true, "", "", "", 1e-6},
                                                  {"tilt", "/tilt_deg", "deg", "", NAN, true, "/tilt_error_deg"},
                                                  {"length", "/length_mm", "mm", "", NAN, true, "", "", "", 1e-6}};
  const nlohmann::json result = {{"offset_mm", 1.31078e-10}, {"tilt_deg", 2e-7}, {"tilt_error_deg", 1e-5},
                                 {"length_mm", 12.5}};
  const HeadlineTable t = EvaluateHeadlines(&headlines, nlohmann::json::object(), result);
  ASSERT_EQ(t.rows.size(), 3u);
  EXPECT_EQ(t.rows[0].value, "0 mm");
  EXPECT_EQ(t.rows[1].value.rfind("0 ± ", 0), 0u) << t.rows[1].value;
  EXPECT_EQ(t.rows[2].value, "12.5 mm");
}

TEST(HtmlReport, LimitsMetWithALimitNotSetIsNotGreen) {
  static const std::vector<Headline> headlines = {
      {"largest stress", "/max_stress_MPa", "MPa", "study:/limits/contact_stress_MPa"},
      {"margin", "/margin_mm", "mm", "/limit_mm", NAN, false}};
  Outputs out;
  out.SetResultJson({{"max_stress_MPa", 7682.0}, {"margin_mm", 0.5}, {"limit_mm", 0.0}});
  // The study sets no stress limit: the one limit set is met, the stress is named as not checked,
  // and the banner is amber, not green.
  const std::string unset = HtmlReport("report_test_unset", &headlines, {{"name", "x"}}, out);
  EXPECT_NE(unset.find("<div class=\"verdict partial\">The limit is met; not checked, no limit set: largest stress"),
            std::string::npos)
      << unset;
  // With the stress limit set and met: green.
  const std::string all =
      HtmlReport("report_test_unset", &headlines, {{"name", "x"}, {"limits", {{"contact_stress_MPa", 8000}}}}, out);
  EXPECT_NE(all.find("<div class=\"verdict ok\">All 2 limits met"), std::string::npos) << all;
  // Set and exceeded: red.
  const std::string bad =
      HtmlReport("report_test_unset", &headlines, {{"name", "x"}, {"limits", {{"contact_stress_MPa", 1500}}}}, out);
  EXPECT_NE(bad.find("<div class=\"verdict bad\">1 of 2 limits exceeded: largest stress"), std::string::npos) << bad;
}

TEST(HtmlReport, WarningsEscapedEveryPlotInlineNothingExternal) {
  const std::string html = HtmlReport("report_test_kind", &kTestHeadlines, {{"name", "a <name>"}}, SampleOutputs(1600));
  EXPECT_NE(html.find("roller &lt;b&gt; is small"), std::string::npos);
  EXPECT_NE(html.find("a &lt;name&gt;"), std::string::npos);
  EXPECT_EQ(Count(html, "<svg "), 2);
  EXPECT_EQ(Count(html, "<figcaption>"), 2);
  EXPECT_EQ(html.find("<script"), std::string::npos);
  // Every src/href is a data: URI; the only URL is the SVG namespace name, which loads nothing.
  const std::regex ref("(src|href)=\"(?!data:)");
  EXPECT_FALSE(std::regex_search(html, ref));
}

TEST(HtmlReport, AnSvgWithoutViewBoxGetsOneSoThatThePageScalesItWithoutCropping) {
  Outputs out = SampleOutputs(1400);
  out.Add("map.svg", "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"1450\" height=\"440\"><rect/></svg>\n");
  const std::string html = HtmlReport("report_test_kind", &kTestHeadlines, {{"name", "n"}}, out);
  EXPECT_NE(html.find("<svg viewBox=\"0 0 1450 440\" xmlns="), std::string::npos);
  EXPECT_EQ(Count(html, "<figure class=\"wide\">"), 1);  // wider than a grid column: full width
}

TEST(HtmlReport, SameOutputsSamePage) {
  const nlohmann::json study = {{"name", "x"}, {"b", {1, 2}}, {"a", {{"c", "d"}}}};
  EXPECT_EQ(HtmlReport("report_test_kind", &kTestHeadlines, study, SampleOutputs(1400)),
            HtmlReport("report_test_kind", &kTestHeadlines, study, SampleOutputs(1400)));
}

TEST(HtmlReport, UnregisteredKindShowsTopLevelNumbers) {
  const std::string html = HtmlReport("no_such_kind_for_report", {{"name", "n"}}, SampleOutputs(1234.5));
  EXPECT_NE(html.find(">max_stress_MPa<"), std::string::npos);
  EXPECT_NE(html.find(">1234.5<"), std::string::npos);
  EXPECT_NE(html.find("No limits to check"), std::string::npos);
}

// A sizing result that found no design ("best": null) has limits, but nothing to check them on:
// the verdict says so with the result's reason, not "No limits to check".
TEST(HtmlReport, ASizingResultWithoutADesignSaysSoInsteadOfNoLimits) {
  Outputs out;
  out.SetResultJson({{"best", nullptr}, {"notes", {"edge-loaded: crown the rollers"}}});
  const HeadlineTable table = EvaluateHeadlines(&kTestHeadlines, {{"name", "n"}},
                                                *out.result());
  EXPECT_TRUE(table.no_design);
  EXPECT_EQ(VerdictOf(table, nlohmann::json::object()), "No design meets the limits: edge-loaded: crown the rollers");
  const std::string html = HtmlReport("report_test_kind", &kTestHeadlines, {{"name", "n"}}, out);
  EXPECT_NE(html.find("<div class=\"verdict bad\">No design meets the limits: edge-loaded"), std::string::npos);
  EXPECT_EQ(html.find("No limits to check"), std::string::npos);
  Outputs bare;
  bare.SetResultJson({{"best", nullptr}});
  EXPECT_EQ(VerdictOf(EvaluateHeadlines(&kTestHeadlines, {}, *bare.result()),
                      nlohmann::json::object()),
            "No design meets the limits (result.json: best is null)");
}

TEST(HtmlReport, EveryRunWritesOne) {
  const nlohmann::json study = nlohmann::json::parse(R"({"study": "transmission_rigidity", "name": "shaft",
    "material": {"shear_modulus_GPa": 80, "youngs_modulus_GPa": 206},
    "chain": [{"element": "shaft_torsion", "name": "s", "length_mm": 100, "outer_diameter_mm": 20,
               "inner_diameter_mm": 0}]})");
  const Outputs out = RunStudy(study, RunContext{});
  ASSERT_TRUE(out.files().count("report.html"));
  EXPECT_NE(out.files().at("report.html").find("torsional rigidity at end b"), std::string::npos);
  // Every file of the run listed with its size, counted here from the file itself.
  for (const auto& [file, content] : out.files()) {
    if (file == "report.html") continue;
    const size_t n = content.size();
    char size[32];
    if (n < 1000)
      std::snprintf(size, sizeof size, "%zu bytes", n);
    else
      std::snprintf(size, sizeof size, n < 10000 ? "%.1f kB" : "%.0f kB", n / 1e3);
    EXPECT_NE(out.files().at("report.html").find("<li><code>" + file + "</code> " + size + "</li>"), std::string::npos)
        << file << " " << size;
  }
}

// A life table anywhere a kind writes one (here /best/life, as the sizing kinds do): the table on
// the page, and life.svg, a bar per element on a log axis with the limit drawn.
Outputs LifeOutputs() {
  Outputs out;
  const nlohmann::json table = nlohmann::json::parse(R"([
    {"element": "input_roller", "kind": "roller", "equivalent_load_N": 543.5, "dynamic_rating_N": 3300,
     "static_rating_N": 3400, "s0": 3.55, "L10h": 2000, "pass": true},
    {"element": "eccentric_bearing", "kind": "ball", "equivalent_load_N": 2020.8, "dynamic_rating_N": 9000,
     "L10h": 500, "pass": false},
    {"element": "input_cam_contact", "kind": "cam contact", "equivalent_pressure_MPa": 1369.4,
     "reference_pressure_MPa": 1500, "L10h": 1000, "pass": true},
    {"element": "idle_roller", "kind": "roller", "equivalent_load_N": 0, "dynamic_rating_N": 3300, "L10h": null,
     "pass": true}])");
  out.SetResultJson({{"best", {{"life", {{"life_h", 1000.0}, {"table", table}}}}}});
  return out;
}

TEST(HtmlReport, LifeTableAndBarPlotOfAnyResultWithALife) {
  Outputs out = LifeOutputs();
  AddReport("no_such_kind_for_report", {{"name", "n"}}, out);
  ASSERT_TRUE(out.files().count("life.svg"));
  const std::string& html = out.files().at("report.html");
  EXPECT_NE(html.find("<h2>Lives</h2>"), std::string::npos);
  EXPECT_NE(html.find("<code>/best/life/table</code>"), std::string::npos);
  EXPECT_NE(html.find("<td>input_roller</td><td>roller</td><td class=\"n\">543.5 N</td><td class=\"n\">3300 N</td>"
                      "<td class=\"n\">3400 N</td><td class=\"n\">3.55</td><td class=\"n\">2000 h</td>"
                      "<td class=\"pass\">pass</td>"),
            std::string::npos);
  EXPECT_NE(html.find("<td class=\"n\">500 h</td><td class=\"fail\">FAIL</td>"), std::string::npos);
  EXPECT_NE(html.find("p_eq 1369.4 MPa</td><td class=\"n\">p_ref 1500 MPa"), std::string::npos);
  EXPECT_NE(html.find(">no load</td>"), std::string::npos);
  EXPECT_EQ(Count(html, "<figcaption>life.svg</figcaption>"), 1);
  // Axis: decades 10² … 10⁴ over 500 px from x = 190: the limit 1000 h at 190 + 500·(3 − 2)/2 = 440;
  // the 2000 h bar 500·(log10 2000 − 2)/2 = 325.26 px long, the 500 h bar (failing: red) 174.74 px.
  const std::string& svg = out.files().at("life.svg");
  EXPECT_NE(svg.find("x1=\"440.00\" y1=\"48.00\" x2=\"440.00\""), std::string::npos) << svg;
  EXPECT_NE(svg.find("width=\"325.26\""), std::string::npos) << svg;
  EXPECT_NE(svg.find("width=\"174.74\" height=\"18.00\" fill=\"#d62728\""), std::string::npos) << svg;
  EXPECT_NE(svg.find(">1e2</text>"), std::string::npos);
  EXPECT_NE(svg.find(">1e4</text>"), std::string::npos);
  EXPECT_NE(svg.find("limit life_h = 1000 h"), std::string::npos);
  EXPECT_NE(svg.find(">no load</text>"), std::string::npos);
  // Same outputs, same files.
  Outputs again = LifeOutputs();
  AddReport("no_such_kind_for_report", {{"name", "n"}}, again);
  EXPECT_EQ(again.files(), out.files());
}

TEST(HtmlReport, NoLifeNoLifePlot) {
  Outputs out = SampleOutputs(1400);
  AddReport("report_test_kind", {{"name", "n"}}, out);
  EXPECT_FALSE(out.files().count("life.svg"));
  EXPECT_EQ(out.files().at("report.html").find("<h2>Lives</h2>"), std::string::npos);
}

}  // namespace report_test
}  // namespace camopt::studies
