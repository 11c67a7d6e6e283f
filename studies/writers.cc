#include "studies/writers.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>


namespace camopt::studies {

namespace {

// printf's "%.10g" and "%.2f" (std::to_chars with a precision is specified as printf in the "C"
// locale: the same characters, several times faster than snprintf, which formatted half of an
// LCR analysis's instructions), cut to 31 characters as the 32-byte snprintf buffers did.
std::string Formatted(double v, std::chars_format format, int precision) {
  char buf[400];
  const std::to_chars_result r = std::to_chars(buf, buf + sizeof buf, v, format, precision);
  const size_t n = r.ec == std::errc() ? size_t(r.ptr - buf) : 0;
  return std::string(buf, std::min<size_t>(n, 31));
}

std::string Num(double v) { return Formatted(v, std::chars_format::general, 10); }

std::string Px(double v) { return Formatted(v, std::chars_format::fixed, 2); }

std::string Escape(const std::string& s) { return XmlText(s); }

// A title centred at x on a canvas `width` px wide: a title longer than the canvas at 15 px (about
// 8.3 px a character in a sans-serif face) is drawn squeezed to the canvas less 20 px
// (textLength), so that no title is ever clipped by the edge of its picture.
std::string TitleText(double x, double y, double width, const std::string& title) {
  size_t chars = 0;
  for (unsigned char c : title) chars += (c & 0xC0) != 0x80;  // UTF-8 code points
  std::string fit;
  if (8.3 * static_cast<double>(chars) > width - 20)
    fit = " textLength=\"" + Px(width - 20) + "\" lengthAdjust=\"spacingAndGlyphs\"";
  return "<text x=\"" + Px(x) + "\" y=\"" + Px(y) + "\" text-anchor=\"middle\" font-size=\"15\"" + fit + ">" +
         Escape(title) + "</text>\n";
}

}  // namespace

std::string XmlText(const std::string& s) {
  std::string out;
  out.reserve(s.size());
  for (size_t i = 0; i < s.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '&') out += "&amp;";
    else if (c == '"') out += "&quot;";
    else if (c < 0x20 && c != '\t' && c != '\n' && c != '\r') out += "\xEF\xBF\xBD";
    else if (c == 0xEF && i + 2 < s.size() && static_cast<unsigned char>(s[i + 1]) == 0xBF &&
             (static_cast<unsigned char>(s[i + 2]) == 0xBE || static_cast<unsigned char>(s[i + 2]) == 0xBF)) {
      out += "\xEF\xBF\xBD";  // U+FFFE, U+FFFF
      i += 2;
    } else {
      out += static_cast<char>(c);
    }
  }
  return out;
}

namespace {

// "Nice" tick step for a range, 1-2-5 series.
double NiceStep(double range, int target) {
  if (!(range > 0)) return 1.0;
  const double raw = range / target;
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  const double f = raw / mag;
  return (f < 1.5 ? 1 : f < 3.5 ? 2 : f < 7.5 ? 5 : 10) * mag;
}

const char* kPalette[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd",
                          "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf"};

}  // namespace

std::string ToCsv(const Table& table) {
  std::ostringstream os;
  for (size_t c = 0; c < table.names.size(); ++c) os << (c ? "," : "") << table.names[c];
  os << "\n";
  size_t rows = 0;
  for (const auto& col : table.columns) rows = std::max(rows, col.size());
  for (size_t r = 0; r < rows; ++r) {
    for (size_t c = 0; c < table.columns.size(); ++c) {
      if (c) os << ",";
      if (r < table.columns[c].size()) os << Num(table.columns[c][r]);
    }
    os << "\n";
  }
  return os.str();
}

