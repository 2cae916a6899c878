// VTK's vtkCurvatures: the angle-deficit Gaussian curvature and the
// dihedral-angle mean curvature, one filter run each; k1 and k2 from them as
// H +- sqrt(H^2 - K), as vtkCurvatures' own maximum and minimum types do.
// The filter is serial. VTK's mean curvature assumes outward normals, the
// truth meshes' orientation, so its sign is isoform's.
#include <vtkCellArray.h>
#include <vtkCurvatures.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkIdTypeArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "curvature_bench.h"

namespace isoform_curvature_bench {
namespace {

vtkSmartPointer<vtkPolyData> poly_data(const Case& c) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(vtkIdType(c.vertex_count()));
  for (size_t v = 0; v < c.vertex_count(); ++v) points->SetPoint(vtkIdType(v), &c.points[3 * v]);
  const size_t m = c.triangles.size() / 3;
  auto offsets = vtkSmartPointer<vtkIdTypeArray>::New();
  auto connectivity = vtkSmartPointer<vtkIdTypeArray>::New();
  offsets->SetNumberOfValues(vtkIdType(m + 1));
  connectivity->SetNumberOfValues(vtkIdType(3 * m));
  for (size_t t = 0; t <= m; ++t) offsets->SetValue(vtkIdType(t), vtkIdType(3 * t));
  for (size_t i = 0; i < 3 * m; ++i) connectivity->SetValue(vtkIdType(i), c.triangles[i]);
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  cells->SetData(offsets, connectivity);
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetPolys(cells);
  return poly;
}

// One filter run; returns the output's per-point array.
vtkSmartPointer<vtkDataArray> curvature(vtkPolyData* input, int type, const char* array) {
  auto filter = vtkSmartPointer<vtkCurvatures>::New();
  filter->SetInputData(input);
  filter->SetCurvatureType(type);
  filter->Update();
  vtkDataArray* a = filter->GetOutput()->GetPointData()->GetArray(array);
  if (!a) throw std::runtime_error(std::string("vtkCurvatures gave no ") + array);
  return a;
}

}  // namespace

void run_vtk(const Case& c, const Options& o, std::vector<Result>& out) {
  Result r;
  r.method = "VTK vtkCurvatures";
  const Clock::time_point t = Clock::now();
  vtkSmartPointer<vtkPolyData> poly = poly_data(c);
  r.setup_seconds = seconds_since(t);
  r.setup_what = "vtkPolyData from the arrays";
  vtkSmartPointer<vtkDataArray> h, k;
  r.one = best_of(o.peer_reps, [&] {
    h = curvature(poly, VTK_CURVATURE_MEAN, "Mean_Curvature");
    k = curvature(poly, VTK_CURVATURE_GAUSS, "Gauss_Curvature");
  });
  Curvatures res;
  const size_t n = c.vertex_count();
  for (auto* v : {&res.k1, &res.k2, &res.mean, &res.gauss}) v->resize(n);
  for (size_t v = 0; v < n; ++v) {
    const double hv = h->GetTuple1(vtkIdType(v)), kv = k->GetTuple1(vtkIdType(v));
    const double disc = std::sqrt(std::max(0.0, hv * hv - kv));
    res.mean[v] = float(hv);
    res.gauss[v] = float(kv);
    res.k1[v] = float(hv + disc);
    res.k2[v] = float(hv - disc);
  }
  r.rms = rms_of(c, res);
  out.push_back(r);
}

}  // namespace isoform_curvature_bench
