// diffuv: multi-source Dijkstra over any Boost Graph Library graph.
//
// The paper (section 2.8) starts Dijkstra's algorithm from a whole set of
// source vertices at distance 0 and relaxes edges with a min-heap holding
// every vertex's tentative distance. This header gives that algorithm as a
// one-shot function and as a reusable object that keeps its heap, handle and
// state buffers between runs (four runs per patch share them).
#ifndef DIFFUV_GRAPH_MULTI_SOURCE_DIJKSTRA_H
#define DIFFUV_GRAPH_MULTI_SOURCE_DIJKSTRA_H

#include <diffuv/core/error.h>
#include <diffuv/graph/heap_tags.h>

#include <boost/graph/graph_concepts.hpp>
#include <boost/graph/graph_traits.hpp>
#include <boost/graph/properties.hpp>
#include <boost/property_map/property_map.hpp>
#include <boost/range/iterator_range.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

namespace diffuv {
namespace internal {

// The origin map of a run that does not ask for one: writes nothing.
struct Ignored_origin {
  using key_type = std::size_t;
  using value_type = std::size_t;
  using reference = std::size_t;
  using category = boost::read_write_property_map_tag;
  template <class Key>
  friend void put(const Ignored_origin&, const Key&, std::size_t) {}
  template <class Key>
  friend std::size_t get(const Ignored_origin&, const Key&) { return 0; }
};

} // namespace internal

/// Computes, for every vertex of a graph, its shortest-path distance to the
/// nearest of a set of source vertices, and keeps its buffers for the next run.
///
/// \tparam Graph a model of `IncidenceGraph` and `VertexListGraph`
///         (`CGAL::Surface_mesh`, `CGAL::Face_filtered_graph`, `boost::adjacency_list`, ...)
/// \tparam HeapTag `Fibonacci_heap_tag` (default, the paper's heap) or another tag of heap_tags.h
/// \tparam VertexIndexMap a `ReadablePropertyMap` from vertices to indices in `[0, num_vertices(g))`
template <class Graph,
          class HeapTag = Fibonacci_heap_tag,
          class VertexIndexMap = typename boost::property_map<Graph, boost::vertex_index_t>::const_type>
class Multi_source_dijkstra {
  BOOST_CONCEPT_ASSERT((boost::IncidenceGraphConcept<Graph>));
  BOOST_CONCEPT_ASSERT((boost::VertexListGraphConcept<Graph>));

public:
  using vertex_descriptor = typename boost::graph_traits<Graph>::vertex_descriptor;

private:
  using Node = internal::Distance_node<vertex_descriptor>;
  using Heap = internal::Min_distance_heap<HeapTag, vertex_descriptor>;
  using Handle = typename Heap::handle_type;
  enum State : std::uint8_t { unseen, queued, settled };

public:
  /// Prepares buffers for `g`, whose vertex set must not change while this object is used.
  explicit Multi_source_dijkstra(const Graph& g)
    : Multi_source_dijkstra(g, get(boost::vertex_index, g)) {}

  Multi_source_dijkstra(const Graph& g, VertexIndexMap vertex_index)
    : graph_(g), vertex_index_(vertex_index),
      handles_(num_vertices(g)), state_(num_vertices(g), unseen) {}

  /// Fills `distance` with the distance of every vertex to the nearest source.
  /// Vertices not reached from any source get `+infinity`.
  ///
  /// \tparam SourceRange a range of `vertex_descriptor`; duplicates are allowed
  /// \tparam WeightMap a `ReadablePropertyMap` from edges to non-negative `double`
  /// \tparam DistanceMap a `ReadWritePropertyMap` from vertices to `double`
  /// \returns `empty_source_range` if `sources` is empty, `negative_weight` if an edge
  ///          weight is negative or NaN (distances are then incomplete), `ok` otherwise.
  template <class SourceRange, class WeightMap, class DistanceMap>
  Status run(const SourceRange& sources, WeightMap weight, DistanceMap distance)
  {
    return run(sources, weight, distance, internal::Ignored_origin());
  }

  /// Same as above, and also fills `origin` with the position, in `sources`,
  /// of the source each vertex is nearest to (a graph Voronoi diagram).
  /// Unreached vertices are not written. On a tie between two sources the
  /// vertex keeps the one that reached it first.
  ///
  /// 	param OriginMap a `WritablePropertyMap` from vertices to `std::size_t`
  template <class SourceRange, class WeightMap, class DistanceMap, class OriginMap>
  Status run(const SourceRange& sources, WeightMap weight, DistanceMap distance, OriginMap origin)
  {
    constexpr double infinity = std::numeric_limits<double>::infinity();
    for(vertex_descriptor v : boost::make_iterator_range(vertices(graph_)))
      put(distance, v, infinity);
    std::fill(state_.begin(), state_.end(), unseen);
    heap_.clear();

    bool any_source = false;
    std::size_t position = 0;
    for(vertex_descriptor s : sources) {
      any_source = true;
      const std::size_t i = get(vertex_index_, s);
      if(state_[i] == queued) { ++position; continue; } // listed twice: the first wins
      put(distance, s, 0.);
      put(origin, s, position++);
      handles_[i] = heap_.push(Node{0., s});
      state_[i] = queued;
    }
    if(!any_source)
      return Status(Status_code::empty_source_range);
    return settle(weight, distance, origin);
  }

