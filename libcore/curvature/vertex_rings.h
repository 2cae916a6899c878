// The vertex neighbourhoods that curvature fits use: each vertex's one-ring
// (the other vertices of its platelet, Definition 4.9 of Hamann 1991) in a
// compressed table, boundary flags, and k-rings gathered by breadth-first
// search over the one-rings.
#pragma once

#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "../mesh.h"

namespace isoform {

class VertexRings {
 public:
  // O(n) in the mesh size. Repeated vertices within a triangle are ignored.
  // Where the processor has AVX-512 conflict detection, a vertex with up to
  // eight triangles is done by it, unless vector_instructions is false
  // (tests compare the two ways); the table is the same either way.
  explicit VertexRings(const Mesh& mesh, bool vector_instructions = true);

  size_t vertex_count() const { return start_.size() - 1; }
  // The one-ring of v without v itself, in the order its triangles meet it.
  const int32_t* ring_begin(int32_t v) const { return ring_.get() + start_[size_t(v)]; }
  const int32_t* ring_end(int32_t v) const { return ring_.get() + start_[size_t(v) + 1]; }
  size_t valence(int32_t v) const { return size_t(start_[size_t(v) + 1] - start_[size_t(v)]); }
  size_t max_valence() const { return max_valence_; }
  // True where v lies on an edge that only one triangle uses.
  bool on_boundary(int32_t v) const { return boundary_[size_t(v)] != 0; }
  // True where v's triangles do not form a single fan (an edge with three or
  // more triangles, or two fans meeting at v).
  bool nonmanifold(int32_t v) const { return nonmanifold_[size_t(v)] != 0; }

 private:
  template <class Offset>
  void build(const Mesh& mesh, bool vector_instructions);
  // The rings from each vertex's corner pairs (vertex_rings.cpp).
  template <class Mark, class Offset>
  void rings_from_pairs(const Offset* at, size_t n, bool vector_instructions);

  std::vector<int64_t> start_;
  std::unique_ptr<int32_t[]> ring_;  // the rings, one after another (in the corner pairs' array)
  size_t max_valence_ = 0;
  std::vector<uint8_t> boundary_;
  std::vector<uint8_t> nonmanifold_;
};

// An allocator whose resize() leaves new elements uninitialised: ring lists
// are written before they are read, and a gather that grows its list per
// vertex would otherwise clear what it is about to write.
template <class T>
struct UninitialisedAllocator : std::allocator<T> {
  template <class U>
  struct rebind {
    using other = UninitialisedAllocator<U>;
  };
  UninitialisedAllocator() = default;
  template <class U>
  UninitialisedAllocator(const UninitialisedAllocator<U>&) noexcept {}
  template <class U>
  void construct(U* p) noexcept {
    ::new (static_cast<void*>(p)) U;
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

// A list of vertices (a platelet).
using RingList = std::vector<int32_t, UninitialisedAllocator<int32_t>>;

// Scratch space for gathering rings; one per thread.
struct RingScratch {
  std::vector<uint32_t> mark;  // per vertex: the stamp of the last gather that saw it
  uint32_t stamp = 0;
  RingList out;
};

// The vertices within `count` steps of v (v excluded) into scratch.out,
// nearest ring first, each ring in the order the breadth-first search meets
// it (the one-rings' order), which depends on v and the mesh alone: not on
// the thread or the order of earlier calls. O(size of the result).
void gather_rings(const VertexRings& rings, int32_t v, int count, RingScratch& scratch);

}  // namespace isoform
