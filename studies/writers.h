// Output writers shared by every study kind: CSV series, SVG plots and drawings (the geometry
// files, DXF/STEP/STL, are in studies/geometry_files.h and cad/; report.html, which gathers every
// SVG of a run, is in studies/report.h).
// They return the file content as a string; Outputs writes everything at once.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace camopt::studies {

/// A table of named columns of equal length.
struct Table {
  std::vector<std::string> names;           // with units, e.g. "input_angle_deg"
  std::vector<std::vector<double>> columns;  // columns[c][row]
  void Add(std::string name, std::vector<double> column) {
    names.push_back(std::move(name));
    columns.push_back(std::move(column));
  }
};

/// Text for an XML or HTML document (an SVG plot's title, report.html): & < > " escaped, and what
/// XML 1.0 has no character for (the control characters other than tab, line feed and carriage
/// return; U+FFFE and U+FFFF) replaced by U+FFFD, so that a study name can never make a file
/// ill-formed. The one escaping of every writer of markup.
std::string XmlText(const std::string& text);

/// CSV with a header line; full precision (%.10g).
std::string ToCsv(const Table& table);

/// How a series is drawn. kAuto: a line, or a marker when the series has a single point or
/// error bars.
enum class SeriesStyle { kAuto, kLine, kMarkers, kLineAndMarkers };

struct Series {
  std::string label;
  std::vector<double> x, y;
  /// Optional ±error bars on y (one per point, e.g. a measurement's standard deviation).
  std::vector<double> y_error = {};
  SeriesStyle style = SeriesStyle::kAuto;
  bool markers = false;  ///< true: the same as style = kMarkers (a scatter plot)
  /// Optional text beside each point (one per point, "" for none), e.g. a sweep case's number.
  std::vector<std::string> point_labels = {};
};

/// A horizontal line at y = value (a limit, a target) or a vertical one at x = value, drawn dashed
/// across the plot and named in the legend. A non-finite value (no limit) draws nothing.
struct GuideLine {
  std::string label;
  double value;
  bool vertical = false;
};

/// A labelled point on a curve (optimum, reference design): a large filled marker, its label
/// beside it and in the legend.
struct MarkedPoint {
  std::string label;
  double x, y;
};

/// The limit lines of a pressure angle bound in magnitude, |φ| ≤ limit: at +limit, and at −limit
/// too when `values` (the plotted angles, deg) go below zero.
std::vector<GuideLine> PressureAngleLimitLines(double limit_deg, const std::vector<double>& values);

struct PlotOptions {
  std::string title, x_label, y_label;  // axis labels as "quantity [unit]"
  int width = 800, height = 480;
  std::vector<GuideLine> guides = {};
  std::vector<MarkedPoint> points = {};
};

/// An SVG plot with axes, ticks, labels and a legend above the plot area (so that it hides no
/// data). Series k has its own colour and, from the second on, its own dash pattern and marker
/// shape, so that a series lying on another stays visible. Guides, marked points and error bars
/// are inside the axis range. Non-finite points are skipped.
std::string SvgLinePlot(const std::vector<Series>& series, const PlotOptions& options);

/// One bar of SvgBarChart: its label left of the axis, its length `value` (NaN: no bar), the text
/// written at its end (the value with its unit, a second number); highlighted bars red.
struct Bar {
  std::string label;
  double value;
  std::string text = "";
  bool highlight = false;
};

struct BarChartOptions {
  std::string title, x_label;
  int width = 800;
  std::vector<GuideLine> guides = {};     ///< vertical dashed lines at a value (a limit), in a legend
  std::vector<std::string> notes = {};    ///< text lines under the chart (advice, what the bars mean)
};

/// A horizontal bar chart on a linear axis from 0, one row a bar, in the order given.
std::string SvgBarChart(const std::vector<Bar>& bars, const BarChartOptions& options);

/// One panel of SvgStackedPlots: SvgLinePlot's series and options.
struct Panel {
  std::vector<Series> series;
  PlotOptions options;
};
/// Panels drawn one below the other in one SVG (e.g. S-V-A-J over the same axis), each as
/// SvgLinePlot draws it; the width is the widest panel's.
std::string SvgStackedPlots(const std::vector<Panel>& panels);

using Polyline = std::vector<std::pair<double, double>>;

struct Circle {
  double x, y, r;
};

/// A geometry drawing: closed or open polylines and circles in model units (mm), y up.
struct Drawing {
  struct Layer {
    std::string name, color;  // color as an SVG colour; DXF uses the layer index
    std::vector<Polyline> polylines;
    std::vector<Circle> circles;
    bool closed = true;
    double stroke_width = 1.0;  // in px at the default scale
    std::string dash = "";      // SVG stroke-dasharray ("" solid), e.g. for a curve on another
  };
  /// A short text centred at (x, y) in model units, e.g. a roller's number.
  struct Label {
    double x, y;
    std::string text;
    std::string color = "black";
  };
  std::string title;
  std::vector<Layer> layers;
  std::vector<Label> labels = {};
  /// The main dimensions as text lines under the drawing ("outer diameter 96 mm").
  std::vector<std::string> dimensions = {};
};

/// SVG of a drawing, fitted to the canvas with equal axis scales; a layer's name is its legend
/// entry, labels are drawn last (on top). Under the drawing: a scale bar of a round length (1, 2
/// or 5 × 10^k mm, about a fifth of the drawing), its overall extent and its main dimensions.
std::string SvgDrawing(const Drawing& drawing, int size_px = 800);

}  // namespace camopt::studies
