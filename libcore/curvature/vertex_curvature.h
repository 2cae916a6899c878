// The per-vertex curvature arrays a mesh carries once Chapter 4 has run on
// it, and what happened at vertices where the chosen fit could not be used.
#pragma once

#include <cstdint>
#include <vector>

namespace isoform {

enum class CurvatureMethod {
  Seed = 0,     // the seed's fit (4.28): 3 quadratic terms over the one-ring, normals as given
  Quadric = 1,  // linear and quadratic terms over the one-ring
  Cubic = 2,    // up to cubic terms over the two-ring
  Quartic = 3   // up to quartic terms over the three-ring (the default)
};

// Bits of VertexCurvature::flags.
enum CurvatureFlag : uint8_t {
  kCurvatureBoundary = 1,      // a boundary vertex: the fit took one more ring
  kCurvatureWidened = 2,       // too few or badly placed points: more rings taken
  kCurvatureLowerOrder = 4,    // even the widest ring could not carry the model: a lower one used
  kCurvatureNonmanifold = 8,   // the vertex's triangles are not one fan
  kCurvatureIsolated = 16,     // no triangle uses the vertex: curvature 0
  kCurvatureFailed = 32,       // no fit was possible: curvature 0
  kCurvatureNormalRepaired = 64  // the given normal was unusable: one from the points was used
};

struct CurvatureStats {
  CurvatureMethod method = CurvatureMethod::Quartic;
  long long vertices = 0;
  long long boundary = 0, widened = 0, lower_order = 0, nonmanifold = 0;
  long long isolated = 0, failed = 0, normal_repaired = 0;
};

struct VertexCurvature {
  std::vector<float> k1, k2, mean, gauss, absolute;  // one per vertex; k1 >= k2
  std::vector<float> d1, d2;                         // three per vertex: unit principal directions
  std::vector<uint8_t> flags;                        // CurvatureFlag bits, one per vertex
  CurvatureStats stats;

  bool empty() const { return k1.empty(); }
};

// The stats' vertex and flag counts from c.flags (the method is left as it is).
inline void count_curvature_flags(VertexCurvature& c) {
  CurvatureStats& s = c.stats;
  s.vertices = (long long)c.flags.size();
  for (uint8_t f : c.flags) {
    s.boundary += (f & kCurvatureBoundary) != 0;
    s.widened += (f & kCurvatureWidened) != 0;
    s.lower_order += (f & kCurvatureLowerOrder) != 0;
    s.nonmanifold += (f & kCurvatureNonmanifold) != 0;
    s.isolated += (f & kCurvatureIsolated) != 0;
    s.failed += (f & kCurvatureFailed) != 0;
    s.normal_repaired += (f & kCurvatureNormalRepaired) != 0;
  }
}

}  // namespace isoform