namespace {

// Dash pattern and marker shape of series k: the first solid with circles, the next ones dashed
// or dotted, so that a series lying exactly on another still shows.
const char* kDashes[] = {"", "8,4", "2,3", "12,3,3,3", "5,5", "1,4"};
enum class Shape { kCircle, kSquare, kTriangle, kDiamond, kDown };

std::string Marker(Shape shape, double x, double y, double r, const std::string& color, bool filled) {
  std::ostringstream os;
  const std::string paint = std::string(" fill=\"") + (filled ? color : "white") + "\" stroke=\"" +
                            (filled ? "black" : color) + "\" stroke-width=\"1.2\"/>";
  switch (shape) {
    case Shape::kCircle:
      os << "<circle cx=\"" << Px(x) << "\" cy=\"" << Px(y) << "\" r=\"" << Px(r) << "\"" << paint;
      break;
    case Shape::kSquare:
      os << "<rect x=\"" << Px(x - r) << "\" y=\"" << Px(y - r) << "\" width=\"" << Px(2 * r)
         << "\" height=\"" << Px(2 * r) << "\"" << paint;
      break;
    case Shape::kTriangle:
      os << "<path d=\"M" << Px(x) << "," << Px(y - 1.2 * r) << " L" << Px(x + 1.1 * r) << ","
         << Px(y + 0.8 * r) << " L" << Px(x - 1.1 * r) << "," << Px(y + 0.8 * r) << " Z\"" << paint;
      break;
    case Shape::kDiamond:
      os << "<path d=\"M" << Px(x) << "," << Px(y - 1.3 * r) << " L" << Px(x + 1.3 * r) << ","
         << Px(y) << " L" << Px(x) << "," << Px(y + 1.3 * r) << " L" << Px(x - 1.3 * r) << ","
         << Px(y) << " Z\"" << paint;
      break;
    case Shape::kDown:
      os << "<path d=\"M" << Px(x) << "," << Px(y + 1.2 * r) << " L" << Px(x + 1.1 * r) << ","
         << Px(y - 0.8 * r) << " L" << Px(x - 1.1 * r) << "," << Px(y - 0.8 * r) << " Z\"" << paint;
      break;
  }
  return os.str() + "\n";
}

// Tick label: short, and exactly 0 near zero.
std::string Tick(double v, double step) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", std::abs(v) < 1e-9 * step ? 0.0 : v);
  return buf;
}

bool DrawsLine(const Series& s) {
  if (s.markers) return false;
  switch (s.style) {
    case SeriesStyle::kLine:
    case SeriesStyle::kLineAndMarkers: return true;
    case SeriesStyle::kMarkers: return false;
    case SeriesStyle::kAuto: break;
  }
  return std::min(s.x.size(), s.y.size()) > 1 && s.y_error.empty();
}

bool DrawsMarkers(const Series& s) {
  return s.markers || s.style == SeriesStyle::kMarkers || s.style == SeriesStyle::kLineAndMarkers ||
         (s.style == SeriesStyle::kAuto && !DrawsLine(s));
}

}  // namespace