  /// Lowers the distances of the previous run (or `add_source()`) with one
  /// more source, `s` at position `position` of the source list: only the
  /// vertices now nearer to `s` than to every earlier source are visited and
  /// rewritten, so that farthest-point sampling, which adds sources one by
  /// one, costs the cells of the new sources rather than one whole run per
  /// source. The result is that of `run()` on all the sources, except that a
  /// vertex exactly as far from `s` as from an earlier source keeps the earlier one.
  ///
  /// \pre `distance` (and `origin`) hold the result of a run on the same graph
  template <class WeightMap, class DistanceMap, class OriginMap>
  Status add_source(vertex_descriptor s, std::size_t position, WeightMap weight, DistanceMap distance,
                    OriginMap origin)
  {
    std::fill(state_.begin(), state_.end(), unseen);
    heap_.clear();
    if(!(get(distance, s) > 0.)) return Status(); // already a source
    put(distance, s, 0.);
    put(origin, s, position);
    handles_[get(vertex_index_, s)] = heap_.push(Node{0., s});
    state_[get(vertex_index_, s)] = queued;
    return settle(weight, distance, origin);
  }

  /// Moves source `position` of the previous run to vertex `s`: the vertices
  /// that were nearest the old source are cleared and reached again, from `s`
  /// and from the vertices around them (with the distances they have); other
  /// vertices change only where `s` is nearer. The cost is that of the old
  /// source's cell and of the new one's, not of a whole run. The result is that
  /// of `run()` with the source moved, except on exact ties between two sources.
  ///
  /// \pre `distance` and `origin` hold the result of a run on the same graph
  template <class WeightMap, class DistanceMap, class OriginMap>
  Status move_source(std::size_t position, vertex_descriptor s, WeightMap weight, DistanceMap distance, OriginMap origin)
  {
    constexpr double infinity = std::numeric_limits<double>::infinity();
    std::fill(state_.begin(), state_.end(), unseen);
    heap_.clear();
    std::vector<vertex_descriptor> cleared;
    for(vertex_descriptor v : boost::make_iterator_range(vertices(graph_)))
      if(get(distance, v) < infinity && get(origin, v) == position) {
        put(distance, v, infinity);
        cleared.push_back(v);
      }
    // The rim: reached vertices next to a cleared one start with their distance.
    for(vertex_descriptor v : cleared)
      for(auto e : boost::make_iterator_range(out_edges(v, graph_))) {
        const vertex_descriptor u = target(e, graph_);
        const std::size_t i = get(vertex_index_, u);
        if(state_[i] == unseen && get(distance, u) < infinity) {
          handles_[i] = heap_.push(Node{get(distance, u), u});
          state_[i] = queued;
        }
      }
    const std::size_t i = get(vertex_index_, s);
    put(distance, s, 0.);
    put(origin, s, position);
    if(state_[i] == queued) heap_.increase(handles_[i], Node{0., s});
    else handles_[i] = heap_.push(Node{0., s});
    state_[i] = queued;
    return settle(weight, distance, origin);
  }

  const Graph& graph() const { return graph_; }

private:
  // Dijkstra's loop from the queued vertices; a vertex is relaxed only to a
  // strictly smaller distance.
  template <class WeightMap, class DistanceMap, class OriginMap>
  Status settle(WeightMap weight, DistanceMap distance, OriginMap origin)
  {
    while(!heap_.empty()) {
      const Node top = heap_.top();
      heap_.pop();
      state_[get(vertex_index_, top.vertex)] = settled;

      for(auto e : boost::make_iterator_range(out_edges(top.vertex, graph_))) {
        const vertex_descriptor v = target(e, graph_);
        const std::size_t i = get(vertex_index_, v);
        if(state_[i] == settled) continue;
        const double w = get(weight, e);
        if(!(w >= 0.)) // also catches NaN
          return Status(Status_code::negative_weight, "weight " + std::to_string(w));
        const double candidate = top.distance + w; // equation (3) of the paper
        if(candidate < get(distance, v)) {
          put(distance, v, candidate);
          put(origin, v, get(origin, top.vertex));
          if(state_[i] == queued) {
            heap_.increase(handles_[i], Node{candidate, v}); // higher priority = nearer
          } else {
            handles_[i] = heap_.push(Node{candidate, v});
            state_[i] = queued;
          }
        }
      }
    }
    return Status();
  }

  const Graph& graph_;
  VertexIndexMap vertex_index_;
  Heap heap_;
  std::vector<Handle> handles_;
  std::vector<std::uint8_t> state_;
};

/// Computes, for every vertex of `g`, its shortest-path distance to the nearest
/// vertex of `sources` (one-shot form of `Multi_source_dijkstra`).
///
/// \tparam Graph a model of `IncidenceGraph` and `VertexListGraph` with an internal vertex index
/// \tparam SourceRange a range of vertex descriptors of `g`
/// \tparam WeightMap a `ReadablePropertyMap` from edges to non-negative `double`
/// \tparam DistanceMap a `ReadWritePropertyMap` from vertices to `double`; unreachable vertices get +infinity
/// \returns `empty_source_range`, `negative_weight` or `ok`
template <class HeapTag = Fibonacci_heap_tag, class Graph, class SourceRange, class WeightMap, class DistanceMap>
Status multi_source_dijkstra(const Graph& g, const SourceRange& sources, WeightMap weight, DistanceMap distance)
{
  Multi_source_dijkstra<Graph, HeapTag> dijkstra(g);
  return dijkstra.run(sources, weight, distance);
}

} // namespace diffuv

#endif // DIFFUV_GRAPH_MULTI_SOURCE_DIJKSTRA_H
