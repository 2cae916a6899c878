// The overlap guard's grid (face_grid.h) against the direct test of every
// pair: small faces in cells, faces far larger than the cells in the list of
// big ones, regions wider than the table (read slot by slot), and the
// updates and refits of a reduction.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "libcore/reduce/face_grid.h"
#include "libcore/reduce/triangle_overlap.h"

namespace isoform::reduce {
namespace {

Point3 point3(const Eigen::Vector3d& x) { return {x(0), x(1), x(2)}; }

// Does a query face cross a live face outside the platelet? Every pair.
bool crosses_directly(const WorkMesh& w, const Platelet& p, const LocalFaces& q) {
  for (size_t g = 0; g < w.tri.size(); ++g) {
    if (!w.face_alive[g] || in_platelet(p, int(g))) continue;
    Point3 b[3];
    for (int k = 0; k < 3; ++k) b[k] = point3(w.pos[size_t(w.tri[g][size_t(k)])]);
    for (const auto& t : q.tri) {
      Point3 a[3];
      for (int k = 0; k < 3; ++k) a[k] = point3(w.pos[size_t(t[size_t(k)])]);
      if (triangles_overlap(a, t.data(), b, w.tri[g].data()).overlap) return true;
    }
  }
  return false;
}

// A triangle of its own three vertices, about `size` across, at c.
std::array<int, 3> add_triangle(WorkMesh& w, const Eigen::Vector3d& c, double size, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-0.5, 0.5);
  std::array<int, 3> t{};
  for (int k = 0; k < 3; ++k) {
    t[size_t(k)] = int(w.pos.size());
    w.pos.push_back(c + size * Eigen::Vector3d(u(rng), u(rng), u(rng)));
  }
  return t;
}

void add_face(WorkMesh& w, const std::array<int, 3>& t) {
  w.tri.push_back(t);
  w.face_alive.push_back(1);
  ++w.live_faces;
}

// 3,000 small faces in [0, 4]^3 and 12 big ones (3 across), half of those
// in [0, 4]^3, half above it, where nothing else is.
WorkMesh soup(std::mt19937& rng) {
  WorkMesh w;
  std::uniform_real_distribution<double> in(0.0, 4.0), above(5.0, 8.0);
  for (int i = 0; i < 3000; ++i) add_face(w, add_triangle(w, {in(rng), in(rng), in(rng)}, 0.05, rng));
  for (int i = 0; i < 12; ++i) {
    const Eigen::Vector3d c = i % 2 ? Eigen::Vector3d(in(rng), in(rng), in(rng)) : Eigen::Vector3d(in(rng), in(rng), above(rng));
    add_face(w, add_triangle(w, c, 3.0, rng));
  }
  return w;
}

struct Tally {
  int yes = 0, no = 0;
};

// Random queries of three sizes, each a fan of two faces around a new point,
// with a few of the mesh's faces as the platelet; grid and direct test must
// agree. Counts each size's answers.
void compare(FaceGrid& grid, WorkMesh& w, std::mt19937& rng, Tally tally[3]) {
  std::uniform_real_distribution<double> anywhere(0.0, 8.0), in(0.0, 4.0);
  std::uniform_int_distribution<int> face(0, int(w.tri.size()) - 1);
  const double sizes[3] = {0.15, 1.0, 3.5};
  for (int i = 0; i < 300; ++i) {
    const int kind = i % 3;
    const Eigen::Vector3d c(in(rng), in(rng), kind == 2 ? anywhere(rng) : in(rng));
    const size_t mark = w.pos.size();
    const std::array<int, 3> t0 = add_triangle(w, c, sizes[kind], rng);
    const int extra = int(w.pos.size());
    w.pos.push_back(c + Eigen::Vector3d(0.3, -0.2, 0.1) * sizes[kind]);
    LocalFaces q;
    q.tri = {t0, {t0[0], t0[2], extra}};
    Platelet p;
    p.a = t0;
    for (int k = 0; k < 3; ++k) p.faces.push_back(face(rng));
    std::sort(p.faces.begin(), p.faces.end());
    p.faces.erase(std::unique(p.faces.begin(), p.faces.end()), p.faces.end());
    Box3f region;
    const bool found = grid.crosses(w, p, w.pos[size_t(t0[0])], q, &region);
    ASSERT_EQ(found, crosses_directly(w, p, q)) << "query " << i << " of size " << sizes[kind];
    (found ? tally[kind].yes : tally[kind].no)++;
    w.pos.resize(mark);
  }
}

// Faces moved, grown far beyond the cells, shrunk and removed, as commits
// do: the face's new corners first, then update() with it as the platelet.
void edit(FaceGrid& grid, WorkMesh& w, std::mt19937& rng) {
  std::uniform_real_distribution<double> in(0.0, 4.0), unit(0.0, 1.0);
  std::uniform_int_distribution<int> face(0, int(w.tri.size()) - 1);
  for (int i = 0; i < 600; ++i) {
    const int f = face(rng);
    if (!w.face_alive[size_t(f)]) continue;
    Platelet p;
    p.faces = {f};
    const double r = unit(rng);
    if (r < 0.2) {  // removed
      w.face_alive[size_t(f)] = 0;
      --w.live_faces;
      grid.update(w, p, 0);
      continue;
    }
    const double size = r < 0.5 ? 2.5 : 0.05;  // grown big, or small again
    const Eigen::Vector3d c(in(rng), in(rng), in(rng));
    std::uniform_real_distribution<double> u(-0.5, 0.5);
    for (int k = 0; k < 3; ++k) w.pos[size_t(w.tri[size_t(f)][size_t(k)])] = c + size * Eigen::Vector3d(u(rng), u(rng), u(rng));
    grid.update(w, p, 1);
  }
}

void check(size_t big_cells, int seed) {
  std::mt19937 rng(seed);
  WorkMesh w = soup(rng);
  FaceGrid grid(w, big_cells);
  Tally before[3], after[3];
  compare(grid, w, rng, before);
  const size_t big_at_start = grid.big_faces();
  edit(grid, w, rng);
  const size_t big_after_edits = grid.big_faces();
  compare(grid, w, rng, after);
  grid.refit(w);
  compare(grid, w, rng, after);
  // Every kind of query met faces and missed them, so both answers were
  // checked; the big list was used as the cases intend.
  for (int k = 0; k < 3; ++k) {
    EXPECT_GT(before[k].yes + after[k].yes, 5) << "size " << k;
    EXPECT_GT(before[k].no + after[k].no, 5) << "size " << k;
  }
  if (big_cells == 0) {
    EXPECT_EQ(big_at_start, w.tri.size());
  } else {
    EXPECT_EQ(big_at_start, 12u);  // the 12 big faces, no small one
    EXPECT_GT(big_after_edits, 12u);
  }
}

TEST(FaceGrid, AnswersAsTheDirectTestWithBigFaces) { check(512, 1); }
TEST(FaceGrid, AnswersAsTheDirectTestWithEveryFaceBig) { check(0, 2); }

// Grown faces fit the grid again once they are many: the list shrinks.
TEST(FaceGrid, RefitsWhenTheBigFacesBecomeMany) {
  std::mt19937 rng(3);
  WorkMesh w = soup(rng);
  FaceGrid grid(w);
  const int fits = grid.fits();
  std::uniform_real_distribution<double> in(0.0, 4.0), u(-0.5, 0.5);
  for (int f = 0; f < 400; ++f) {  // 400 faces grow to 2.5 across
    const Eigen::Vector3d c(in(rng), in(rng), in(rng));
    for (int k = 0; k < 3; ++k) w.pos[size_t(w.tri[size_t(f)][size_t(k)])] = c + 2.5 * Eigen::Vector3d(u(rng), u(rng), u(rng));
    Platelet p;
    p.faces = {f};
    grid.update(w, p, 1);
  }
  // Beyond the limit of the first fit: twice its 12 big faces, 64, a 64th.
  const size_t grown = grid.big_faces();
  EXPECT_GT(grown, 2 * 12 + 64 + w.tri.size() / 64);
  grid.refit(w);
  EXPECT_EQ(grid.fits(), fits + 1);
  EXPECT_LT(grid.big_faces(), grown / 4);  // cells fitted to the larger faces
  Tally tally[3];
  compare(grid, w, rng, tally);
}

}  // namespace
}  // namespace isoform::reduce
