// The overlap guard (prevent_overlap, face_grid.h): a thin shell, whose two
// sheets lie closer than its triangles grow, reduced with and without it.
#include <gtest/gtest.h>

#include <cmath>

#include <tbb/global_control.h>

#include "libcore/reduce/mesh_overlap.h"
#include "libcore/reduce/reduce.h"
#include "libcore/topology.h"

namespace isoform::reduce {
namespace {

// A torus ((2 + r cos u) cos v, (2 + r cos u) sin v, r sin u) on an nu x nv
// grid; `inward` turns its triangles to face the tube's axis.
void add_tube(Mesh& m, int nu, int nv, double r, bool inward) {
  const int32_t base = int32_t(m.vertex_count());
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const double u = 2 * M_PI * i / nu, v = 2 * M_PI * j / nv;
      const double p[3] = {(2 + r * std::cos(u)) * std::cos(v), (2 + r * std::cos(u)) * std::sin(v), r * std::sin(u)};
      for (double x : p) {
        m.points.push_back(float(x));
        m.precise_points.push_back(x);
      }
    }
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const int32_t a = base + j * nu + i, b = base + j * nu + (i + 1) % nu,
                    c = base + ((j + 1) % nv) * nu + (i + 1) % nu, d = base + ((j + 1) % nv) * nu + i;
      if (inward)
        m.triangles.insert(m.triangles.end(), {a, b, c, a, c, d});
      else
        m.triangles.insert(m.triangles.end(), {a, c, b, a, d, c});
    }
}

// A torus-shaped shell: the outer tube (radius 1) facing out, the inner one
// (radius 1 - gap) facing in, with an offset grid so the sheets differ.
Mesh thin_shell(double gap) {
  Mesh m;
  add_tube(m, 96, 160, 1.0, false);
  add_tube(m, 90, 150, 1.0 - gap, true);
  return m;
}

ReduceStats reduce_shell(Mesh& m, bool guard, bool ahead = true) {
  ReduceOptions o;
  o.keep_fraction = 0.02;
  o.prevent_overlap = guard;
  o.compute_ahead = ahead;
  return reduce_mesh(m, o, Progress(nullptr));
}

TEST(NoOverlap, ThinShellReducedWithoutTheGuardOverlapsWithItDoesNot) {
  const Mesh shell = thin_shell(0.02);
  ASSERT_TRUE(find_overlaps(shell).empty());
  Mesh plain = shell, guarded = shell;
  const ReduceStats s0 = reduce_shell(plain, false);
  const ReduceStats s1 = reduce_shell(guarded, true);
  EXPECT_EQ(s0.refused.overlap, 0);
  // Without the guard the sheets go through each other somewhere.
  EXPECT_FALSE(find_overlaps(plain).empty());
  // With it they never do, and the guard was needed to keep them apart.
  EXPECT_TRUE(find_overlaps(guarded).empty());
  EXPECT_GT(s1.refused.overlap, 0);
  EXPECT_GT(s1.removals, 3000);
  EXPECT_EQ(guarded.stats.boundary_edges, 0);
  EXPECT_EQ(guarded.stats.nonmanifold_edges, 0);
  EXPECT_EQ(guarded.part_count, 2);
  // Its result can be reduced again (the input check finds no overlap).
  ReduceOptions again;
  again.keep_fraction = 0.5;
  again.prevent_overlap = true;
  EXPECT_NO_THROW(reduce_mesh(guarded, again, Progress(nullptr)));
  EXPECT_TRUE(find_overlaps(guarded).empty());
}

// The guard reads faces beyond the platelet: removals computed ahead side
// by side must still give the serial result to the bit.
TEST(NoOverlap, OneThreadAndAllThreadsGiveTheSameBits) {
  const Mesh shell = thin_shell(0.02);
  Mesh one = shell, all = shell;
  ReduceStats s1, s2;
  {
    const tbb::global_control serial(tbb::global_control::max_allowed_parallelism, 1);
    s1 = reduce_shell(one, true);
  }
  s2 = reduce_shell(all, true);
  EXPECT_GT(s1.refused.overlap, 0);
  EXPECT_EQ(s1.removals, s2.removals);
  EXPECT_EQ(s1.refused.overlap, s2.refused.overlap);
  EXPECT_EQ(one.triangles, all.triangles);
  EXPECT_EQ(one.precise_points, all.precise_points);
}

// A removal computed ahead read the faces in its region's boxes: one that an
// earlier removal of its batch changed there (new faces or old ones, no
// shared vertex needed) must be computed again. Each removal computed at its
// turn must give the same bits.
TEST(NoOverlap, ComputedAheadOrAtItsTurnTheSameBits) {
  const Mesh shell = thin_shell(0.02);
  Mesh ahead = shell, at_turn = shell;
  const ReduceStats s1 = reduce_shell(ahead, true, true);
  const ReduceStats s2 = reduce_shell(at_turn, true, false);
  EXPECT_GT(s1.refused.overlap, 0);
  EXPECT_EQ(s1.removals, s2.removals);
  EXPECT_EQ(s1.refused.overlap, s2.refused.overlap);
  EXPECT_EQ(ahead.triangles, at_turn.triangles);
  EXPECT_EQ(ahead.precise_points, at_turn.precise_points);
}

}  // namespace
}  // namespace isoform::reduce
