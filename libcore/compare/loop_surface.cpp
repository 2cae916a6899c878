// The Loop limit surface through OpenSubdiv's Far layer: a TopologyRefiner
// with SCHEME_LOOP refined adaptively, a PatchTable with Gregory end caps in
// double precision, the refined and local points computed once, and
// PatchMap::FindPatch + EvaluateBasis per sample (position, first and second
// derivatives with respect to the base face's parameters).
#include "loop_surface.h"

#include <cmath>
#include <mutex>
#include <vector>

#include <opensubdiv/far/error.h>
#include <opensubdiv/far/patchMap.h>
#include <opensubdiv/far/patchTable.h>
#include <opensubdiv/far/patchTableFactory.h>
#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>

namespace isoform::compare {
namespace {

namespace Far = OpenSubdiv::Far;
namespace Sdc = OpenSubdiv::Sdc;

// A control point as PrimvarRefiner and the stencil tables want it.
struct Point {
  double p[3];
  void Clear(void* = nullptr) { p[0] = p[1] = p[2] = 0.0; }
  void AddWithWeight(const Point& src, double w) {
    p[0] += w * src.p[0];
    p[1] += w * src.p[1];
    p[2] += w * src.p[2];
  }
};

// OpenSubdiv reports through global callbacks (printing by default). They
// are redirected once to a thread-local message, read after each build.
thread_local std::string osd_message;
void on_error(Far::ErrorType, const char* message) {
  if (!osd_message.empty()) osd_message += "; ";
  osd_message += message;
}
void on_warning(const char*) {}
void install_callbacks() {
  static std::once_flag once;
  std::call_once(once, [] {
    Far::SetErrorCallback(on_error);
    Far::SetWarningCallback(on_warning);
  });
}

// The topology check OpenSubdiv does not make for us: every index in range.
bool check_mesh(const Mesh& mesh, std::string& error) {
  if (mesh.triangle_count() == 0) {
    error = "the mesh has no triangles";
    return false;
  }
  const auto n = int32_t(mesh.vertex_count());
  for (int32_t v : mesh.triangles)
    if (v < 0 || v >= n) {
      error = "triangle vertex index " + std::to_string(v) + " is out of range (" + std::to_string(n) + " vertices)";
      return false;
    }
  return true;
}

Far::TopologyRefiner* make_refiner(const Mesh& mesh, const LoopOptions& options) {
  const std::vector<int> per_face(mesh.triangle_count(), 3);
  Far::TopologyDescriptor desc;
  desc.numVertices = int(mesh.vertex_count());
  desc.numFaces = int(mesh.triangle_count());
  desc.numVertsPerFace = per_face.data();
  desc.vertIndicesPerFace = mesh.triangles.data();
  Sdc::Options sdc;
  sdc.SetVtxBoundaryInterpolation(options.sharp_corners ? Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER
                                                        : Sdc::Options::VTX_BOUNDARY_EDGE_ONLY);
  using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
  return Factory::Create(desc, Factory::Options(Sdc::SCHEME_LOOP, sdc));
}

double base_coordinate(const Mesh& mesh, size_t i) {
  return mesh.precise_points.size() == mesh.points.size() ? mesh.precise_points[i] : double(mesh.points[i]);
}

class LoopSurface : public TriangleSurface {
 public:
  LoopSurface(std::unique_ptr<Far::TopologyRefiner> refiner, std::unique_ptr<Far::PatchTable> table,
              std::vector<Point> points)
      : refiner_(std::move(refiner)), table_(std::move(table)), map_(*table_), points_(std::move(points)),
        faces_(size_t(refiner_->GetLevel(0).GetNumFaces())) {}

  size_t triangle_count() const override { return faces_; }

