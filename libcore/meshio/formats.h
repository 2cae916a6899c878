// The readers and writers behind save_mesh and load_mesh, one pair per
// format. Readers parse a whole file already in memory and name path in
// every error; writers send their bytes to an AtomicFile, which owns the
// file system side. meshio.cpp chooses among them by extension.
#pragma once

#include <string>
#include <string_view>

#include "../mesh.h"
#include "atomic_file.h"

namespace isoform::meshio {

Mesh read_ply(std::string_view bytes, const std::string& path);
Mesh read_obj(std::string_view bytes, const std::string& path);
Mesh read_stl(std::string_view bytes, const std::string& path);

// The writers expect a mesh that save_mesh has checked: whole triples,
// indices in range, normals and parts absent or complete.
void write_ply(const Mesh& mesh, AtomicFile& file);
void write_obj(const Mesh& mesh, AtomicFile& file);
void write_stl(const Mesh& mesh, AtomicFile& file);

// Points are written as float unless the mesh has double-precision points
// that rounding to float would move by more than a millionth of the mesh's
// extent (a scan far from the origin, say): then PLY and OBJ write those,
// so that what was read in double is not lost.
bool points_need_double(const Mesh& mesh);

}  // namespace isoform::meshio
