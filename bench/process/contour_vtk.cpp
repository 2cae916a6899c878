// The VTK peer as a user writes it: read the dense scan into a vtkImageData
// of its own sample type, vtkFlyingEdges3D with normals, write a binary PLY
// with vtkPLYWriter.
//
// usage: contour_vtk IN.raw NX NY NZ u16|f32 SX SY SZ ISOVALUE OUT.ply
#include <vtkFlyingEdges3D.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPLYWriter.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkUnsignedShortArray.h>

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "raw scans are read as they are");

int main(int argc, char** argv) {
  if (argc != 11) {
    std::cerr << "usage: contour_vtk IN.raw NX NY NZ u16|f32 SX SY SZ ISOVALUE OUT.ply\n";
    return 2;
  }
  const int dims[3] = {std::atoi(argv[2]), std::atoi(argv[3]), std::atoi(argv[4])};
  const std::string type = argv[5];
  vtkNew<vtkImageData> image;
  image->SetDimensions(dims[0], dims[1], dims[2]);
  image->SetSpacing(std::atof(argv[6]), std::atof(argv[7]), std::atof(argv[8]));
  vtkSmartPointer<vtkDataArray> scalars;
  if (type == "u16")
    scalars = vtkSmartPointer<vtkUnsignedShortArray>::New();
  else
    scalars = vtkSmartPointer<vtkFloatArray>::New();
  const vtkIdType count = vtkIdType(dims[0]) * dims[1] * dims[2];
  scalars->SetNumberOfTuples(count);
  std::ifstream in(argv[1], std::ios::binary);
  in.read(static_cast<char*>(scalars->GetVoidPointer(0)), std::streamsize(count * (type == "u16" ? 2 : 4)));
  if (!in) {
    std::cerr << "contour_vtk: " << argv[1] << ": cannot read " << count << " samples\n";
    return 1;
  }
  image->GetPointData()->SetScalars(scalars);
  vtkNew<vtkFlyingEdges3D> filter;
  filter->SetInputData(image);
  filter->SetValue(0, std::atof(argv[9]));
  filter->ComputeNormalsOn();
  filter->ComputeGradientsOff();
  filter->ComputeScalarsOff();
  vtkNew<vtkPLYWriter> writer;
  writer->SetInputConnection(filter->GetOutputPort());
  writer->SetFileTypeToBinary();
  writer->SetFileName(argv[10]);
  if (writer->Write() != 1) {
    std::cerr << "contour_vtk: cannot write " << argv[10] << '\n';
    return 1;
  }
  return 0;
}
