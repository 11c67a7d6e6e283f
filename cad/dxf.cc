#include "cad/dxf.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <sstream>

namespace camopt::cad {

namespace {

__extension__ typedef unsigned __int128 U128;  // GCC and Clang on 64-bit targets

// 10^k as 128-bit integers, k = 0 ... 22.
struct Powers10 {
  U128 p[23];
  constexpr Powers10() : p() {
    p[0] = 1;
    for (int k = 1; k < 23; ++k) p[k] = p[k - 1] * 10;
  }
};
constexpr Powers10 kPow10;

}  // namespace

char* FormatG12(char* first, double value) {
  // %.12g (C11 §7.21.6.1): the value rounded to 12 significant digits (to nearest, ties to even,
  // on its exact binary value), d.ddddddddddd × 10^X; fixed notation with 11 − X decimals when
  // −4 ≤ X < 12, else d.ddddddddddde±XX; trailing zeros, and a trailing point, removed.
  const double a = std::abs(value);
  if (!(a >= 1e-9 && a < 1e11))
    return std::to_chars(first, first + 32, value, std::chars_format::general, 12).ptr;
  // a = m 2^q exactly (m < 2^53; q < 0 in this range, −q ≤ 83).
  int binary_exponent;
  const double fraction = std::frexp(a, &binary_exponent);
  const std::uint64_t m = static_cast<std::uint64_t>(std::ldexp(fraction, 53));
  const int shift = 53 - binary_exponent;
  // X = floor(log10 a), from 2^(e − 1) ≤ a < 2^e: floor((e − 1) log10 2) or one more.
  int x = static_cast<int>(std::floor((binary_exponent - 1) * 0.30102999566398120));
  const U128 kHigh = kPow10.p[12];
  U128 scaled, whole;
  for (;;) {
    scaled = static_cast<U128>(m) * kPow10.p[11 - x];  // a 10^(11 − X) 2^shift, < 2^127
    whole = scaled >> shift;
    if (whole < kHigh) break;
    ++x;
  }
  // Rounded to nearest, ties to even.
  const U128 rest = scaled - (whole << shift), half = static_cast<U128>(1) << (shift - 1);
  std::uint64_t digits = static_cast<std::uint64_t>(whole);
  if (rest > half || (rest == half && (digits & 1))) ++digits;
  if (digits == static_cast<std::uint64_t>(kHigh)) digits /= 10, ++x;
  char d[12];
  for (int i = 11; i >= 0; --i) d[i] = static_cast<char>('0' + digits % 10), digits /= 10;
  int n = 12;
  while (n > 1 && d[n - 1] == '0') --n;
  char* out = first;
  if (value < 0) *out++ = '-';
  if (x >= -4 && x < 12) {
    if (x >= 0) {
      for (int i = 0; i <= x; ++i) *out++ = d[i];
      if (n > x + 1) {
        *out++ = '.';
        for (int i = x + 1; i < n; ++i) *out++ = d[i];
      }
    } else {
      *out++ = '0';
      *out++ = '.';
      for (int i = 0; i < -x - 1; ++i) *out++ = '0';
      for (int i = 0; i < n; ++i) *out++ = d[i];
    }
  } else {
    *out++ = d[0];
    if (n > 1) {
      *out++ = '.';
      for (int i = 1; i < n; ++i) *out++ = d[i];
    }
    *out++ = 'e';
    *out++ = x < 0 ? '-' : '+';
    const int ax = std::abs(x);
    if (ax >= 100) *out++ = static_cast<char>('0' + ax / 100);
    *out++ = static_cast<char>('0' + ax / 10 % 10);
    *out++ = static_cast<char>('0' + ax % 10);
  }
  return out;
}

namespace {

// Group-code / value writer with a running handle counter.
class Out {
 public:
  // A value is one line of the file: a line break or another control byte in a user's text (a
  // study name) would end it and shift every following group, so they become spaces.
  void Pair(int code, const std::string& value) {
    Code(code);
    for (char c : value) out_ += static_cast<unsigned char>(c) < 0x20 || c == 0x7f ? ' ' : c;
    out_ += '\n';
  }
  void Pair(int code, int value) { Pair(code, std::to_string(value)); }
  void Num(int code, double value) {
    // As printf's "%.12g" (std::to_chars with a precision is specified so), without "-0".
    char buf[40];
    char* const end = FormatG12(buf, value == 0.0 ? 0.0 : value);
    Code(code);
    out_.append(buf, end);
    out_ += '\n';
  }
  /// A point in the xy plane: group codes `code` (x), code + 10 (y), code + 20 (z = 0).
  void Point(int code, const Vec2<double>& p) {
    Num(code, p.x());
    Num(code + 10, p.y());
    Num(code + 20, 0);
  }
  std::string Handle() {
    char buf[20];
    std::snprintf(buf, sizeof buf, "%X", next_++);
    return buf;
  }
  std::string Peek() const {
    char buf[20];
    std::snprintf(buf, sizeof buf, "%X", next_);
    return buf;
  }
  const std::string& str() const { return out_; }

