// The OpenCASCADE half of cad/solid.h, built as the module libcamopt_occt.so that cad/solid.cc
// loads on first use (cad/occt_module.h): OCCT's 60-odd shared libraries then cost a process
// nothing until a part needs the kernel (docs/performance.md, "A process's start"). Only this file
// includes OCCT headers.
#include "cad/occt_module.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <tuple>

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepGProp.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <GC_MakeArcOfCircle.hxx>
#include <GC_MakeSegment.hxx>
#include <GProp_GProps.hxx>
#include <GeomAPI_PointsToBSplineSurface.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Interface_Static.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Poly_Triangulation.hxx>
#include <STEPCAFControl_Reader.hxx>
#include <STEPControl_Reader.hxx>
#include <TDF_LabelSequence.hxx>
#include <TDataStd_Name.hxx>
#include <TDocStd_Document.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>
#include <Standard_Failure.hxx>
#include <STEPControl_Writer.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Circ.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>

namespace camopt::cad {

namespace {

// OCCT prints transfer statistics to stdout by default; camopt's stdout is its own.
void SilenceOcct() {
  static const bool done = [] {
    Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_Printer));
    return true;
  }();
  (void)done;
}

gp_Pnt P(const Vec2<double>& v, double z = 0.0) { return gp_Pnt(v.x(), v.y(), z); }

// The chain of arcs as a wire of arc edges (one lateral face per arc). Joining them into one
// B-spline edge gives a file five times smaller, but OCCT 7.6's BRepGProp then misjudges the
// solid's volume by 10-20 % (its mesh volume stays right), so a reader could not check it.
TopoDS_Wire WireOf(const std::vector<ArcSegment>& chain) {
  BRepBuilderAPI_MakeWire wire;
  for (const ArcSegment& a : chain) {
    TopoDS_Edge edge;
    if (std::abs(a.bulge) < 1e-12) {
      edge = BRepBuilderAPI_MakeEdge(GC_MakeSegment(P(a.start), P(a.end)).Value()).Edge();
    } else {
      edge = BRepBuilderAPI_MakeEdge(GC_MakeArcOfCircle(P(a.start), P(PointOnArc(a, 0.5)), P(a.end)).Value())
                 .Edge();
    }
    wire.Add(edge);
    if (!wire.IsDone()) throw std::runtime_error("OCCT: the profile's arcs do not join into a wire");
  }
  return wire.Wire();
}

