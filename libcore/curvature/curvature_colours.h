// Vertex colours that show where a surface bends (Figure 4.1 of Hamann
// 1991): one curvature quantity mapped through a colour map over a robust
// range, the 2nd to 98th percentile, so a few extreme vertices do not wash
// the picture out. H and K (and k1, k2) use a diverging map centred on zero,
// |k1|+|k2| a sequential one.
#pragma once

#include "../mesh.h"

namespace isoform {

enum class CurvatureQuantity { K1 = 0, K2 = 1, Mean = 2, Gauss = 3, Absolute = 4 };

// The per-vertex values of a quantity (mesh.curvature must be computed).
const std::vector<float>& curvature_values(const Mesh& mesh, CurvatureQuantity q);
const std::vector<float>& curvature_values(const VertexCurvature& c, CurvatureQuantity q);

// The robust range used for the colours: [lo, hi]; symmetric about zero for
// the signed quantities.
void curvature_colour_range(const Mesh& mesh, CurvatureQuantity q, double* lo, double* hi);

// Fills mesh.colors (red, green, blue, alpha per vertex). Vertices flagged
// isolated or failed are grey.
void colour_by_curvature(Mesh& mesh, CurvatureQuantity q);

// Both at once, from the curvature alone: the range into lo, hi and the
// colours into colors (4 per vertex, reused where the size matches).
void curvature_colours(const VertexCurvature& c, CurvatureQuantity q, std::vector<uint8_t>& colors, double* lo,
                       double* hi);

// The colour (red, green, blue, alpha into out[0 .. 3]) of one vertex with
// this value and these flags on the range [lo, hi]: the rule the functions
// above apply to every vertex (four at a time, with the same bits).
void curvature_colour(CurvatureQuantity q, double lo, double hi, float value, uint8_t flags, uint8_t* out);

}  // namespace isoform
