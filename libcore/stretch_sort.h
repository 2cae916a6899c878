// A counting sort of items (triangles) by keys (vertices, slabs) in a few
// stretches of items side by side, each with its own counts per key. A
// key's list then holds the first stretch's items, then the second's, and
// so on: ascending, as one scan of the items would list them.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

namespace isoform {

// keys_of(item, visit) calls visit(key) for each key of the item (key <
// keys; a key twice lists the item twice). Into start (keys + 1 entries)
// and items (each key's items from items[start[key]]).
template <class Int, class KeysOf>
void sort_by_keys_in_stretches(size_t count, size_t keys, KeysOf keys_of, std::vector<Int>& start,
                               std::vector<int32_t>& items) {
  const size_t stretches = count < 65536 ? 1 : size_t(std::clamp(tbb::this_task_arena::max_concurrency(), 1, 4));
  const size_t per = (count + stretches - 1) / stretches;
  std::vector<std::vector<Int>> fill(stretches, std::vector<Int>(keys, 0));
  const auto each_stretch = [&](auto visit) {
    tbb::parallel_for(size_t(0), stretches, [&](size_t s) {
      std::vector<Int>& mine = fill[s];
      const size_t last = std::min(count, (s + 1) * per);
      for (size_t t = s * per; t < last; ++t) keys_of(t, [&](size_t key) { visit(mine[key], t); });
    });
  };
  each_stretch([](Int& c, size_t) { ++c; });
  start.assign(keys + 1, 0);
  for (size_t key = 0; key < keys; ++key) {
    Int at = start[key];
    for (size_t s = 0; s < stretches; ++s) {
      const Int c = fill[s][key];
      fill[s][key] = at;
      at += c;
    }
    start[key + 1] = at;
  }
  items.resize(size_t(start[keys]));
  each_stretch([&](Int& next, size_t t) { items[size_t(next++)] = int32_t(t); });
}

}  // namespace isoform
