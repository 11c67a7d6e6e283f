#include "studies/writers.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>

#include <dxflib/dl_dxf.h>
#include <unistd.h>

namespace camopt::studies {

namespace {

std::string Num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

std::string Px(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  return buf;
}

std::string Escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '&') out += "&amp;";
    else out += c;
  }
  return out;
}

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

std::string SvgLinePlot(const std::vector<Series>& series, const PlotOptions& o) {
  double xmin = INFINITY, xmax = -INFINITY, ymin = INFINITY, ymax = -INFINITY;
  for (const auto& s : series)
    for (size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i) {
      if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) continue;
      xmin = std::min(xmin, s.x[i]);
      xmax = std::max(xmax, s.x[i]);
      ymin = std::min(ymin, s.y[i]);
      ymax = std::max(ymax, s.y[i]);
    }
  if (!std::isfinite(xmin)) xmin = 0, xmax = 1, ymin = 0, ymax = 1;
  if (xmax - xmin < 1e-12) xmax = xmin + 1;
  if (ymax - ymin < 1e-12 * std::max(1.0, std::abs(ymax))) {
    const double pad = std::max(1.0, std::abs(ymax)) * 0.05;
    ymin -= pad;
    ymax += pad;
  }
  const double ystep = NiceStep(ymax - ymin, 6), xstep = NiceStep(xmax - xmin, 8);
  ymin = std::floor(ymin / ystep) * ystep;
  ymax = std::ceil(ymax / ystep) * ystep;

  const double L = 80, R = 20, T = 40, B = 60;
  const double W = o.width - L - R, H = o.height - T - B;
  auto X = [&](double x) { return L + (x - xmin) / (xmax - xmin) * W; };
  auto Y = [&](double y) { return T + (ymax - y) / (ymax - ymin) * H; };

  std::ostringstream os;
  os << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << o.width << "\" height=\""
     << o.height << "\" font-family=\"sans-serif\" font-size=\"12\">\n";
  os << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  os << "<text x=\"" << o.width / 2 << "\" y=\"22\" text-anchor=\"middle\" font-size=\"15\">"
     << Escape(o.title) << "</text>\n";
  for (double y = ymin; y <= ymax + 0.5 * ystep; y += ystep) {
    os << "<line x1=\"" << Px(L) << "\" x2=\"" << Px(L + W) << "\" y1=\"" << Px(Y(y))
       << "\" y2=\"" << Px(Y(y)) << "\" stroke=\"#ddd\"/>\n";
    os << "<text x=\"" << Px(L - 6) << "\" y=\"" << Px(Y(y) + 4) << "\" text-anchor=\"end\">"
       << Num(std::abs(y) < 1e-12 * ystep ? 0.0 : y) << "</text>\n";
  }
  for (double x = std::ceil(xmin / xstep) * xstep; x <= xmax + 1e-9 * xstep; x += xstep) {
    os << "<line y1=\"" << Px(T) << "\" y2=\"" << Px(T + H) << "\" x1=\"" << Px(X(x))
       << "\" x2=\"" << Px(X(x)) << "\" stroke=\"#eee\"/>\n";
    os << "<text x=\"" << Px(X(x)) << "\" y=\"" << Px(T + H + 18) << "\" text-anchor=\"middle\">"
       << Num(std::abs(x) < 1e-12 * xstep ? 0.0 : x) << "</text>\n";
  }
  os << "<rect x=\"" << Px(L) << "\" y=\"" << Px(T) << "\" width=\"" << Px(W) << "\" height=\""
     << Px(H) << "\" fill=\"none\" stroke=\"black\"/>\n";
  os << "<text x=\"" << Px(L + W / 2) << "\" y=\"" << o.height - 15
     << "\" text-anchor=\"middle\">" << Escape(o.x_label) << "</text>\n";
  os << "<text transform=\"translate(18," << Px(T + H / 2)
     << ") rotate(-90)\" text-anchor=\"middle\">" << Escape(o.y_label) << "</text>\n";
  for (size_t k = 0; k < series.size(); ++k) {
    const auto& s = series[k];
    const char* color = kPalette[k % 10];
    std::ostringstream path;
    bool pen = false;
    for (size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i) {
      if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) {
        pen = false;
        continue;
      }
      path << (pen ? " L" : " M") << Px(X(s.x[i])) << "," << Px(Y(s.y[i]));
      pen = true;
    }
    if (s.markers) {
      for (size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i)
        if (std::isfinite(s.x[i]) && std::isfinite(s.y[i]))
          os << "<circle cx=\"" << Px(X(s.x[i])) << "\" cy=\"" << Px(Y(s.y[i])) << "\" r=\"3\" fill=\""
             << color << "\"/>\n";
    } else {
      os << "<path d=\"" << path.str() << "\" fill=\"none\" stroke=\"" << color
         << "\" stroke-width=\"1.5\"/>\n";
    }
    os << "<line x1=\"" << Px(L + 10) << "\" x2=\"" << Px(L + 30) << "\" y1=\"" << Px(T + 14 + 16 * k)
       << "\" y2=\"" << Px(T + 14 + 16 * k) << "\" stroke=\"" << color << "\" stroke-width=\"2\"/>\n";
    os << "<text x=\"" << Px(L + 35) << "\" y=\"" << Px(T + 18 + 16 * k) << "\">" << Escape(s.label)
       << "</text>\n";
  }
  os << "</svg>\n";
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
  if (!std::isfinite(xmin)) xmin = ymin = -1, xmax = ymax = 1;
  const double span = std::max({xmax - xmin, ymax - ymin, 1e-9});
  const double margin = 30, title = 30, scale = (size - 2 * margin) / span;
  const double cx = 0.5 * (xmin + xmax), cy = 0.5 * (ymin + ymax);
  auto X = [&](double x) { return size / 2.0 + (x - cx) * scale; };
  auto Y = [&](double y) { return title + size / 2.0 - (y - cy) * scale; };

  std::ostringstream os;
  os << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << size << "\" height=\""
     << size + title << "\" font-family=\"sans-serif\" font-size=\"12\">\n";
  os << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  os << "<text x=\"" << size / 2 << "\" y=\"20\" text-anchor=\"middle\" font-size=\"15\">"
     << Escape(d.title) << "</text>\n";
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
         << "\" stroke-width=\"" << layer.stroke_width << "\"/>\n";
    }
    for (const auto& c : layer.circles)
      os << "<circle cx=\"" << Px(X(c.x)) << "\" cy=\"" << Px(Y(c.y)) << "\" r=\"" << Px(c.r * scale)
         << "\" fill=\"none\" stroke=\"" << layer.color << "\" stroke-width=\"" << layer.stroke_width
         << "\"/>\n";
    os << "<text x=\"10\" y=\"" << 48 + 16 * row++ << "\" fill=\"" << layer.color << "\">"
       << Escape(layer.name) << "</text>\n";
  }
  os << "</svg>\n";
  return os.str();
}

