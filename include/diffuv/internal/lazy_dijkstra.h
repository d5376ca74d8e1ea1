// diffuv: Dijkstra's algorithm with a binary heap and lazy deletion, on any
// adjacency given by a callable.
//
// The heap-tagged engine (graph/multi_source_dijkstra.h) keeps a handle per
// vertex and decreases keys; this one pushes a vertex again whenever its
// distance drops and skips the stale entries when they are popped, which
// needs no handles and suits small local graphs (layout/internal/local_region.h) and
// flat arrays (the benchmark's compressed-row reference).
#ifndef DIFFUV_INTERNAL_LAZY_DIJKSTRA_H
#define DIFFUV_INTERNAL_LAZY_DIJKSTRA_H

#include <functional>
#include <queue>
#include <utility>
#include <vector>

namespace diffuv {
namespace internal {

/// Shortest edge-path distances from `sources` (distance 0) into `dist`,
/// which must hold infinity for every vertex on entry (indexed by `Index`).
/// `for_each_edge(a, relax)` calls `relax(b, length)` for each edge from
/// vertex `a` to a vertex `b`.
template <class Index, class ForEachEdge>
void lazy_dijkstra(const std::vector<Index>& sources, std::vector<double>& dist, ForEachEdge&& for_each_edge)
{
  using Entry = std::pair<double, Index>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  for(Index s : sources) {
    dist[s] = 0.;
    queue.emplace(0., s);
  }
  while(!queue.empty()) {
    const Entry top = queue.top();
    queue.pop();
    const double d = top.first;
    if(d > dist[top.second]) continue;
    for_each_edge(top.second, [&](Index b, double length) {
      const double candidate = d + length;
      if(candidate < dist[b]) {
        dist[b] = candidate;
        queue.emplace(candidate, b);
      }
    });
  }
}

} // namespace internal
} // namespace diffuv

#endif // DIFFUV_INTERNAL_LAZY_DIJKSTRA_H
