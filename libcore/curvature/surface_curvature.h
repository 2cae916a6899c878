// Section 4.2 of Hamann (1991): principal curvatures at the vertices of a
// triangulated surface, from a height field fitted over each vertex's
// platelet in the tangent plane of its normal (steps (i) to (viii)).
#pragma once

#include "../mesh.h"
#include "../progress.h"
#include "vertex_curvature.h"

namespace isoform {

struct CurvatureOptions {
  CurvatureMethod method = CurvatureMethod::Quartic;
  int extra_rings = 0;  // rings added to the method's platelet, 0..8 (noisy meshes)
  bool update_normals = false;  // replace mesh.normals by the fitted surfaces' normals
  int threads = 0;      // 0 = all cores, 1 = serial
};

// Fills mesh.curvature from mesh.points, mesh.triangles and mesh.normals
// (which orient the result: see principal.h for the sign). Every vertex gets
// a finite result; where the method's fit cannot be used the vertex is
// widened, lowered or flagged (vertex_curvature.h). Deterministic: the same
// mesh gives the same bits for any thread count. Throws InvalidArgument for
// a mesh whose normals do not match its vertices, Cancelled when progress
// asks; the mesh is unchanged on failure.
void compute_curvature(Mesh& mesh, const CurvatureOptions& options, const Progress& progress);

// The same without touching the mesh: the results into out, whose arrays
// are reused where their sizes already match, and with update_normals the
// fitted normals (3 per vertex) into *fitted_normals. out is unspecified
// after a throw.
void compute_curvature(const Mesh& mesh, const CurvatureOptions& options, const Progress& progress,
                       VertexCurvature& out, std::vector<float>* fitted_normals);

// The name of a method ("seed", "quadric", "cubic", "quartic") and back
// (false for an unknown name).
const char* curvature_method_name(CurvatureMethod method);
bool parse_curvature_method(const char* name, CurvatureMethod* out);

}  // namespace isoform
