// The measuring pass of the comparison study. For each surface, in order:
//   1. the lattice: evaluate every sample (timed), deviation from the
//      reference, H and K, the tessellation vertex, the sample table;
//   2. the data points: each base vertex against the surface at a corner;
//   3. the edges: both sides at the same edge points, normal and H gaps.
#include "compare.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "lattice.h"
#include "libcore/errors.h"
#include "surface_geometry.h"

namespace isoform::compare {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

V3 base_point(const Mesh& m, int32_t v) {
  const size_t i = 3 * size_t(v);
  if (m.precise_points.size() == m.points.size()) return {m.precise_points[i], m.precise_points[i + 1], m.precise_points[i + 2]};
  return {m.points[i], m.points[i + 1], m.points[i + 2]};
}

// The flat triangle's point and normal, where a surface cannot be evaluated
// (the tessellation never gets NaN vertices).
void flat_sample(const Mesh& m, size_t t, double u, double v, SurfaceSample& s) {
  const V3 p0 = base_point(m, m.triangles[3 * t]), p1 = base_point(m, m.triangles[3 * t + 1]),
           p2 = base_point(m, m.triangles[3 * t + 2]);
  for (int c = 0; c < 3; ++c) s.point[c] = (1 - u - v) * p0[c] + u * p1[c] + v * p2[c];
  V3 n = cross({p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]}, {p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2]});
  const double len = norm(n);
  s.normal = len > 0 ? V3{n[0] / len, n[1] / len, n[2] / len} : V3{0, 0, 1};
}

// Which triangles feed the sample table: evenly spaced, at most `wanted`.
std::vector<bool> table_selection(size_t triangles, long long wanted) {
  std::vector<bool> pick(triangles, false);
  if (wanted <= 0 || triangles == 0) return pick;
  if (size_t(wanted) >= triangles) return std::vector<bool>(triangles, true);
  for (long long r = 0; r < wanted; ++r) pick[size_t(double(r) * double(triangles) / double(wanted))] = true;
  return pick;
}

class SurfacePass {
 public:
  SurfacePass(const Mesh& base, const TriangleSurface& surface, const Reference* reference, int k)
      : base_(base), surface_(surface), reference_(reference), k_(k) {}

  // Step 1. Fills metrics, the tessellation and this surface's table values.
  void lattice_pass(SurfaceMetrics& m, Mesh& tess, const std::vector<bool>& pick, std::vector<SampleValues>& values,
                    std::vector<SampleRow>* rows, const Progress& progress, float f0, float f1) {
    const std::vector<LatticePoint> points = lattice(k_);
    const std::vector<int32_t> local = lattice_triangles(k_);
    TessellationIds ids(base_, k_);
    StatsSum deviation, h_error;
    std::vector<double> hs, ks;
    std::vector<int32_t> map(points.size());
    double seconds = 0.0;
    std::vector<SurfaceSample> samples(points.size());
    std::vector<char> ok(points.size());
    // Base vertex ids come first; isolated vertices keep their own point.
    tess.points.resize(3 * base_.vertex_count());
    tess.normals.assign(3 * base_.vertex_count(), 0.0f);
    for (size_t v = 0; v < base_.vertex_count(); ++v)
      for (int c = 0; c < 3; ++c) tess.points[3 * v + size_t(c)] = float(base_point(base_, int32_t(v))[size_t(c)]);
    const size_t n = base_.triangle_count();
    for (size_t t = 0; t < n; ++t) {
      if (t % 1024 == 0) check_progress(progress, f0 + (f1 - f0) * float(t) / float(n));
      const auto start = std::chrono::steady_clock::now();
      for (size_t p = 0; p < points.size(); ++p) ok[p] = surface_.evaluate(t, points[p].u, points[p].v, samples[p]);
      seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      for (size_t p = 0; p < points.size(); ++p) {
        SurfaceSample& s = samples[p];
        ++m.samples;
        if (!ok[p]) {
          ++m.failed_samples;
          flat_sample(base_, t, points[p].u, points[p].v, s);
          s.has_second = false;
        }
        const SampleCurvature c = ok[p] ? curvature_of(s) : SampleCurvature{};
        SampleValues val{s.point[0], s.point[1], s.point[2], kNaN, kNaN, kNaN};
        if (c.ok) {
          hs.push_back(c.mean);
          ks.push_back(c.gauss);
          val.mean = c.mean;
          val.gauss = c.gauss;
        }
        if (reference_ && ok[p]) {
          val.deviation = reference_->deviation(s.point);
          if (std::isfinite(val.deviation)) deviation.add(val.deviation);  // NaN: undefined there
          const double h_true = reference_->mean_curvature(s.point);
          if (c.ok && std::isfinite(h_true)) h_error.add(c.mean - h_true);
        }
        if (pick[t]) {
          values.push_back(val);
          if (rows) rows->push_back({int32_t(t), points[p].u, points[p].v});
        }
        bool fresh = false;
        map[p] = ids.id(t, points[p].i, points[p].j, fresh);
        if (fresh) put_vertex(tess, map[p], s);
      }
      for (int32_t q : local) tess.triangles.push_back(map[size_t(q)]);
    }
    m.deviation = deviation.stats();
    m.mean_curvature_error = h_error.stats();
    m.mean_curvature = spread_of(std::move(hs));
    m.gauss_curvature = spread_of(std::move(ks));
    m.evaluation_seconds = seconds;
    m.seconds_per_million = m.samples > 0 ? seconds * 1e6 / double(m.samples) : 0.0;
    m.tessellation_triangles = (long long)tess.triangle_count();
  }