std::string SvgLinePlot(const std::vector<Series>& series, const PlotOptions& o) {
  double xmin = INFINITY, xmax = -INFINITY, ymin = INFINITY, ymax = -INFINITY;
  auto grow_x = [&](double x) { xmin = std::min(xmin, x), xmax = std::max(xmax, x); };
  auto grow_y = [&](double y) { ymin = std::min(ymin, y), ymax = std::max(ymax, y); };
  for (const auto& s : series)
    for (size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i) {
      if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) continue;
      grow_x(s.x[i]);
      grow_y(s.y[i]);
      if (i < s.y_error.size() && std::isfinite(s.y_error[i])) {
        grow_y(s.y[i] - std::abs(s.y_error[i]));
        grow_y(s.y[i] + std::abs(s.y_error[i]));
      }
    }
  for (const auto& p : o.points)
    if (std::isfinite(p.x) && std::isfinite(p.y)) grow_x(p.x), grow_y(p.y);
  const bool have_data = std::isfinite(xmin);
  for (const auto& g : o.guides) {
    if (!std::isfinite(g.value)) continue;
    if (g.vertical) grow_x(g.value);
    else grow_y(g.value);
  }
  if (!have_data || !std::isfinite(xmin) || !std::isfinite(ymin)) xmin = 0, xmax = 1, ymin = 0, ymax = 1;
  // Markers keep clear of the frame: a little room left and right.
  const bool markers = !o.points.empty() || std::any_of(series.begin(), series.end(), [](const Series& s) {
    return DrawsMarkers(s);
  });
  if (markers && xmax > xmin) {
    const double xpad = 0.03 * (xmax - xmin);
    xmin -= xpad;
    xmax += xpad;
  }
  if (xmax - xmin < 1e-12 * std::max(1.0, std::abs(xmax))) {
    const double pad = std::max(1.0, std::abs(xmax)) * 0.05;
    xmin -= pad;
    xmax += pad;
  }
  if (ymax - ymin < 1e-12 * std::max(1.0, std::abs(ymax))) {
    const double pad = std::max(1.0, std::abs(ymax)) * 0.05;
    ymin -= pad;
    ymax += pad;
  }
  // A little room above and below, so that no curve or limit line lies on the frame.
  const double ypad = 0.02 * (ymax - ymin);
  ymin -= ypad;
  ymax += ypad;
  const double ystep = NiceStep(ymax - ymin, 6), xstep = NiceStep(xmax - xmin, 8);
  ymin = std::floor(ymin / ystep) * ystep;
  ymax = std::ceil(ymax / ystep) * ystep;

  // Legend entries (series, guides, points) in rows above the plot area.
  struct Entry {
    std::string label, color, dash;
    bool line;
    int shape;  // -1: none
    bool filled;
  };
  std::vector<Entry> entries;
  for (size_t k = 0; k < series.size(); ++k)
    entries.push_back({series[k].label, kPalette[k % 10], kDashes[k % 6], DrawsLine(series[k]),
                       DrawsMarkers(series[k]) ? static_cast<int>(k % 5) : -1,
                       false});
  for (const auto& g : o.guides)
    if (std::isfinite(g.value)) entries.push_back({g.label, "#000000", "6,3", true, -1, false});
  for (size_t i = 0; i < o.points.size(); ++i)
    entries.push_back({o.points[i].label, kPalette[(series.size() + i) % 10], "", false,
                       static_cast<int>((3 + i) % 5), true});
  const double L = 80, R = 20, B = 60, row_h = 16;
  std::vector<std::pair<double, int>> slots;  // x offset, row
  {
    double x = 0;
    int row = 0;
    for (const auto& e : entries) {
      const double w = 42 + 6.8 * static_cast<double>(e.label.size());
      if (x > 0 && x + w > o.width - L - R) x = 0, ++row;
      slots.push_back({x, row});
      x += w + 14;
    }
  }
  const int legend_rows = slots.empty() ? 0 : slots.back().second + 1;
  const double T = 44 + row_h * legend_rows + (legend_rows ? 6 : 0);
  const int height = o.height + static_cast<int>(row_h * std::max(0, legend_rows - 1));
  const double W = o.width - L - R, H = height - T - B;
  auto X = [&](double x) { return L + (x - xmin) / (xmax - xmin) * W; };
  auto Y = [&](double y) { return T + (ymax - y) / (ymax - ymin) * H; };

  std::ostringstream os;
  os << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << o.width << "\" height=\""
     << height << "\" viewBox=\"0 0 " << o.width << " " << height
     << "\" font-family=\"sans-serif\" font-size=\"12\">\n";
  os << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  os << TitleText(o.width / 2.0, 22, o.width, o.title);
  for (double y = ymin; y <= ymax + 0.5 * ystep; y += ystep) {
    os << "<line x1=\"" << Px(L) << "\" x2=\"" << Px(L + W) << "\" y1=\"" << Px(Y(y))
       << "\" y2=\"" << Px(Y(y)) << "\" stroke=\"#ddd\"/>\n";
    os << "<text x=\"" << Px(L - 6) << "\" y=\"" << Px(Y(y) + 4) << "\" text-anchor=\"end\">"
       << Tick(y, ystep) << "</text>\n";
  }
  for (double x = std::ceil(xmin / xstep) * xstep; x <= xmax + 1e-9 * xstep; x += xstep) {
    os << "<line y1=\"" << Px(T) << "\" y2=\"" << Px(T + H) << "\" x1=\"" << Px(X(x))
       << "\" x2=\"" << Px(X(x)) << "\" stroke=\"#eee\"/>\n";
    os << "<text x=\"" << Px(X(x)) << "\" y=\"" << Px(T + H + 18) << "\" text-anchor=\"middle\">"
       << Tick(x, xstep) << "</text>\n";
  }
  os << "<rect x=\"" << Px(L) << "\" y=\"" << Px(T) << "\" width=\"" << Px(W) << "\" height=\""
     << Px(H) << "\" fill=\"none\" stroke=\"black\"/>\n";
  os << "<text x=\"" << Px(L + W / 2) << "\" y=\"" << height - 15
     << "\" text-anchor=\"middle\">" << Escape(o.x_label) << "</text>\n";
  os << "<text transform=\"translate(18," << Px(T + H / 2)
     << ") rotate(-90)\" text-anchor=\"middle\">" << Escape(o.y_label) << "</text>\n";
  // Guides under the data.
  for (const auto& g : o.guides) {
    if (!std::isfinite(g.value)) continue;
    if (g.vertical)
      os << "<line x1=\"" << Px(X(g.value)) << "\" x2=\"" << Px(X(g.value)) << "\" y1=\"" << Px(T)
         << "\" y2=\"" << Px(T + H) << "\"";
    else
      os << "<line x1=\"" << Px(L) << "\" x2=\"" << Px(L + W) << "\" y1=\"" << Px(Y(g.value))
         << "\" y2=\"" << Px(Y(g.value)) << "\"";
    os << " stroke=\"#000000\" stroke-width=\"1.5\" stroke-dasharray=\"6,3\"/>\n";
  }
  for (size_t k = 0; k < series.size(); ++k) {
    const auto& s = series[k];
    const std::string color = kPalette[k % 10];
    const size_t n = std::min(s.x.size(), s.y.size());
    if (DrawsLine(s)) {
      std::ostringstream path;
      bool pen = false;
      for (size_t i = 0; i < n; ++i) {
        if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) {
          pen = false;
          continue;
        }
        path << (pen ? " L" : " M") << Px(X(s.x[i])) << "," << Px(Y(s.y[i]));
        pen = true;
      }
      os << "<path d=\"" << path.str() << "\" fill=\"none\" stroke=\"" << color
         << "\" stroke-width=\"" << (k == 0 ? "2" : "1.5") << "\"";
      if (*kDashes[k % 6]) os << " stroke-dasharray=\"" << kDashes[k % 6] << "\"";
      os << "/>\n";
    }
    for (size_t i = 0; i < std::min(n, s.y_error.size()); ++i) {
      if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i]) || !std::isfinite(s.y_error[i])) continue;
      const double x = X(s.x[i]), y0 = Y(s.y[i] - std::abs(s.y_error[i])),
                   y1 = Y(s.y[i] + std::abs(s.y_error[i]));
      os << "<path d=\"M" << Px(x) << "," << Px(y0) << " L" << Px(x) << "," << Px(y1) << " M"
         << Px(x - 4) << "," << Px(y0) << " L" << Px(x + 4) << "," << Px(y0) << " M" << Px(x - 4)
         << "," << Px(y1) << " L" << Px(x + 4) << "," << Px(y1) << "\" fill=\"none\" stroke=\""
         << color << "\" stroke-width=\"1.2\"/>\n";
    }
    if (DrawsMarkers(s))
      for (size_t i = 0; i < n; ++i)
        if (std::isfinite(s.x[i]) && std::isfinite(s.y[i]))
          os << Marker(static_cast<Shape>(k % 5), X(s.x[i]), Y(s.y[i]), 3.5, color, false);
    for (size_t i = 0; i < std::min(n, s.point_labels.size()); ++i) {
      if (s.point_labels[i].empty() || !std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) continue;
      const double x = X(s.x[i]), y = Y(s.y[i]);
      const bool right_half = x > L + 0.8 * W;
      os << "<text x=\"" << Px(right_half ? x - 6 : x + 6) << "\" y=\"" << Px(y - 5) << "\" text-anchor=\""
         << (right_half ? "end" : "start") << "\" font-size=\"11\" fill=\"" << color
         << "\" stroke=\"white\" stroke-width=\"3\" paint-order=\"stroke\">" << Escape(s.point_labels[i])
         << "</text>\n";
    }
  }
  for (size_t i = 0; i < o.points.size(); ++i) {
    const auto& p = o.points[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) continue;
    const double x = X(p.x), y = Y(p.y);
    os << Marker(static_cast<Shape>((3 + i) % 5), x, y, 6, kPalette[(series.size() + i) % 10], true);
    const bool right_half = x > L + 0.6 * W;
    os << "<text x=\"" << Px(right_half ? x - 10 : x + 10) << "\" y=\"" << Px(y - 8)
       << "\" text-anchor=\"" << (right_half ? "end" : "start")
       << "\" stroke=\"white\" stroke-width=\"3\" paint-order=\"stroke\">" << Escape(p.label)
       << "</text>\n";
  }
  for (size_t k = 0; k < entries.size(); ++k) {
    const auto& e = entries[k];
    const double x = L + slots[k].first, y = 40 + row_h * slots[k].second;
    if (e.line) {
      os << "<line x1=\"" << Px(x) << "\" x2=\"" << Px(x + 28) << "\" y1=\"" << Px(y) << "\" y2=\""
         << Px(y) << "\" stroke=\"" << e.color << "\" stroke-width=\"2\"";
      if (!e.dash.empty()) os << " stroke-dasharray=\"" << e.dash << "\"";
      os << "/>\n";
    }
    if (e.shape >= 0) os << Marker(static_cast<Shape>(e.shape), x + 14, y, e.filled ? 5 : 3.5, e.color, e.filled);
    os << "<text x=\"" << Px(x + 34) << "\" y=\"" << Px(y + 4) << "\">" << Escape(e.label) << "</text>\n";
  }
  os << "</svg>\n";
  return os.str();
}