 private:
  void Code(int code) {
    char buf[16];
    const std::to_chars_result r = std::to_chars(buf, buf + sizeof buf, code);
    out_.append(buf, r.ptr);
    out_ += '\n';
  }
  std::string out_;
  unsigned next_ = 0x20;
};

}  // namespace

void DxfDocument::AddLayer(const std::string& name, int color) { layers_.push_back({name, color}); }

DxfDocument::Entity& DxfDocument::NewEntity(Entity::Kind kind, const std::string& layer) {
  Entity& e = entities_.emplace_back();
  e.kind = kind;
  e.layer = layer;
  return e;
}

void DxfDocument::AddChain(const std::string& layer, const std::vector<ArcSegment>& chain, bool closed) {
  Entity& e = NewEntity(Entity::kChain, layer);
  e.chain = chain;
  e.closed = closed;
}

void DxfDocument::AddCircle(const std::string& layer, const Vec2<double>& centre, double radius) {
  Entity& e = NewEntity(Entity::kCircle, layer);
  e.a = centre;
  e.value = radius;
}

void DxfDocument::AddLine(const std::string& layer, const Vec2<double>& a, const Vec2<double>& b) {
  Entity& e = NewEntity(Entity::kLine, layer);
  e.a = a;
  e.b = b;
}

void DxfDocument::AddCentreMark(const std::string& layer, const Vec2<double>& c, double size) {
  const double h = 0.5 * size;
  AddLine(layer, c - Vec2<double>(h, 0), c + Vec2<double>(h, 0));
  AddLine(layer, c - Vec2<double>(0, h), c + Vec2<double>(0, h));
}

void DxfDocument::AddText(const std::string& layer, const Vec2<double>& position, double height,
                          const std::string& text) {
  Entity& e = NewEntity(Entity::kText, layer);
  e.a = position;
  e.value = height;
  e.text = text;
}

std::string DxfDocument::ToString() const {
  // Handles fixed up front for the objects that are referenced before they are written.
  Out o;
  const std::string root = o.Handle(), group_dict = o.Handle(), layout_dict = o.Handle();
  const std::string model_layout = o.Handle(), paper_layout = o.Handle();
  const std::string model_record = o.Handle(), paper_record = o.Handle();
  const std::string style_standard = o.Handle();

  std::ostringstream body_dummy;
  // A table's head with a new handle, returned (the owner of its records).
  auto table = [&](const std::string& name, int count) {
    const std::string handle = o.Handle();
    o.Pair(0, "TABLE");
    o.Pair(2, name);
    o.Pair(5, handle);
    o.Pair(330, "0");
    o.Pair(100, "AcDbSymbolTable");
    o.Pair(70, count);
    return handle;
  };
  // A table record's head and its name (group 2), then the standard flags (group 70 = 0) except
  // for block records, which have none.
  auto record = [&](const std::string& type, const std::string& handle, const std::string& owner,
                    const std::string& subclass, const std::string& name) {
    o.Pair(0, type);
    o.Pair(type == "DIMSTYLE" ? 105 : 5, handle);
    o.Pair(330, owner);
    o.Pair(100, "AcDbSymbolTableRecord");
    o.Pair(100, subclass);
    o.Pair(2, name);
    if (type != "BLOCK_RECORD") o.Pair(70, 0);
  };

  // The header is written last into its own buffer: $HANDSEED is known only at the end.
  Out& w = o;
  // An entity's head (blocks' BLOCK and ENDBLK too) with a new handle; paper-space ones carry 67.
  auto entity = [&](const char* type, const std::string& owner, bool paper, const std::string& layer,
                    const char* subclass) {
    w.Pair(0, type);
    w.Pair(5, w.Handle());
    w.Pair(330, owner);
    w.Pair(100, "AcDbEntity");
    if (paper) w.Pair(67, 1);
    w.Pair(8, layer);
    w.Pair(100, subclass);
  };
  w.Pair(0, "SECTION");
  w.Pair(2, "CLASSES");
  w.Pair(0, "ENDSEC");
  w.Pair(0, "SECTION");
  w.Pair(2, "TABLES");
  {
    const std::string t = table("VPORT", 1);
    record("VPORT", w.Handle(), t, "AcDbViewportTableRecord", "*Active");
    w.Num(10, 0); w.Num(20, 0); w.Num(11, 1); w.Num(21, 1);
    w.Num(12, 0); w.Num(22, 0); w.Num(13, 0); w.Num(23, 0);
    w.Num(14, 1); w.Num(24, 1); w.Num(15, 1); w.Num(25, 1);
    w.Num(16, 0); w.Num(26, 0); w.Num(36, 1); w.Num(17, 0); w.Num(27, 0); w.Num(37, 0);
    w.Num(40, 200); w.Num(41, 1); w.Num(42, 50); w.Num(43, 0); w.Num(44, 0); w.Num(50, 0); w.Num(51, 0);
    w.Pair(71, 0); w.Pair(72, 100); w.Pair(73, 1); w.Pair(74, 3); w.Pair(75, 0); w.Pair(76, 0);
    w.Pair(77, 0); w.Pair(78, 0);
    w.Pair(0, "ENDTAB");
  }
  {
    const std::string t = table("LTYPE", 3);
    for (const char* name : {"ByBlock", "ByLayer", "Continuous"}) {
      record("LTYPE", w.Handle(), t, "AcDbLinetypeTableRecord", name);
      w.Pair(3, std::string(name) == "Continuous" ? "Solid line" : "");
      w.Pair(72, 65);
      w.Pair(73, 0);
      w.Num(40, 0);
    }
    w.Pair(0, "ENDTAB");
  }
  {
    const std::string t = table("LAYER", static_cast<int>(layers_.size()) + 1);
    std::vector<Layer> all = {{"0", 7}};
    all.insert(all.end(), layers_.begin(), layers_.end());
    for (const Layer& l : all) {
      record("LAYER", w.Handle(), t, "AcDbLayerTableRecord", l.name);
      w.Pair(62, l.color);
      w.Pair(6, "Continuous");
    }
    w.Pair(0, "ENDTAB");
  }
  {
    const std::string t = table("STYLE", 1);
    record("STYLE", style_standard, t, "AcDbTextStyleTableRecord", "Standard");
    w.Num(40, 0);
    w.Num(41, 1);
    w.Num(50, 0);
    w.Pair(71, 0);
    w.Num(42, 2.5);
    w.Pair(3, "txt");
    w.Pair(4, "");
    w.Pair(0, "ENDTAB");
  }
  for (const char* name : {"VIEW", "UCS"}) {
    table(name, 0);
    w.Pair(0, "ENDTAB");
  }
  {
    const std::string t = table("APPID", 1);
    record("APPID", w.Handle(), t, "AcDbRegAppTableRecord", "ACAD");
    w.Pair(0, "ENDTAB");
  }
  {
    const std::string t = table("DIMSTYLE", 1);
    w.Pair(100, "AcDbDimStyleTable");
    w.Pair(71, 0);
    record("DIMSTYLE", w.Handle(), t, "AcDbDimStyleTableRecord", "Standard");
    w.Pair(0, "ENDTAB");
  }
  {
    const std::string t = table("BLOCK_RECORD", 2);
    record("BLOCK_RECORD", model_record, t, "AcDbBlockTableRecord", "*Model_Space");
    w.Pair(340, model_layout);
    record("BLOCK_RECORD", paper_record, t, "AcDbBlockTableRecord", "*Paper_Space");
    w.Pair(340, paper_layout);
    w.Pair(0, "ENDTAB");
  }
  w.Pair(0, "ENDSEC");

  w.Pair(0, "SECTION");
  w.Pair(2, "BLOCKS");
  for (int paper = 0; paper < 2; ++paper) {
    const std::string& rec = paper ? paper_record : model_record;
    const std::string name = paper ? "*Paper_Space" : "*Model_Space";
    entity("BLOCK", rec, paper, "0", "AcDbBlockBegin");
    w.Pair(2, name);
    w.Pair(70, 0);
    w.Point(10, Vec2<double>::Zero());
    w.Pair(3, name);
    w.Pair(1, "");
    entity("ENDBLK", rec, paper, "0", "AcDbBlockEnd");
  }
  w.Pair(0, "ENDSEC");

  w.Pair(0, "SECTION");
  w.Pair(2, "ENTITIES");
  for (const Entity& e : entities_) {
    auto head = [&](const char* type, const char* subclass) { entity(type, model_record, false, e.layer, subclass); };
    switch (e.kind) {
      case Entity::kChain: {
        head("LWPOLYLINE", "AcDbPolyline");
        const size_t n = e.chain.size() + (e.closed ? 0 : 1);
        w.Pair(90, static_cast<int>(n));
        w.Pair(70, e.closed ? 1 : 0);
        w.Num(43, 0);
        for (size_t i = 0; i < e.chain.size(); ++i) {
          w.Num(10, e.chain[i].start.x());
          w.Num(20, e.chain[i].start.y());
          if (e.chain[i].bulge != 0.0) w.Num(42, e.chain[i].bulge);
        }
        if (!e.closed && !e.chain.empty()) {
          w.Num(10, e.chain.back().end.x());
          w.Num(20, e.chain.back().end.y());
        }
        break;
      }
      case Entity::kCircle:
        head("CIRCLE", "AcDbCircle");
        w.Point(10, e.a);
        w.Num(40, e.value);
        break;
      case Entity::kLine:
        head("LINE", "AcDbLine");
        w.Point(10, e.a);
        w.Point(11, e.b);
        break;
      case Entity::kText:
        head("TEXT", "AcDbText");
        w.Point(10, e.a);
        w.Num(40, e.value);
        w.Pair(1, e.text);
        w.Pair(7, "Standard");
        w.Pair(100, "AcDbText");
        break;
    }
  }
  w.Pair(0, "ENDSEC");

  w.Pair(0, "SECTION");
  w.Pair(2, "OBJECTS");
  auto dictionary = [&](const std::string& h, const std::string& owner,
                        const std::vector<std::pair<std::string, std::string>>& items) {
    w.Pair(0, "DICTIONARY");
    w.Pair(5, h);
    w.Pair(330, owner);
    w.Pair(100, "AcDbDictionary");
    w.Pair(281, 1);
    for (const auto& [key, value] : items) {
      w.Pair(3, key);
      w.Pair(350, value);
    }
  };
  dictionary(root, "0", {{"ACAD_GROUP", group_dict}, {"ACAD_LAYOUT", layout_dict}});
  dictionary(group_dict, root, {});
  dictionary(layout_dict, root, {{"Layout1", paper_layout}, {"Model", model_layout}});
  for (int paper = 0; paper < 2; ++paper) {
    w.Pair(0, "LAYOUT");
    w.Pair(5, paper ? paper_layout : model_layout);
    w.Pair(330, layout_dict);
    w.Pair(100, "AcDbPlotSettings");
    w.Pair(1, "");
    w.Pair(4, "");
    w.Pair(6, "");
    for (int c = 40; c <= 49; ++c) w.Num(c, 0);
    w.Num(140, 0); w.Num(141, 0); w.Num(142, 1); w.Num(143, 1);
    w.Pair(70, paper ? 0 : 1024);
    w.Pair(72, 1);
    w.Pair(73, 0);
    w.Pair(74, 5);
    w.Pair(7, "");
    w.Pair(75, 16);
    w.Num(147, 1); w.Num(148, 0); w.Num(149, 0);
    w.Pair(100, "AcDbLayout");
    w.Pair(1, paper ? "Layout1" : "Model");
    w.Pair(70, 1);
    w.Pair(71, paper ? 1 : 0);
    w.Num(10, 0); w.Num(20, 0); w.Num(11, 420); w.Num(21, 297);
    w.Num(12, 0); w.Num(22, 0); w.Num(32, 0);
    w.Num(14, 0); w.Num(24, 0); w.Num(34, 0);
    w.Num(15, 0); w.Num(25, 0); w.Num(35, 0);
    w.Num(146, 0);
    w.Num(13, 0); w.Num(23, 0); w.Num(33, 0);
    w.Num(16, 1); w.Num(26, 0); w.Num(36, 0);
    w.Num(17, 0); w.Num(27, 1); w.Num(37, 0);
    w.Pair(76, 0);
    w.Pair(330, paper ? paper_record : model_record);
  }
  w.Pair(0, "ENDSEC");
  w.Pair(0, "EOF");

  Out h;
  h.Pair(0, "SECTION");
  h.Pair(2, "HEADER");
  h.Pair(9, "$ACADVER");
  h.Pair(1, "AC1015");
  h.Pair(9, "$DWGCODEPAGE");
  h.Pair(3, "ANSI_1252");
  h.Pair(9, "$INSBASE");
  h.Point(10, Vec2<double>::Zero());
  h.Pair(9, "$INSUNITS");
  h.Pair(70, 4);  // millimetres
  h.Pair(9, "$MEASUREMENT");
  h.Pair(70, 1);  // metric
  h.Pair(9, "$LUNITS");
  h.Pair(70, 2);  // decimal
  h.Pair(9, "$LUPREC");
  h.Pair(70, 4);
  h.Pair(9, "$HANDSEED");
  h.Pair(5, o.Peek());
  h.Pair(0, "ENDSEC");
  std::string file;
  file.reserve(h.str().size() + o.str().size());
  return file.append(h.str()).append(o.str());
}

}  // namespace camopt::cad