// Writes a shape to STEP AP214 in memory with a fixed time stamp.
std::string StepOf(const TopoDS_Shape& shape, const std::string& raw_name) {
  SilenceOcct();
  // OCCT gets a plain placeholder; the name enters the text below, encoded as a STEP string.
  const std::string name = StepString(raw_name);
  Interface_Static::SetCVal("write.step.schema", "AP214IS");
  Interface_Static::SetCVal("write.step.unit", "MM");
  Interface_Static::SetCVal("write.step.product.name", "camopt part");
  STEPControl_Writer writer;
  if (writer.Transfer(shape, STEPControl_AsIs) != IFSelect_RetDone)
    throw std::runtime_error("OCCT: STEP transfer failed");
  char tmpl[] = "/tmp/camopt-step-XXXXXX";
  const int fd = mkstemp(tmpl);
  if (fd < 0) throw std::runtime_error("cannot create a temporary file for STEP output");
  close(fd);
  const std::string tmp = tmpl;
  const IFSelect_ReturnStatus st = writer.Write(tmp.c_str());
  std::ifstream in(tmp, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  std::filesystem::remove(tmp);
  if (st != IFSelect_RetDone) throw std::runtime_error("OCCT: STEP write failed");
  std::string s = buffer.str();
  // FILE_NAME('name','time stamp',...): the time stamp becomes fixed, so that one study gives
  // the same bytes on every run; the file name becomes the product name.
  const size_t fn = s.find("FILE_NAME(");
  if (fn != std::string::npos) {
    const size_t q1 = s.find('\'', fn), q2 = s.find('\'', q1 + 1);
    const size_t q3 = s.find('\'', q2 + 1), q4 = s.find('\'', q3 + 1);
    if (q4 != std::string::npos) {
      s.replace(q3 + 1, q4 - q3 - 1, "2000-01-01T00:00:00");
      s.replace(q1 + 1, q2 - q1 - 1, name);
    }
  }
  // PRODUCT('name','description',...): OCCT 7.6 appends a process-wide counter to the product name
  // ("cam 2", "cam 10"), so the bytes depended on how many files the process had written before
  // (a sweep's cases, in thread order). Both strings become the name, unfolded.
  const size_t pr = s.find("= PRODUCT('");
  if (pr != std::string::npos) {
    const size_t a1 = s.find('\'', pr), a2 = s.find('\'', a1 + 1);
    const size_t b1 = s.find('\'', a2 + 1), b2 = s.find('\'', b1 + 1);
    if (b2 != std::string::npos && s.find_first_not_of(", \n", a2 + 1) == b1) {
      s.replace(a1, b2 + 1 - a1, "'" + name + "','" + name + "'");
    }
  }
  return s;
}

// Triangles of every face, vertices merged where their coordinates are equal, oriented outward.
TriangleMesh MeshOf(const TopoDS_Shape& shape, double deflection) {
  BRepMesh_IncrementalMesh mesher(shape, deflection, Standard_False, 0.1, Standard_False);
  TriangleMesh mesh;
  std::map<std::tuple<double, double, double>, int> index;
  auto vertex = [&](const gp_Pnt& p) {
    const auto key = std::make_tuple(p.X(), p.Y(), p.Z());
    const auto [it, inserted] = index.emplace(key, static_cast<int>(mesh.vertices.size()));
    if (inserted) mesh.vertices.emplace_back(p.X(), p.Y(), p.Z());
    return it->second;
  };
  for (TopExp_Explorer ex(shape, TopAbs_FACE); ex.More(); ex.Next()) {
    const TopoDS_Face& face = TopoDS::Face(ex.Current());
    TopLoc_Location loc;
    const Handle(Poly_Triangulation) tri = BRep_Tool::Triangulation(face, loc);
    if (tri.IsNull()) throw std::runtime_error("OCCT: a face has no triangulation");
    const bool reversed = face.Orientation() == TopAbs_REVERSED;
    std::vector<int> ids(tri->NbNodes() + 1);
    for (int i = 1; i <= tri->NbNodes(); ++i) ids[i] = vertex(tri->Node(i).Transformed(loc.Transformation()));
    for (int t = 1; t <= tri->NbTriangles(); ++t) {
      int a, b, c;
      tri->Triangle(t).Get(a, b, c);
      if (reversed) std::swap(b, c);
      if (ids[a] == ids[b] || ids[b] == ids[c] || ids[a] == ids[c]) continue;
      mesh.triangles.push_back({ids[a], ids[b], ids[c]});
    }
  }
  return mesh;
}

// The OCCT mesh of the extruded solid: for a profile that MeshExtrusion cannot triangulate (not
// star-shaped about the cam's centre).
TriangleMesh OcctMeshUnguarded(const Extrusion& e) {
  SilenceOcct();
  BRepBuilderAPI_MakeFace face_maker(WireOf(e.profile), Standard_True);
  if (!face_maker.IsDone()) throw std::runtime_error("OCCT: no planar face on the cam profile");
  TopoDS_Face face = face_maker.Face();
  if (e.bore_diameter_mm > 0) {
    TopoDS_Wire w;
    if (e.keyway_width_mm > 0) {
      w = WireOf(BoreChain(e));
    } else {
      gp_Circ circle(gp_Ax2(P(e.bore_centre), gp::DZ()), 0.5 * e.bore_diameter_mm);
      w = BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(circle).Edge()).Wire();
    }
    w.Reverse();  // inner wire: clockwise seen from +z
    BRepBuilderAPI_MakeFace with_hole(face, w);
    if (!with_hole.IsDone()) throw std::runtime_error("OCCT: the bore does not fit the cam face");
    face = with_hole.Face();
  }
  for (const Hole& h : e.holes) {
    gp_Circ circle(gp_Ax2(P(h.centre), gp::DZ()), 0.5 * h.diameter_mm);
    BRepBuilderAPI_MakeWire hole(BRepBuilderAPI_MakeEdge(circle).Edge());
    TopoDS_Wire w = hole.Wire();
    w.Reverse();
    BRepBuilderAPI_MakeFace with_hole(face, w);
    if (!with_hole.IsDone()) throw std::runtime_error("OCCT: a hole does not fit the cam face");
    face = with_hole.Face();
  }
  BRepPrimAPI_MakePrism prism(face, gp_Vec(0, 0, e.thickness_mm));
  if (!prism.IsDone()) throw std::runtime_error("OCCT: extrusion failed");
  const TopoDS_Shape solid = prism.Shape();
  if (!BRepCheck_Analyzer(solid).IsValid()) throw std::runtime_error("OCCT: the extruded cam is not a valid solid");
  return MeshOf(solid, MeshDeflection(e));
}