std::string SvgStackedPlots(const std::vector<Panel>& panels) {
  std::ostringstream body;
  int y = 0, width = 0;
  for (const Panel& p : panels) {
    std::string svg = SvgLinePlot(p.series, p.options);
    // SvgLinePlot's root is <svg xmlns=… width="W" height="H" …>: nested here at (0, y).
    const size_t h_at = svg.find("height=\"") + 8;
    const int h = std::stoi(svg.substr(h_at, svg.find('"', h_at) - h_at));
    svg.replace(0, std::string("<svg xmlns=\"http://www.w3.org/2000/svg\"").size(),
                "<svg x=\"0\" y=\"" + std::to_string(y) + "\"");
    body << svg;
    y += h;
    width = std::max(width, p.options.width);
  }
  std::ostringstream os;
  os << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << y
     << "\" viewBox=\"0 0 " << width << " " << y << "\">\n"
     << body.str() << "</svg>\n";
  return os.str();
}

std::string SvgDrawing(const Drawing& d, int size) {
  double xmin = INFINITY, xmax = -INFINITY, ymin = INFINITY, ymax = -INFINITY;
  auto grow = [&](double x, double y, double r) {
    xmin = std::min(xmin, x - r);
    xmax = std::max(xmax, x + r);
    ymin = std::min(ymin, y - r);
    ymax = std::max(ymax, y + r);
  };
  for (const auto& layer : d.layers) {
    for (const auto& pl : layer.polylines)
      for (const auto& [x, y] : pl)
        if (std::isfinite(x) && std::isfinite(y)) grow(x, y, 0);
    for (const auto& c : layer.circles) grow(c.x, c.y, c.r);
  }
  for (const auto& l : d.labels)
    if (std::isfinite(l.x) && std::isfinite(l.y)) grow(l.x, l.y, 0);
  if (!std::isfinite(xmin)) xmin = ymin = -1, xmax = ymax = 1;
  const double span = std::max({xmax - xmin, ymax - ymin, 1e-9});
  const double margin = 30, title = 30, scale = (size - 2 * margin) / span;
  const double cx = 0.5 * (xmin + xmax), cy = 0.5 * (ymin + ymax);
  auto X = [&](double x) { return size / 2.0 + (x - cx) * scale; };
  auto Y = [&](double y) { return title + size / 2.0 - (y - cy) * scale; };
  // The footer: the scale bar and extent on one line, then one line per main dimension.
  const double footer = 30 + 16 * static_cast<double>(d.dimensions.size());
  const int height = static_cast<int>(size + title + footer);

  std::ostringstream os;
  os << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << size << "\" height=\""
     << height << "\" viewBox=\"0 0 " << size << " " << height
     << "\" font-family=\"sans-serif\" font-size=\"12\">\n";
  os << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  os << TitleText(size / 2.0, 20, size, d.title);
  int row = 0;
  for (const auto& layer : d.layers) {
    for (const auto& pl : layer.polylines) {
      std::ostringstream path;
      bool pen = false;
      for (const auto& [x, y] : pl) {
        if (!std::isfinite(x) || !std::isfinite(y)) {
          pen = false;
          continue;
        }
        path << (pen ? " L" : " M") << Px(X(x)) << "," << Px(Y(y));
        pen = true;
      }
      if (layer.closed) path << " Z";
      os << "<path d=\"" << path.str() << "\" fill=\"none\" stroke=\"" << layer.color
         << "\" stroke-width=\"" << layer.stroke_width << "\"";
      if (!layer.dash.empty()) os << " stroke-dasharray=\"" << layer.dash << "\"";
      os << "/>\n";
    }
    for (const auto& c : layer.circles)
      os << "<circle cx=\"" << Px(X(c.x)) << "\" cy=\"" << Px(Y(c.y)) << "\" r=\"" << Px(c.r * scale)
         << "\" fill=\"none\" stroke=\"" << layer.color << "\" stroke-width=\"" << layer.stroke_width
         << "\"/>\n";
    os << "<text x=\"10\" y=\"" << 48 + 16 * row++ << "\" fill=\"" << layer.color << "\">"
       << Escape(layer.name) << (layer.dash.empty() ? "" : " (dashed)") << "</text>\n";
  }
  for (const auto& l : d.labels) {
    if (!std::isfinite(l.x) || !std::isfinite(l.y)) continue;
    os << "<text x=\"" << Px(X(l.x)) << "\" y=\"" << Px(Y(l.y) + 4) << "\" text-anchor=\"middle\" fill=\""
       << l.color << "\" font-size=\"11\" stroke=\"white\" stroke-width=\"3\" paint-order=\"stroke\">"
       << Escape(l.text) << "</text>\n";
  }
  // Scale bar: the round length nearest a fifth of the drawing's span.
  const double target = span / 5, decade = std::pow(10.0, std::floor(std::log10(target)));
  double bar = decade;
  for (double m : {2.0, 5.0, 10.0})
    if (std::abs(m * decade - target) < std::abs(bar - target)) bar = m * decade;
  const double y0 = size + title + 12, x1 = size - margin, x0 = x1 - bar * scale;
  os << "<path d=\"M" << Px(x0) << "," << Px(y0 - 5) << " L" << Px(x0) << "," << Px(y0) << " L" << Px(x1) << ","
     << Px(y0) << " L" << Px(x1) << "," << Px(y0 - 5) << "\" fill=\"none\" stroke=\"black\" stroke-width=\"1.5\"/>\n";
  char text[160];
  std::snprintf(text, sizeof text, "%g mm", bar);
  os << "<text x=\"" << Px(x0 - 6) << "\" y=\"" << Px(y0 + 4) << "\" text-anchor=\"end\">" << text << "</text>\n";
  std::snprintf(text, sizeof text, "extent %.1f × %.1f mm", xmax - xmin, ymax - ymin);
  os << "<text x=\"10\" y=\"" << Px(y0 + 4) << "\">" << text << "</text>\n";
  for (size_t i = 0; i < d.dimensions.size(); ++i)
    os << "<text x=\"10\" y=\"" << Px(y0 + 20 + 16 * static_cast<double>(i)) << "\">" << Escape(d.dimensions[i])
       << "</text>\n";
  os << "</svg>\n";
  return os.str();
}