  // Step 2: the surface at a corner of the first triangle of each vertex.
  void data_point_pass(SurfaceMetrics& m) const {
    std::vector<bool> done(base_.vertex_count(), false);
    StatsSum error;
    const double corner[3][2] = {{0, 0}, {1, 0}, {0, 1}};
    for (size_t t = 0; t < base_.triangle_count(); ++t)
      for (int c = 0; c < 3; ++c) {
        const int32_t v = base_.triangles[3 * t + size_t(c)];
        if (done[size_t(v)]) continue;
        done[size_t(v)] = true;
        SurfaceSample s;
        if (surface_.evaluate(t, corner[c][0], corner[c][1], s)) error.add(distance(s.point, base_point(base_, v)));
      }
    m.data_point_error = error.stats();
  }

  // Step 3: each interior edge once, k points, from both sides.
  void edge_pass(SurfaceMetrics& m) const {
    StatsSum normal_gap, position_gap, plane_gap, h_jump;
    long long folded = 0;
    for (size_t t = 0; t < base_.triangle_count(); ++t)
      for (int e = 0; e < 3; ++e) {
        const int32_t o = base_.neighbours.empty() ? -1 : base_.neighbours[3 * t + size_t(e)];
        if (o < 0 || size_t(o) < t) continue;
        const int g = opposite_edge(t, e, size_t(o));
        if (g < 0) continue;  // inconsistently oriented: no shared parameter
        bool fold = false;
        for (int j = 0; j < k_; ++j) {
          const double s = (j + 0.5) / k_;
          double u0, v0, u1, v1;
          edge_parameter(e, s, u0, v0);
          edge_parameter(g, 1.0 - s, u1, v1);
          SurfaceSample a, b;
          if (!surface_.evaluate(t, u0, v0, a) || !surface_.evaluate(size_t(o), u1, v1, b)) continue;
          const double gap = angle_between(a.normal, b.normal);
          normal_gap.add(gap);
          plane_gap.add(std::min(gap, M_PI - gap));
          fold = fold || gap > 0.5 * M_PI;
          position_gap.add(distance(a.point, b.point));
          const SampleCurvature ca = curvature_of(a), cb = curvature_of(b);
          if (ca.ok && cb.ok) h_jump.add(ca.mean - cb.mean);
        }
        folded += fold ? 1 : 0;
      }
    m.normal_gap = normal_gap.stats();
    m.position_gap = position_gap.stats();
    m.tangent_plane_gap = plane_gap.stats();
    m.folded_edges = folded;
    m.mean_curvature_jump = h_jump.stats();
  }

 private:
  // The edge of o that runs from t's corner e+1 to its corner e, or -1.
  int opposite_edge(size_t t, int e, size_t o) const {
    const int32_t a = base_.triangles[3 * t + size_t(e)], b = base_.triangles[3 * t + size_t((e + 1) % 3)];
    for (int g = 0; g < 3; ++g)
      if (base_.triangles[3 * o + size_t(g)] == b && base_.triangles[3 * o + size_t((g + 1) % 3)] == a) return g;
    return -1;
  }

  static void put_vertex(Mesh& tess, int32_t id, const SurfaceSample& s) {
    const size_t i = 3 * size_t(id);
    if (tess.points.size() < i + 3) {
      tess.points.resize(i + 3);
      tess.normals.resize(i + 3);
    }
    for (int c = 0; c < 3; ++c) {
      tess.points[i + size_t(c)] = float(s.point[c]);
      tess.normals[i + size_t(c)] = float(s.normal[c]);
    }
  }

  static void check_progress(const Progress& progress, float fraction) {
    if (progress.cancelled()) throw Cancelled("compare: cancelled");
    progress.fraction(fraction);
  }

  const Mesh& base_;
  const TriangleSurface& surface_;
  const Reference* reference_;
  int k_;
};

}  // namespace

CompareResult compare_surfaces(const Mesh& base, const std::vector<NamedSurface>& surfaces, const Reference* reference,
                               const CompareSettings& settings, const Progress& progress) {
  if (settings.level < 1 || settings.level > 64)
    throw InvalidArgument("compare: level " + std::to_string(settings.level) + " is not 1..64");
  CompareResult r;
  r.base_vertices = (long long)base.vertex_count();
  r.base_triangles = (long long)base.triangle_count();
  r.level = settings.level;
  if (reference) {
    r.reference_kind = reference->kind();
    r.reference_description = reference->description();
    r.deviation_unit = reference->unit();
  }
  const std::vector<bool> pick = table_selection(base.triangle_count(), settings.table_triangles);
  const float share = 1.0f / float(std::max<size_t>(1, surfaces.size()));
  for (size_t i = 0; i < surfaces.size(); ++i) {
    SurfaceMetrics m;
    m.name = surfaces[i].name;
    Mesh tess;
    std::vector<SampleValues> values;
    SurfacePass pass(base, *surfaces[i].surface, reference, settings.level);
    pass.lattice_pass(m, tess, pick, values, i == 0 ? &r.rows : nullptr, progress, share * float(i),
                      share * (float(i) + 0.8f));
    pass.data_point_pass(m);
    pass.edge_pass(m);
    r.surfaces.push_back(m);
    r.tessellations.push_back(std::move(tess));
    r.values.push_back(std::move(values));
  }
  progress.fraction(1.0f);
  return r;
}

}  // namespace isoform::compare