std::string ToDxf(const Drawing& d) {
  // dxflib writes to a path; write to a private temporary file and read it back.
  char tmpl[] = "/tmp/camopt-dxf-XXXXXX";
  const int fd = mkstemp(tmpl);
  if (fd < 0) throw std::runtime_error("cannot create a temporary file for DXF output");
  close(fd);
  const std::string tmp = tmpl;
  {
    DL_Dxf dxf;
    std::unique_ptr<DL_WriterA> dw(dxf.out(tmp.c_str(), DL_Codes::AC1015));
    if (!dw) throw std::runtime_error("cannot open " + tmp + " for DXF output");
    dxf.writeHeader(*dw);
    dw->sectionEnd();
    dw->sectionTables();
    dxf.writeVPort(*dw);
    dw->tableLinetypes(3);
    dxf.writeLinetype(*dw, DL_LinetypeData("BYBLOCK", "BYBLOCK", 0, 0, 0.0));
    dxf.writeLinetype(*dw, DL_LinetypeData("BYLAYER", "BYLAYER", 0, 0, 0.0));
    dxf.writeLinetype(*dw, DL_LinetypeData("CONTINUOUS", "Continuous", 0, 0, 0.0));
    dw->tableEnd();
    dw->tableLayers(static_cast<int>(d.layers.size()) + 1);
    dxf.writeLayer(*dw, DL_LayerData("0", 0),
                   DL_Attributes("", DL_Codes::black, 100, "CONTINUOUS", 1.0));
    for (size_t i = 0; i < d.layers.size(); ++i)
      dxf.writeLayer(*dw, DL_LayerData(d.layers[i].name, 0),
                     DL_Attributes("", static_cast<int>(1 + i % 6), 100, "CONTINUOUS", 1.0));
    dw->tableEnd();
    dw->tableStyle(1);
    // Exactly "Standard": dxflib gives DIMSTYLE the handle of the style of that name, and leaves
    // it uninitialised (different bytes on every run) when there is none.
    dxf.writeStyle(*dw, DL_StyleData("Standard", 0, 2.5, 1.0, 0.0, 0, 2.5, "txt", ""));
    dw->tableEnd();
    dxf.writeView(*dw);
    dxf.writeUcs(*dw);
    dw->tableAppid(1);
    dxf.writeAppid(*dw, "ACAD");
    dw->tableEnd();
    dxf.writeDimStyle(*dw, 1, 1, 1, 1, 1);
    dxf.writeBlockRecord(*dw);
    dw->tableEnd();
    dw->sectionEnd();
    dw->sectionBlocks();
    dxf.writeBlock(*dw, DL_BlockData("*Model_Space", 0, 0.0, 0.0, 0.0));
    dxf.writeEndBlock(*dw, "*Model_Space");
    dxf.writeBlock(*dw, DL_BlockData("*Paper_Space", 0, 0.0, 0.0, 0.0));
    dxf.writeEndBlock(*dw, "*Paper_Space");
    dw->sectionEnd();
    dw->sectionEntities();
    for (const auto& layer : d.layers) {
      const DL_Attributes attr(layer.name, 256, -1, "BYLAYER", 1.0);
      for (const auto& pl : layer.polylines) {
        dxf.writePolyline(*dw, DL_PolylineData(static_cast<int>(pl.size()), 0, 0, layer.closed ? 1 : 0),
                          attr);
        for (const auto& [x, y] : pl) dxf.writeVertex(*dw, DL_VertexData(x, y, 0.0, 0.0));
        dxf.writePolylineEnd(*dw);
      }
      for (const auto& c : layer.circles)
        dxf.writeCircle(*dw, DL_CircleData(c.x, c.y, 0.0, c.r), attr);
    }
    dw->sectionEnd();
    dxf.writeObjects(*dw);
    dxf.writeObjectsEnd(*dw);
    dw->dxfEOF();
    dw->close();
  }
  std::ifstream in(tmp, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  std::filesystem::remove(tmp);
  return buffer.str();
}

}  // namespace camopt::studies
