// The comparison's measures for one surface, gathered at the same samples
// on every surface: deviation from a reference, error at the data points,
// normal gap and mean-curvature jump across edges, curvature spread, speed,
// and the triangles of the tessellation.
#pragma once

#include <string>
#include <vector>

namespace isoform::compare {

// Summary of absolute values: count, largest, root mean square, mean.
struct Stats {
  long long count = 0;
  double max = 0.0, rms = 0.0, mean = 0.0;
};

// Accumulates |x| for Stats.
class StatsSum {
 public:
  void add(double x);
  void merge(const StatsSum& other);
  Stats stats() const;

 private:
  long long n_ = 0;
  double max_ = 0.0, sum_ = 0.0, sum2_ = 0.0;
};

// Distribution of a signed quantity: nearest-rank percentiles and the
// standard deviation (the "spread").
struct Spread {
  long long count = 0;
  double p05 = 0.0, p50 = 0.0, p95 = 0.0, mean = 0.0, stddev = 0.0;
};
Spread spread_of(std::vector<double> values);

struct SurfaceMetrics {
  std::string name;                 // "linear", "loop", "side-vertex"
  long long samples = 0;            // lattice samples evaluated
  long long failed_samples = 0;     // samples the surface could not evaluate
  Stats deviation;                  // from the reference (its unit); count 0 without one
  Stats data_point_error;           // |surface at a vertex's corner - vertex|, world units
  Stats normal_gap;                 // radians between the two sides' normals at edge samples
  Stats position_gap;               // world units between the two sides' points there
  // Radians between the two sides' tangent planes there (unoriented: the
  // smaller of the normal gap and pi minus it).
  Stats tangent_plane_gap;
  // Edges with a sample where the two sides' normals point apart (gap above
  // pi/2): the surface folds back along them (patch/orientation.h).
  long long folded_edges = 0;
  Stats mean_curvature_jump;        // |H_left - H_right| at edge samples, 1/world unit
  Stats mean_curvature_error;       // |H - H_reference| where the reference knows H
  Spread mean_curvature;            // H over all samples
  Spread gauss_curvature;           // K over all samples
  double evaluation_seconds = 0.0;  // one thread, lattice samples only
  double seconds_per_million = 0.0;
  long long tessellation_triangles = 0;
};

}  // namespace isoform::compare
