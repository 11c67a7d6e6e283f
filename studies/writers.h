// Output writers shared by every study kind: CSV series, SVG line plots and drawings, DXF.
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

/// CSV with a header line; full precision (%.10g).
std::string ToCsv(const Table& table);

struct Series {
  std::string label;
  std::vector<double> x, y;
  bool markers = false;  ///< a dot at each point instead of a line (a scatter plot)
};

struct PlotOptions {
  std::string title, x_label, y_label;
  int width = 800, height = 480;
};

/// An SVG line plot with axes, ticks, labels and a legend. Non-finite points are skipped.
std::string SvgLinePlot(const std::vector<Series>& series, const PlotOptions& options);

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
  };
  std::string title;
  std::vector<Layer> layers;
};

/// SVG of a drawing, fitted to the canvas with equal axis scales.
std::string SvgDrawing(const Drawing& drawing, int size_px = 800);

/// DXF (R2000, through dxflib) of a drawing: one DXF layer per drawing layer, polylines as
/// POLYLINE entities in mm, circles as CIRCLE entities.
std::string ToDxf(const Drawing& drawing);

}  // namespace camopt::studies