std::vector<GuideLine> PressureAngleLimitLines(double limit_deg, const std::vector<double>& values) {
  std::vector<GuideLine> lines = {{"pressure angle limit", limit_deg}};
  if (std::any_of(values.begin(), values.end(), [](double v) { return v < 0; }))
    lines.push_back({"−pressure angle limit", -limit_deg});
  return lines;
}

std::string SvgBarChart(const std::vector<Bar>& bars, const BarChartOptions& o) {
  double hi = 0;
  for (const Bar& b : bars)
    if (std::isfinite(b.value)) hi = std::max(hi, b.value);
  for (const GuideLine& g : o.guides)
    if (std::isfinite(g.value)) hi = std::max(hi, g.value);
  if (!(hi > 0)) hi = 1;
  const double step = NiceStep(hi, 5), top_value = std::ceil(hi / step) * step;
  const double label_w = 210, right = 40, top = 40 + (o.guides.empty() ? 0 : 18), row_h = 26;
  const double plot_w = o.width - label_w - right, bottom = top + row_h * static_cast<double>(bars.size());
  // The notes wrapped at spaces to the canvas (about 6.8 px a character at 12 px).
  std::vector<std::string> lines;
  const size_t per_line = static_cast<size_t>(std::max(20.0, (o.width - 20) / 6.8));
  for (const std::string& note : o.notes) {
    std::string line, word;
    std::istringstream words(note);
    while (words >> word) {
      if (!line.empty() && line.size() + 1 + word.size() > per_line) lines.push_back(line), line.clear();
      line += (line.empty() ? "" : " ") + word;
    }
    lines.push_back(line);
  }
  const double height = bottom + 44 + 16 * static_cast<double>(lines.size());
  auto X = [&](double v) { return label_w + plot_w * v / top_value; };
  std::ostringstream os;
  os << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << o.width << "\" height=\"" << Px(height)
     << "\" viewBox=\"0 0 " << o.width << " " << Px(height) << "\" font-family=\"sans-serif\" font-size=\"12\">\n";
  os << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  os << TitleText(o.width / 2.0, 22, o.width, o.title);
  for (double v = 0; v <= top_value + 0.5 * step; v += step)
    os << "<line x1=\"" << Px(X(v)) << "\" x2=\"" << Px(X(v)) << "\" y1=\"" << Px(top - 4) << "\" y2=\"" << Px(bottom)
       << "\" stroke=\"#dddddd\"/>\n<text x=\"" << Px(X(v)) << "\" y=\"" << Px(bottom + 16)
       << "\" text-anchor=\"middle\">" << Tick(v, step) << "</text>\n";
  os << "<text x=\"" << Px(label_w + plot_w / 2) << "\" y=\"" << Px(bottom + 34) << "\" text-anchor=\"middle\">"
     << Escape(o.x_label) << "</text>\n";
  for (size_t i = 0; i < bars.size(); ++i) {
    const Bar& b = bars[i];
    const double y = top + row_h * static_cast<double>(i), baseline = y + row_h * 0.65;
    os << "<text x=\"" << Px(label_w - 6) << "\" y=\"" << Px(baseline) << "\" text-anchor=\"end\">" << Escape(b.label)
       << "</text>\n";
    const double w = std::isfinite(b.value) ? std::max(X(b.value) - label_w, 0.5) : 0.0;
    if (w > 0)
      os << "<rect x=\"" << Px(label_w) << "\" y=\"" << Px(y + 4) << "\" width=\"" << Px(w) << "\" height=\""
         << Px(row_h - 8) << "\" fill=\"" << (b.highlight ? "#d62728" : "#1f77b4") << "\"/>\n";
    // The bar's text beside its end, or inside it when the end is near the right edge.
    const bool inside = label_w + w + 6 + 6.8 * static_cast<double>(b.text.size()) > o.width - 4;
    os << "<text x=\"" << Px(inside ? label_w + w - 4 : label_w + w + 4) << "\" y=\"" << Px(baseline) << "\""
       << (inside ? " text-anchor=\"end\" fill=\"white\"" : "") << ">" << Escape(b.text) << "</text>\n";
  }
  double legend_x = label_w;
  for (const GuideLine& g : o.guides) {
    if (!std::isfinite(g.value)) continue;
    os << "<line x1=\"" << Px(X(g.value)) << "\" x2=\"" << Px(X(g.value)) << "\" y1=\"" << Px(top - 4) << "\" y2=\""
       << Px(bottom) << "\" stroke=\"black\" stroke-width=\"1.5\" stroke-dasharray=\"6,3\"/>\n";
    os << "<line x1=\"" << Px(legend_x) << "\" x2=\"" << Px(legend_x + 30) << "\" y1=\"" << Px(top - 18) << "\" y2=\""
       << Px(top - 18) << "\" stroke=\"black\" stroke-width=\"1.5\" stroke-dasharray=\"6,3\"/>\n<text x=\""
       << Px(legend_x + 36) << "\" y=\"" << Px(top - 14) << "\">" << Escape(g.label) << "</text>\n";
    legend_x += 56 + 6.8 * static_cast<double>(g.label.size());
  }
  for (size_t i = 0; i < lines.size(); ++i)
    os << "<text x=\"10\" y=\"" << Px(bottom + 56 + 16 * static_cast<double>(i)) << "\">" << Escape(lines[i])
       << "</text>\n";
  os << "</svg>\n";
  return os.str();
}

}  // namespace camopt::studies