SurfaceOutput BSplineSurfacesUnguarded(const std::vector<PointGrid>& grids, const std::string& name,
                                        double tolerance_mm) {
  SilenceOcct();
  SurfaceOutput out;
  BRep_Builder builder;
  TopoDS_Compound compound;
  builder.MakeCompound(compound);
  for (const PointGrid& g : grids) {
    const int nu = static_cast<int>(g.size()), nv = nu ? static_cast<int>(g[0].size()) : 0;
    if (nu < 2 || nv < 2) continue;
    TColgp_Array2OfPnt pts(1, nu, 1, nv);
    for (int i = 0; i < nu; ++i)
      for (int j = 0; j < nv; ++j) pts.SetValue(i + 1, j + 1, gp_Pnt(g[i][j].x(), g[i][j].y(), g[i][j].z()));
    GeomAPI_PointsToBSplineSurface fit;
    fit.Init(pts, 3, 3, GeomAbs_C2, tolerance_mm);
    if (!fit.IsDone()) throw std::runtime_error("OCCT: B-spline surface fit failed");
    const Handle(Geom_BSplineSurface) surface = fit.Surface();
    const TopoDS_Face face = BRepBuilderAPI_MakeFace(surface, 1e-7).Face();
    builder.Add(compound, face);
    GProp_GProps area;
    BRepGProp::SurfaceProperties(face, area, 1e-9);
    out.area_mm2 += area.Mass();
    ++out.faces;
  }
  out.step = StepOf(compound, name);
  return out;
}

StepReadBack ReadStepUnguarded(const std::string& content) {
  SilenceOcct();
  StepReadBack r;
  STEPControl_Reader reader;
  std::istringstream in(content);
  if (reader.ReadStream("camopt.step", in) != IFSelect_RetDone) return r;
  reader.TransferRoots();
  const TopoDS_Shape shape = reader.OneShape();
  if (shape.IsNull()) return r;
  for (TopExp_Explorer ex(shape, TopAbs_SOLID); ex.More(); ex.Next()) ++r.solids;
  for (TopExp_Explorer ex(shape, TopAbs_SHELL); ex.More(); ex.Next()) ++r.shells;
  for (TopExp_Explorer ex(shape, TopAbs_FACE); ex.More(); ex.Next()) ++r.faces;
  GProp_GProps vol, area;
  BRepGProp::VolumeProperties(shape, vol, 1e-9);
  BRepGProp::SurfaceProperties(shape, area, 1e-9);
  r.volume_mm3 = vol.Mass();
  r.area_mm2 = area.Mass();
  r.valid = BRepCheck_Analyzer(shape).IsValid();
  return r;
}

std::string NameOf(const TDF_Label& label) {
  Handle(TDataStd_Name) attr;
  if (!label.FindAttribute(TDataStd_Name::GetID(), attr)) return "";
  const TCollection_ExtendedString& ext = attr->Get();
  std::string out;
  for (int i = 1; i <= ext.Length(); ++i) {
    const Standard_ExtCharacter ch = ext.Value(i);
    out += ch < 0x80 ? char(ch) : '?';
  }
  return out;
}

AssemblyReadBack ReadStepAssemblyUnguarded(const std::string& content) {
  SilenceOcct();
  AssemblyReadBack r;
  Handle(TDocStd_Document) doc;
  XCAFApp_Application::GetApplication()->NewDocument("MDTV-XCAF", doc);
  STEPCAFControl_Reader reader;
  reader.SetNameMode(true);
  std::istringstream in(content);
  if (reader.ChangeReader().ReadStream("camopt.step", in) != IFSelect_RetDone) return r;
  if (!reader.Transfer(doc)) return r;
  r.read = true;
  const Handle(XCAFDoc_ShapeTool) tool = XCAFDoc_DocumentTool::ShapeTool(doc->Main());
  TDF_LabelSequence free;
  tool->GetFreeShapes(free);
  if (free.Length() != 1) return r;
  const TDF_Label top = free.Value(1);
  r.name = NameOf(top);
  r.assembly = XCAFDoc_ShapeTool::IsAssembly(top);
  TDF_LabelSequence components;
  XCAFDoc_ShapeTool::GetComponents(top, components, false);
  for (int i = 1; i <= components.Length(); ++i) {
    const TDF_Label comp = components.Value(i);
    AssemblyComponent c;
    c.name = NameOf(comp);
    TDF_Label part;
    if (XCAFDoc_ShapeTool::GetReferredShape(comp, part)) c.part = NameOf(part);
    const gp_Trsf trsf = XCAFDoc_ShapeTool::GetLocation(comp).Transformation();
    const gp_XYZ o = trsf.TranslationPart();
    c.origin = Eigen::Vector3d(o.X(), o.Y(), o.Z());
    const gp_Dir x = gp::DX().Transformed(trsf), z = gp::DZ().Transformed(trsf);
    c.angle_rad = std::atan2(x.Y(), x.X());
    c.axis_tilt = z.Angle(gp::DZ());
    const TopoDS_Shape placed = XCAFDoc_ShapeTool::GetShape(comp);
    GProp_GProps vol;
    BRepGProp::VolumeProperties(placed, vol, 1e-9);
    c.volume_mm3 = vol.Mass();
    const gp_Pnt g = vol.CentreOfMass();
    c.centroid = Eigen::Vector3d(g.X(), g.Y(), g.Z());
    r.components.push_back(c);
  }
  doc->Close();
  return r;
}

