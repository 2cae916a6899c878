// Mesh files: PLY, OBJ and STL, read and written by isoform's own small
// layer rather than OpenMesh's IO. Two reasons decided it: the PLY output must
// carry a per-face `part` int beside the vertex normals, and a save must be
// atomic under our control (temporary file, fsync, rename), which OpenMesh's
// writers, opening the target path themselves, cannot give.
#pragma once

#include <string>

#include "../mesh.h"
#include "../progress.h"

namespace isoform {

// Writes mesh to path in the format named by its extension (.ply, .obj, .stl;
// case-insensitive):
// - PLY: binary little endian; float x y z (double when float would move
//   the mesh's double-precision points: formats.h, points_need_double), then
//   nx ny nz when mesh.normals is not empty, the curvature (k1 k2 mean gauss
//   absolute d1x d1y d1z d2x d2y d2z, uchar curvature_flags) when the mesh
//   has it, uchar red green blue alpha when mesh.colors is not empty, per
//   vertex; uchar/int vertex_indices (and int part when mesh.parts is not
//   empty) per face; an element edge (int vertex1 vertex2) when mesh.edges
//   is not empty.
// - OBJ: v (double precision as for PLY), vn (when normals exist), 1-based f
//   and l lines; parts, curvature and colours are not kept.
// - STL: binary, one facet normal computed from each triangle; vertex normals
//   and parts are not kept.
// The save is atomic: the data go to PATH.tmp-<random> in the same directory,
// which is flushed to disk and renamed over path. On any failure the temporary
// file is removed and an existing path is left untouched.
// Throws InvalidArgument for an unknown extension or an inconsistent mesh
// (array sizes, indices out of range), IoError when writing fails.
void save_mesh(const Mesh& mesh, const std::string& path);
// The same, stopping with Cancelled (the temporary file removed, path left
// untouched) when progress's cancel flag is set while the file is written.
void save_mesh(const Mesh& mesh, const std::string& path, const Progress& progress);

// Reads the mesh at path, choosing the format by extension as save_mesh does.
// Returns points and triangles, and normals when the file gives one per
// vertex (else normals stay empty); a PLY face property `part`, as save_mesh
// writes it, fills parts and part_count. Neighbours, parts of other files and
// statistics are not computed. Polygons are split into triangles
// (polygon_split.h: a convex one into the fan from its first corner).
// - PLY: ascii, binary little or big endian; any scalar types. Everything
//   save_mesh writes is read back, so that a PLY written by isoform and saved
//   again gives the same bytes: double x y z also into precise_points, the
//   curvature group (only when all of it is there), the colour (red green
//   blue, alpha when there, else opaque; floating-point colours from 0 to
//   1), the edge element. Other elements and properties are skipped.
// - OBJ: v, vn, f (a, a/b, a/b/c, a//c, negative indices).
//   Normals are kept only when every vertex has exactly one.
// - STL: binary or ascii; exactly equal corners are welded into one vertex.
// A file with a zero normal (some writers fill the slots with zeros) is read
// as one without normals. A number below a float's normal range in a text
// file is read as the nearest float (0 or subnormal).
// Throws InvalidArgument for an unknown extension, IoError when the file
// cannot be read, FormatError (naming the file and the place) when its
// content is malformed, truncated or not finite.
Mesh load_mesh(const std::string& path);

}  // namespace isoform
