// The `measure` child for VTK's vtkFlyingEdges3D on a dense scan. Built only
// when CMake finds VTK.
#include <vtkFlyingEdges3D.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSMPTools.h>
#include <vtkUnsignedShortArray.h>
#include <vtkVersion.h>

#include "bench.h"

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__,
              "raw scans are little-endian and read into VTK arrays as they are");

namespace isoform_bench {

namespace {

// Flying Edges runs on the scan's own sample type, as a VTK user would load
// it; the file is read straight into the VTK array, so no second copy adds
// to the peak.
vtkSmartPointer<vtkImageData> load_image(const RawLayout& layout) {
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(layout.dims[0], layout.dims[1], layout.dims[2]);
  image->SetSpacing(layout.spacing[0], layout.spacing[1], layout.spacing[2]);
  vtkSmartPointer<vtkDataArray> scalars;
  if (layout.type == "u16")
    scalars = vtkSmartPointer<vtkUnsignedShortArray>::New();
  else
    scalars = vtkSmartPointer<vtkFloatArray>::New();
  scalars->SetNumberOfTuples(vtkIdType(layout.sample_count()));
  read_raw_into(layout, static_cast<char*>(scalars->GetVoidPointer(0)));
  image->GetPointData()->SetScalars(scalars);
  return image;
}

}  // namespace

Json measure_flying_edges(const Request& request) {
  vtkSMPTools::Initialize(kThreads);
  const Clock::time_point start = Clock::now();
  const vtkSmartPointer<vtkImageData> image = load_image(request.raw);
  const double load_ms = ms_between(start, Clock::now());
  const long long peak_after_load = peak_rss_kb();

  double first_ms = 0.0;
  std::vector<double> timed;
  vtkIdType points = 0, triangles = 0;
  for (int call = 0; call <= request.reps; ++call) {
    // A new filter per call: a re-executed filter would hold its previous
    // output while it builds the next, which the other methods do not.
    vtkNew<vtkFlyingEdges3D> filter;
    filter->SetInputData(image);
    filter->SetValue(0, request.iso);
    // Normals on (isoform makes them too), no interpolated scalars.
    filter->ComputeNormalsOn();
    filter->ComputeGradientsOff();
    filter->ComputeScalarsOff();
    const Clock::time_point t = Clock::now();
    filter->Update();
    const double ms = ms_between(t, Clock::now());
    if (call == 0)
      first_ms = ms;
    else
      timed.push_back(ms);
    points = filter->GetOutput()->GetNumberOfPoints();
    triangles = filter->GetOutput()->GetNumberOfPolys();
  }

  Json out = timing_json(load_ms, first_ms, timed);
  out["load_note"] = "raw file into a vtkImageData of the scan's sample type";
  out["samples"] = request.raw.sample_count();
  out["mesh"] = Json{{"points", points}, {"triangles", triangles}};
  out["vtk_version"] = vtkVersion::GetVTKVersion();
  out["smp_backend"] = vtkSMPTools::GetBackend();
  out["peak_after_load_kb"] = peak_after_load;
  out["peak_kb"] = peak_rss_kb();
  return out;
}

}  // namespace isoform_bench
