// Whether two triangles of a mesh cross each other beyond the vertices they
// share: the narrow phase of the self-overlap check (mesh_overlap.h).
//
// Orientation predicates in double with a bound on their rounding error: a
// sign inside the bound counts as "in the plane" (or on the line), and only
// overlaps that no rounding can undo are reported. So a mere contact (a
// vertex on another triangle, two triangles touching along an edge, a fold
// at an angle below rounding) is not an overlap; a crossing, however
// shallow, beyond about 1e-14 of the triangles' size is. Two triangles count
// as coplanar when each one's corners lie in the other's plane within the
// bound; those are decided in the projection that drops the larger normal's
// largest axis. By what the triangles share:
// - nothing: an edge of one crosses the other's inside, or (coplanar) their
//   insides overlap;
// - one vertex s: the edge opposite s in one crosses the other's inside, or
//   (coplanar) their wedges at s overlap;
// - an edge: only a fold, both in one plane on the same side of the edge;
// - three vertices: the same triangle twice.
// A degenerate triangle (zero area in double) overlaps nothing here: it is a
// segment or a point, and the triangles around it carry its edges.
#pragma once

#include <array>
#include <cstdint>

namespace isoform::reduce {

using Point3 = std::array<double, 3>;

struct PairOverlap {
  bool overlap = false;
  Point3 near{};  // a point of the intersection, or near it (coplanar cases)
};

// a and b are the corners, ia and ib their mesh vertex indices.
PairOverlap triangles_overlap(const Point3 a[3], const int32_t ia[3], const Point3 b[3], const int32_t ib[3]);
// The same with the normals given: na = triangle_normal(a), nb = triangle_normal(b)
// (for callers that test one triangle against many).
PairOverlap triangles_overlap(const Point3 a[3], const Point3& na, const int32_t ia[3], const Point3 b[3],
                              const Point3& nb, const int32_t ib[3]);
// (t1 - t0) x (t2 - t0).
Point3 triangle_normal(const Point3 t[3]);

// True when a and b certainly do not overlap, by the plane tests that
// triangles_overlap makes first (the corners of one that the other does not
// share strictly on one side of the other's plane), with twice the rounding
// bound of an extent at least the pair's: `extent` >= the largest side of
// the box around both triangles. A side that clears twice the larger bound
// is the side triangles_overlap finds (the factor covers the rounding of the
// extent and of the products' last bits), so true here means no overlap
// there. False decides nothing (call triangles_overlap). For broad phases
// that know the triangles' boxes: most neighbouring pairs end here.
bool certainly_apart(const Point3 a[3], const Point3& na, const int32_t ia[3], const Point3 b[3], const Point3& nb,
                     const int32_t ib[3], double extent);

}  // namespace isoform::reduce
