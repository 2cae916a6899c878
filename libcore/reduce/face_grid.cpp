// The faces of the working mesh in a uniform grid (see face_grid.h).
#include "face_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "batch_crew.h"
#include "triangle_overlap.h"

namespace isoform::reduce {
namespace {

constexpr int kReach = 1 << 20;  // cell indices stay within (-kReach, kReach)

float down(double x) {
  float f = float(x);
  return double(f) > x ? std::nextafter(f, -std::numeric_limits<float>::infinity()) : f;
}
float up(double x) {
  float f = float(x);
  return double(f) < x ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
}

Point3 point3(const Eigen::Vector3d& x) { return {x(0), x(1), x(2)}; }

// A spin lock around FaceGrid::update.
class Hold {
 public:
  explicit Hold(std::atomic_flag& f) : f_(f) {
    while (f_.test_and_set(std::memory_order_acquire)) BatchCrew::pause();
  }
  ~Hold() { f_.clear(std::memory_order_release); }

 private:
  std::atomic_flag& f_;
};

}  // namespace

void Box3f::add(const Box3f& b) {
  if (b.empty()) return;
  if (empty()) {
    *this = b;
    return;
  }
  for (size_t k = 0; k < 3; ++k) {
    lo[k] = std::min(lo[k], b.lo[k]);
    hi[k] = std::max(hi[k], b.hi[k]);
  }
}

Box3f triangle_box(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  Box3f box;
  for (int k = 0; k < 3; ++k) {
    box.lo[size_t(k)] = down(std::min({a(k), b(k), c(k)}));
    box.hi[size_t(k)] = up(std::max({a(k), b(k), c(k)}));
  }
  return box;
}

FaceGrid::FaceGrid(const WorkMesh& w, size_t big_cells) : box_(w.tri.size()), big_cells_(big_cells) { refit(w); }

// NOTE: cells twice as wide as the faces' mean box: a face then meets one
// to eight cells, and a platelet's new faces a few dozen.
void FaceGrid::refit(const WorkMesh& w) {
  if (built_faces_ > 0 && 4 * w.live_faces > built_faces_ && big_.size() <= big_limit_) return;
  double sum = 0;
  long long n = 0;
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  for (size_t f = 0; f < w.tri.size(); ++f) {
    if (!w.face_alive[f]) continue;
    const auto& t = w.tri[f];
    const Eigen::Vector3d &a = w.pos[size_t(t[0])], &b = w.pos[size_t(t[1])], &c = w.pos[size_t(t[2])];
    const Eigen::Vector3d l = a.cwiseMin(b).cwiseMin(c), h = a.cwiseMax(b).cwiseMax(c);
    lo = lo.cwiseMin(l);
    sum += (h - l).maxCoeff();
    ++n;
  }
  origin_ = n > 0 && lo.allFinite() ? lo : Eigen::Vector3d::Zero();
  double cell = n > 0 ? 2 * sum / double(n) : 1.0;
  if (!(cell > 0) || !std::isfinite(cell)) cell = 1.0;
  build(w, cell);
}

void FaceGrid::build(const WorkMesh& w, double cell) {
  inverse_ = 1.0 / cell;
  // (A face meets about two cells, a cell holds about four faces: half as
  // many slots as faces to start with, doubled when half are used.)
  size_t capacity = 1024;
  while (capacity < size_t(std::max(1LL, w.live_faces / 2))) capacity *= 2;
  slots_ = BigVector<Slot>(capacity);
  set_shift();
  used_ = 0;
  for (const Big& g : big_) big_at_[size_t(g.face)] = -1;
  big_.clear();
  built_faces_ = w.live_faces;
  ++fits_;
  for (size_t f = 0; f < w.tri.size(); ++f) {
    if (!w.face_alive[f]) continue;
    const auto& t = w.tri[f];
    insert(int(f), triangle_box(w.pos[size_t(t[0])], w.pos[size_t(t[1])], w.pos[size_t(t[2])]));
  }
  // (Twice as many as now: faces big at every fit do not refit each batch.)
  big_limit_ = 2 * big_.size() + 64 + size_t(w.live_faces / 64);
}

bool FaceGrid::is_big(const std::array<int, 3>& c0, const std::array<int, 3>& c1) const {
  double cells = 1;
  for (size_t k = 0; k < 3; ++k) cells *= double(c1[k]) - double(c0[k]) + 1;
  return cells > double(big_cells_);
}

std::array<int, 3> FaceGrid::cell_of(const float x[3]) const {
  std::array<int, 3> c;
  for (int k = 0; k < 3; ++k) {
    const double i = std::floor((double(x[k]) - origin_(k)) * inverse_);
    c[size_t(k)] = int(std::clamp(i, double(1 - kReach), double(kReach - 1)));
  }
  return c;
}

uint64_t FaceGrid::key(int x, int y, int z) {
  return uint64_t(x + kReach) | uint64_t(y + kReach) << 21 | uint64_t(z + kReach) << 42;
}

size_t FaceGrid::first_slot(uint64_t key) const {
  // (The product's high bits: every bit of the key reaches them.)
  return size_t((key * 0x9E3779B97F4A7C15ull) >> shift_);
}

void FaceGrid::set_shift() {
  shift_ = 64;
  for (size_t n = slots_.size(); n > 1; n >>= 1) --shift_;
}

void FaceGrid::add(uint64_t key, int face, const Box3f& box) {
  const size_t mask = slots_.size() - 1;
  size_t s = first_slot(key);
  for (; slots_[s].key != kFree; s = (s + 1) & mask) {
    Slot& slot = slots_[s];
    if (slot.key == key && slot.count < kPerSlot) {
      slot.box[slot.count] = box;
      slot.face[slot.count++] = face;
      return;
    }
  }
  if (2 * (used_ + 1) > slots_.size()) {
    grow();
    add(key, face, box);
    return;
  }
  slots_[s].key = key;
  slots_[s].count = 1;
  slots_[s].face[0] = face;
  slots_[s].box[0] = box;
  ++used_;
}

void FaceGrid::grow() {
  BigVector<Slot> old(2 * slots_.size());
  old.swap(slots_);
  set_shift();
  const size_t mask = slots_.size() - 1;
  for (const Slot& slot : old) {
    if (slot.key == kFree) continue;
    size_t s = first_slot(slot.key);
    while (slots_[s].key != kFree) s = (s + 1) & mask;
    slots_[s] = slot;
  }
}

void FaceGrid::insert(int face, const Box3f& b) {
  box_[size_t(face)] = b;
  const std::array<int, 3> c0 = cell_of(b.lo.data()), c1 = cell_of(b.hi.data());
  if (is_big(c0, c1)) {
    if (big_at_.empty()) big_at_.assign(box_.size(), -1);
    big_at_[size_t(face)] = int32_t(big_.size());
    big_.push_back({face, b});
    return;
  }
  for (int z = c0[2]; z <= c1[2]; ++z)
    for (int y = c0[1]; y <= c1[1]; ++y)
      for (int x = c0[0]; x <= c1[0]; ++x) add(key(x, y, z), face, b);
}

void FaceGrid::erase(int face, const Box3f& b) {
  const size_t mask = slots_.size() - 1;
  const std::array<int, 3> c0 = cell_of(b.lo.data()), c1 = cell_of(b.hi.data());
  if (is_big(c0, c1)) {
    // (The list's order is not kept: queries only ask whether any crosses.)
    const int32_t at = big_at_[size_t(face)];
    big_at_[size_t(big_.back().face)] = at;
    big_[size_t(at)] = big_.back();
    big_.pop_back();
    big_at_[size_t(face)] = -1;
    return;
  }
  for (int z = c0[2]; z <= c1[2]; ++z)
    for (int y = c0[1]; y <= c1[1]; ++y)
      for (int x = c0[0]; x <= c1[0]; ++x) {
        const uint64_t k = key(x, y, z);
        for (size_t s = first_slot(k); slots_[s].key != kFree; s = (s + 1) & mask) {
          Slot& slot = slots_[s];
          if (slot.key != k) continue;
          int32_t* end = slot.face + slot.count;
          int32_t* it = std::find(slot.face, end, face);
          if (it == end) continue;
          slot.box[it - slot.face] = slot.box[slot.count - 1];
          *it = end[-1];
          --slot.count;
          break;
        }
      }
}

void FaceGrid::update(const WorkMesh& w, const Platelet& p, size_t made) {
  const Hold hold(lock_);
  for (int f : p.faces) erase(f, box_[size_t(f)]);
  for (size_t i = 0; i < made; ++i) {
    const int f = p.faces[i];
    const auto& t = w.tri[size_t(f)];
    insert(f, triangle_box(w.pos[size_t(t[0])], w.pos[size_t(t[1])], w.pos[size_t(t[2])]));
  }
}

Box3f FaceGrid::boxes_of(const Platelet& p) const {
  Box3f b;
  for (int f : p.faces) b.add(box_[size_t(f)]);
  return b;
}

namespace {

// A triangle as the tests take it.
struct Tested {
  Point3 p[3];
  int32_t v[3];
  Point3 n;
  Box3f box;
  double extent = 0;  // the box's largest side
};

void make_tested(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                 const std::array<int, 3>& v, Tested& t) {
  t.p[0] = point3(a);
  t.p[1] = point3(b);
  t.p[2] = point3(c);
  for (int k = 0; k < 3; ++k) t.v[k] = v[size_t(k)];
  t.n = triangle_normal(t.p);
  t.box = triangle_box(a, b, c);
  t.extent = 0;
  for (size_t k = 0; k < 3; ++k) t.extent = std::max(t.extent, double(t.box.hi[k]) - double(t.box.lo[k]));
}

}  // namespace

template <class Test>
bool FaceGrid::any_in_cells(const Box3f& region, Test test) const {
  const std::array<int, 3> c0 = cell_of(region.lo.data()), c1 = cell_of(region.hi.data());
  // A face is met in the cell of its box's and the region's low corner only.
  const auto first_meeting = [&](const Box3f& bg, const std::array<int, 3>& c) {
    if (!region.meets(bg)) return false;
    const float low[3] = {std::max(region.lo[0], bg.lo[0]), std::max(region.lo[1], bg.lo[1]),
                          std::max(region.lo[2], bg.lo[2])};
    return cell_of(low) == c;
  };
  double cells = 1;
  for (size_t k = 0; k < 3; ++k) cells *= double(c1[k]) - double(c0[k]) + 1;
  if (cells > double(slots_.size())) {
    // Fewer slots than cells to walk: every slot, its cell from its key.
    constexpr uint64_t mask21 = (uint64_t(1) << 21) - 1;
    for (const Slot& slot : slots_) {
      if (slot.key == kFree || slot.count == 0) continue;
      const std::array<int, 3> c{int(slot.key & mask21) - kReach, int((slot.key >> 21) & mask21) - kReach,
                                 int(slot.key >> 42) - kReach};
      for (int j = 0; j < slot.count; ++j)
        if (first_meeting(slot.box[j], c) && test(slot.face[j], slot.box[j])) return true;
    }
    return false;
  }
  const size_t mask = slots_.size() - 1;
  for (int z = c0[2]; z <= c1[2]; ++z)
    for (int y = c0[1]; y <= c1[1]; ++y)
      for (int x = c0[0]; x <= c1[0]; ++x) {
        const std::array<int, 3> c{x, y, z};
        const uint64_t k = key(x, y, z);
        for (size_t s = first_slot(k); slots_[s].key != kFree; s = (s + 1) & mask) {
          const Slot& slot = slots_[s];
          if (slot.key != k) continue;
          for (int j = 0; j < slot.count; ++j)
            if (first_meeting(slot.box[j], c) && test(slot.face[j], slot.box[j])) return true;
        }
      }
  return false;
}

// NOTE: one walk over the cells of the union of the new faces' boxes: a
// face near the platelet meets several new faces, and their cells are
// mostly the same.
bool FaceGrid::crosses(const WorkMesh& w, const Platelet& p, const Eigen::Vector3d& point, const LocalFaces& faces,
                       Box3f* region) const {
  thread_local std::vector<Tested> made;
  made.resize(faces.tri.size());
  *region = Box3f();
  for (size_t i = 0; i < faces.tri.size(); ++i) {
    const auto& t = faces.tri[i];
    make_tested(local_pos(w, p, point, t[0]), local_pos(w, p, point, t[1]), local_pos(w, p, point, t[2]), t, made[i]);
    region->add(made[i].box);
  }
  if (region->empty()) return false;
  Tested other;
  const auto crossed = [&](int g, const Box3f& bg) {
    if (!region->meets(bg) || in_platelet(p, g)) return false;
    const auto& t = w.tri[size_t(g)];
    make_tested(w.pos[size_t(t[0])], w.pos[size_t(t[1])], w.pos[size_t(t[2])], t, other);
    for (const Tested& m : made) {
      if (!m.box.meets(other.box)) continue;
      if (certainly_apart(m.p, m.n, m.v, other.p, other.n, other.v, m.extent + other.extent)) continue;
      if (triangles_overlap(m.p, m.n, m.v, other.p, other.n, other.v).overlap) return true;
    }
    return false;
  };
  if (any_in_cells(*region, crossed)) return true;
  for (const Big& g : big_)
    if (crossed(g.face, g.box)) return true;
  return false;
}

}  // namespace isoform::reduce
