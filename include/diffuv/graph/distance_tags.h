// diffuv: which distance the diffusion measures from each side.
//
// The paper diffuses along edges (graph distances, section 2.6) and notes
// that geodesics would respect the surface better at a higher cost. Three
// backends, chosen by a tag, all multi-source:
//   Graph_distance_tag  the paper's edge-path Dijkstra
//   Fmm_distance_tag    first-order fast marching across triangles (fast_marching.h);
//                       the pipelines' default (doc/quality.md has the numbers)
//   Exact_distance_tag  exact polyhedral geodesics, CGAL's Surface_mesh_shortest_path (slow)
#ifndef DIFFUV_GRAPH_DISTANCE_TAGS_H
#define DIFFUV_GRAPH_DISTANCE_TAGS_H

#include <diffuv/core/error.h>
#include <diffuv/graph/exact_geodesics.h>
#include <diffuv/graph/fast_marching.h>
#include <diffuv/graph/heap_tags.h>
#include <diffuv/graph/multi_source_dijkstra.h>

#include <CGAL/boost/graph/properties.h>

#include <memory>

namespace diffuv {

/// Edge-path distances: `Multi_source_dijkstra` with the edge weight map.
struct Graph_distance_tag {};
/// Distances through triangles: `Fast_marching` (the edge weights are not used).
struct Fmm_distance_tag {};
/// Exact polyhedral geodesics: `exact_geodesic_distances()` (the edge weights are not used).
struct Exact_distance_tag {};

/// The distance of `parameterize_disc()` and `parameterize_patches()` unless
/// told otherwise: fast marching folds far less than edge paths and bends
/// shapes less, for about 1.5x the distance time (doc/quality.md).
using Default_distance_tag = Fmm_distance_tag;

namespace internal {

// One multi-source distance computation per tag, keeping its buffers.
template <class Graph, class DistanceTag, class HeapTag>
class Distance_engine;

// Each engine's twin() is a second engine over the same graph for a run on
// another thread at the same time; it shares what can be shared.
template <class Graph, class HeapTag>
class Distance_engine<Graph, Graph_distance_tag, HeapTag> {
public:
  explicit Distance_engine(const Graph& g) : dijkstra_(g) {}
  Distance_engine twin() const { return Distance_engine(dijkstra_.graph()); }
  template <class SourceRange, class WeightMap, class DistanceMap>
  Status run(const SourceRange& sources, WeightMap weight, DistanceMap distance)
  {
    return dijkstra_.run(sources, weight, distance);
  }

private:
  Multi_source_dijkstra<Graph, HeapTag> dijkstra_;
};

template <class Graph, class HeapTag>
class Distance_engine<Graph, Fmm_distance_tag, HeapTag> {
public:
  explicit Distance_engine(const Graph& g) : graph_(g) {}
  template <class SourceRange, class WeightMap, class DistanceMap>
  Status run(const SourceRange& sources, WeightMap, DistanceMap distance)
  {
    return marching().run(sources, distance);
  }
  // Builds this engine's tables if it has none yet (on the calling thread),
  // then gives the twin a share of them: one build for both.
  Distance_engine twin()
  {
    Distance_engine other(graph_);
    other.marching_ = std::make_unique<Fast_marching<Graph, HeapTag>>(marching().twin());
    return other;
  }

private:
  Fast_marching<Graph, HeapTag>& marching()
  {
    if(!marching_) marching_ = std::make_unique<Fast_marching<Graph, HeapTag>>(graph_); // per-mesh set-up, once
    return *marching_;
  }

  const Graph& graph_;
  std::unique_ptr<Fast_marching<Graph, HeapTag>> marching_;
};

template <class Graph, class HeapTag>
class Distance_engine<Graph, Exact_distance_tag, HeapTag> {
public:
  explicit Distance_engine(const Graph& g) : graph_(g) {}
  template <class SourceRange, class WeightMap, class DistanceMap>
  Status run(const SourceRange& sources, WeightMap, DistanceMap distance)
  {
    return exact_geodesic_distances(graph_, get(CGAL::vertex_point, graph_), sources, distance);
  }
  Distance_engine twin() const { return Distance_engine(graph_); }

private:
  const Graph& graph_;
};

} // namespace internal
} // namespace diffuv

#endif // DIFFUV_GRAPH_DISTANCE_TAGS_H