// OCCT reports failures as Standard_Failure, which is not a std::exception: turned into one here,
// so that camopt reports them (exit 1, a defect: the inputs were checked) instead of terminating.
// OCCT's STEP translator keeps its settings and controller in process-wide statics
// (Interface_Static, STEPControl_Controller), so two threads of a sweep writing STEP at once made
// the transfer fail (seen under ASan timing in CI). Every OCCT call of this file holds one lock.
std::mutex& OcctMutex() {
  static std::mutex m;
  return m;
}

template <typename F>
auto Guarded(const char* what, F f) {
  const std::lock_guard<std::mutex> lock(OcctMutex());
  try {
    return f();
  } catch (const Standard_Failure& failure) {
    throw std::runtime_error(std::string("OCCT: ") + what + ": " + failure.GetMessageString());
  }
}

TriangleMesh OcctExtrusionMesh(const Extrusion& e) {
  return Guarded("extruded cam", [&] { return OcctMeshUnguarded(e); });
}

SurfaceOutput OcctBSplineSurfaces(const std::vector<PointGrid>& grids, const std::string& name, double tolerance_mm) {
  return Guarded("B-spline surfaces", [&] { return BSplineSurfacesUnguarded(grids, name, tolerance_mm); });
}

double OcctMaxDistanceToStepFaces(const std::string& content, const std::vector<Eigen::Vector3d>& points) {
  return Guarded("STEP distances", [&] {
    SilenceOcct();
    STEPControl_Reader reader;
    std::istringstream in(content);
    if (reader.ReadStream("camopt.step", in) != IFSelect_RetDone) return double(INFINITY);
    reader.TransferRoots();
    const TopoDS_Shape shape = reader.OneShape();
    // One projector per face, its search structure built once (Init), then Perform per point.
    std::vector<std::unique_ptr<GeomAPI_ProjectPointOnSurf>> projectors;
    for (TopExp_Explorer ex(shape, TopAbs_FACE); ex.More(); ex.Next()) {
      const Handle(Geom_Surface) surface = BRep_Tool::Surface(TopoDS::Face(ex.Current()));
      double u0 = 0, u1 = 0, v0 = 0, v1 = 0;
      surface->Bounds(u0, u1, v0, v1);
      projectors.push_back(std::make_unique<GeomAPI_ProjectPointOnSurf>());
      projectors.back()->Init(surface, u0, u1, v0, v1);
    }
    if (projectors.empty()) return double(INFINITY);
    double worst = 0.0;
    for (const Eigen::Vector3d& p : points) {
      double best = INFINITY;
      for (const auto& projection : projectors) {
        projection->Perform(gp_Pnt(p.x(), p.y(), p.z()));
        if (projection->NbPoints() > 0) best = std::min(best, projection->LowerDistance());
      }
      worst = std::max(worst, best);
    }
    return worst;
  });
}

StepReadBack OcctReadStep(const std::string& content) {
  return Guarded("STEP read", [&] { return ReadStepUnguarded(content); });
}

AssemblyReadBack OcctReadStepAssembly(const std::string& content) {
  return Guarded("STEP assembly read", [&] { return ReadStepAssemblyUnguarded(content); });
}

const OcctFunctions kFunctions{kOcctModuleVersion, &OcctExtrusionMesh, &OcctBSplineSurfaces,
                               &OcctMaxDistanceToStepFaces, &OcctReadStep, &OcctReadStepAssembly};

}  // namespace
}  // namespace camopt::cad

extern "C" __attribute__((visibility("default"))) const camopt::cad::OcctFunctions* camopt_occt_functions() {
  return &camopt::cad::kFunctions;
}
