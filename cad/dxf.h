// A small DXF R2000 (AC1015) writer of our own: units declared ($INSUNITS = 4, millimetres;
// $MEASUREMENT = 1, metric), every object with a unique handle and a valid owner (tables, block
// records, layouts, the root dictionary), so that a DXF reader's audit has nothing to repair.
// Entities: LWPOLYLINE with bulges (arcs), CIRCLE, LINE, TEXT. Handles are assigned in writing
// order, so the same drawing gives the same bytes.
#pragma once

#include <string>
#include <vector>

#include "cad/arc_fit.h"

namespace camopt::cad {

/// `value` as printf's "%.12g" writes it (and std::to_chars(first, last, value,
/// std::chars_format::general, 12)), into [first, first + 32): the end of the text. Every DXF number
/// is written so; the ones between 1e-9 and 1e11 in magnitude from their exact binary value in
/// integer arithmetic, the others by std::to_chars.
char* FormatG12(char* first, double value);

class DxfDocument {
 public:
  /// A layer with an AutoCAD colour index (1 red, 2 yellow, 3 green, 4 cyan, 5 blue, 7 white/black).
  void AddLayer(const std::string& name, int color);
  /// A chain of arcs as one LWPOLYLINE (closed: the last end point equals the first start point
  /// and is not repeated).
  void AddChain(const std::string& layer, const std::vector<ArcSegment>& chain, bool closed);
  void AddCircle(const std::string& layer, const Vec2<double>& centre, double radius);
  void AddLine(const std::string& layer, const Vec2<double>& a, const Vec2<double>& b);
  /// A centre mark: two crossing lines of length `size` [mm].
  void AddCentreMark(const std::string& layer, const Vec2<double>& centre, double size);
  /// Single-line text, left-aligned at `position`, height in mm.
  void AddText(const std::string& layer, const Vec2<double>& position, double height, const std::string& text);

  std::string ToString() const;

 private:
  struct Layer {
    std::string name;
    int color;
  };
  struct Entity {
    enum Kind { kChain, kCircle, kLine, kText } kind = kChain;
    std::string layer;
    std::vector<ArcSegment> chain;
    bool closed = false;
    Vec2<double> a = Vec2<double>::Zero(), b = Vec2<double>::Zero();
    double value = 0.0;
    std::string text;
  };
  /// A new entity of `kind` on `layer`, appended (drawing order is writing order).
  Entity& NewEntity(Entity::Kind kind, const std::string& layer);
  std::vector<Layer> layers_;
  std::vector<Entity> entities_;
};

}  // namespace camopt::cad