  bool evaluate(size_t triangle, double u, double v, SurfaceSample& out) const override {
    if (triangle >= faces_ || !(u >= 0.0 && v >= 0.0 && u + v <= 1.0 + 1e-12)) return false;
    const Far::PatchTable::PatchHandle* handle = map_.FindPatch(int(triangle), u, v);
    if (!handle) return false;
    // 20 is the largest patch (a quad Gregory); triangles use at most 18.
    double w[6][20];
    table_->EvaluateBasis(*handle, u, v, w[0], w[1], w[2], w[3], w[4], w[5]);
    const Far::ConstIndexArray cvs = table_->GetPatchVertices(*handle);
    std::array<double, 3>* outs[6] = {&out.point, &out.du, &out.dv, &out.duu, &out.duv, &out.dvv};
    for (int d = 0; d < 6; ++d) {
      std::array<double, 3>& r = *outs[d];
      r = {0.0, 0.0, 0.0};
      for (int i = 0; i < cvs.size(); ++i)
        for (int c = 0; c < 3; ++c) r[c] += w[d][i] * points_[size_t(cvs[i])].p[c];
    }
    // NOTE: OpenSubdiv 3.5 scales the second derivatives of a rotated
    // (centre) sub-triangle by -4^depth instead of +4^depth: the parameter
    // map of a rotated triangle is (u, v) -> (1 - u, 1 - v) scaled, whose
    // second-order factor is the square of -2^depth. Undone here; the test
    // DerivativesMatchDifferences checks it against differences of du, dv.
    if (table_->GetPatchParam(*handle).IsTriangleRotated())
      for (std::array<double, 3>* d : {&out.duu, &out.duv, &out.dvv})
        for (double& c : *d) c = -c;
    // NOTE: OpenSubdiv 3.5 differentiates its Gregory triangles (the end
    // caps around irregular vertices) approximately: the rational interior
    // points are held fixed. First derivatives are still exact at the patch
    // corners (the base vertices), where those points have no weight, and
    // off by a few percent inside (test DerivativesInGregoryEndCaps); second
    // derivatives are not the surface's anywhere there, so they are not
    // offered. At isolation L the end caps reach 2^-L of an edge from a vertex.
    out.has_second = table_->GetPatchDescriptor(*handle).GetType() != Far::PatchDescriptor::GREGORY_TRIANGLE;
    return unit_normal(out);
  }

 private:
  static bool unit_normal(SurfaceSample& s) {
    const auto& a = s.du;
    const auto& b = s.dv;
    const std::array<double, 3> n = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(len > 0.0) || !std::isfinite(len)) return false;
    s.normal = {n[0] / len, n[1] / len, n[2] / len};
    return true;
  }

  std::unique_ptr<Far::TopologyRefiner> refiner_;
  std::unique_ptr<Far::PatchTable> table_;
  Far::PatchMap map_;
  std::vector<Point> points_;  // refined vertices of every level, then local points
  size_t faces_;
};

// Refined vertices of levels 1.. and the patch table's local points, from
// the base points.
std::vector<Point> control_points(const Mesh& mesh, const Far::TopologyRefiner& refiner,
                                  const Far::PatchTable& table) {
  const size_t refined = size_t(refiner.GetNumVerticesTotal());
  std::vector<Point> points(refined + size_t(table.GetNumLocalPoints()));
  for (size_t v = 0; v < mesh.vertex_count(); ++v)
    for (int c = 0; c < 3; ++c) points[v].p[c] = base_coordinate(mesh, 3 * v + size_t(c));
  Far::PrimvarRefinerReal<double> primvar(refiner);
  Point* src = points.data();
  for (int level = 1; level <= refiner.GetMaxLevel(); ++level) {
    Point* dst = src + refiner.GetLevel(level - 1).GetNumVertices();
    primvar.Interpolate(level, src, dst);
    src = dst;
  }
  // NOTE: PatchTable::ComputeLocalPointValues always reads float stencils;
  // the double-precision table built here is applied directly.
  if (const auto* stencils = table.GetLocalPointStencilTable<double>())
    stencils->UpdateValues(points.data(), points.data() + refined);
  return points;
}

}  // namespace

std::unique_ptr<TriangleSurface> make_loop_surface(const Mesh& mesh, const LoopOptions& options,
                                                   std::string& error) {
  if (!check_mesh(mesh, error)) return nullptr;
  if (options.isolation < 1 || options.isolation > 10) {
    error = "Loop isolation level " + std::to_string(options.isolation) + " is not 1..10";
    return nullptr;
  }
  install_callbacks();
  osd_message.clear();
  std::unique_ptr<Far::TopologyRefiner> refiner(make_refiner(mesh, options));
  if (!refiner) {
    error = "OpenSubdiv refused the topology" + (osd_message.empty() ? "" : ": " + osd_message);
    return nullptr;
  }
  Far::PatchTableFactory::Options patch_options(unsigned(options.isolation));
  patch_options.SetEndCapType(Far::PatchTableFactory::Options::ENDCAP_GREGORY_BASIS);
  patch_options.SetPatchPrecision<double>();
  patch_options.generateVaryingTables = false;
  refiner->RefineAdaptive(patch_options.GetRefineAdaptiveOptions());
  std::unique_ptr<Far::PatchTable> table(Far::PatchTableFactory::Create(*refiner, patch_options));
  if (!table || !osd_message.empty()) {
    error = "OpenSubdiv could not build the Loop patches" + (osd_message.empty() ? "" : ": " + osd_message);
    return nullptr;
  }
  std::vector<Point> points = control_points(mesh, *refiner, *table);
  return std::make_unique<LoopSurface>(std::move(refiner), std::move(table), std::move(points));
}

}  // namespace isoform::compare
