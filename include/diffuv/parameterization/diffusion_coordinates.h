// diffuv: (u, v) of every vertex of a disc patch from its distances to four sides.
//
// Paper, section 2.8, equation (4): four multi-source Dijkstra runs give
// d_u1, d_u2, d_v1, d_v2 and
//     u = d_u1 / (d_u1 + d_u2),   v = d_v1 / (d_v1 + d_v2),   clamped to [0,1].
#ifndef DIFFUV_PARAMETERIZATION_DIFFUSION_COORDINATES_H
#define DIFFUV_PARAMETERIZATION_DIFFUSION_COORDINATES_H

#include <diffuv/core/error.h>
#include <diffuv/internal/message_text.h>
#include <diffuv/graph/distance_tags.h>
#include <diffuv/graph/heap_tags.h>
#include <diffuv/graph/multi_source_dijkstra.h>
#include <diffuv/core/four_sides.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>
#include <boost/range/iterator_range.hpp>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/parallel_for.h>
#endif

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace diffuv {


/// The relative distance of equation (2) of the paper, d1 / (d1 + d2), with
/// its edge cases defined:
/// - clamped to [0,1] (the paper clamps; round-off can leave it outside);
/// - 0/0, a vertex on both opposite sides (the paper's Figure 8 overlap,
///   e.g. a side of a single vertex shared with the opposite side): 0.5, halfway;
/// - one distance infinite (the vertex is not reached from that side): the
///   limit of the ratio, 1 if d1 is infinite, 0 if d2 is;
/// - both infinite (reached from neither side): NaN, which callers report.
inline double diffusion_ratio(double d1, double d2)
{
  const bool inf1 = std::isinf(d1), inf2 = std::isinf(d2);
  if(inf1 && inf2) return std::numeric_limits<double>::quiet_NaN();
  if(inf1) return 1.;
  if(inf2) return 0.;
  const double sum = d1 + d2;
  if(sum <= 0.) return 0.5;
  return std::clamp(d1 / sum, 0., 1.);
}

/// Computes diffusion coordinates on a disc patch, and keeps the Dijkstra
/// buffers and the four distance fields for the next patch of the same graph.
///
/// \tparam Graph a model of `IncidenceGraph` and `VertexListGraph` with an internal vertex index
///         (a `CGAL::Surface_mesh`, a `CGAL::Face_filtered_graph` patch of it, ...)
/// \tparam HeapTag the heap of the distance runs, `Fibonacci_heap_tag` by default
/// \tparam DistanceTag `Graph_distance_tag` (default, the paper's), `Fmm_distance_tag` or
///         `Exact_distance_tag` (distance_tags.h); the last two need a triangle mesh with vertex points
template <class Graph, class DistanceTag = Default_distance_tag, class HeapTag = Fibonacci_heap_tag>
class Diffusion_coordinates {
public:
  using vertex_descriptor = typename boost::graph_traits<Graph>::vertex_descriptor;

  explicit Diffusion_coordinates(const Graph& g) : graph_(g), engine_(g)
  {
    for(auto& d : distance_) d.resize(num_vertices(g));
  }

  /// Fills `uv` for every vertex of the graph from the four sides.
  ///
  /// \tparam WeightMap a `ReadablePropertyMap` from edges to non-negative `double` (edge lengths)
  /// \tparam UvMap a `WritablePropertyMap` from vertices to a 2D point type constructible from (u, v)
  /// \returns `empty_side` (detail names the side) if a side has no vertex;
  ///          `unreachable_vertices` if some vertex is not reached from a side (their
  ///          coordinates follow `diffusion_ratio()`: NaN if reached from neither side
  ///          of a pair); `ok` otherwise
  /// \throws std::out_of_range if a side vertex's index is not below
  ///         `num_vertices(g)` (not a vertex of the graph); nothing is computed
  ///
  /// \param parallel_passes run the four distance passes on two threads
  ///        (oneTBB; ignored without it), two on each, with a second engine
  ///        sharing the first's tables; `parameterize_patches()` uses it for a
  ///        mesh of one patch.
  template <class WeightMap, class UvMap>
  Status compute(const Four_sides<vertex_descriptor>& sides, WeightMap weight, UvMap uv, bool parallel_passes = false)
  {
    auto index = get(boost::vertex_index, graph_);
    internal::check_side_vertices(sides, index, distance_[0].size(), "Diffusion_coordinates::compute");
    for(Side s : all_sides)
      if(sides[s].empty())
        return Status(Status_code::empty_side, std::string("side ") + side_name(s));
    std::array<Status, 4> status;
    auto pass = [&](Side s, auto& engine) {
      const std::size_t i = static_cast<std::size_t>(s);
      status[i] = engine.run(sides[s], weight, boost::make_iterator_property_map(distance_[i].begin(), index));
    };
#ifdef CGAL_LINKED_WITH_TBB
    if(parallel_passes) {
      // u1 and u2 here, v1 and v2 on another thread, each pair with its own
      // engine; the twin shares what the first has built (fast marching's
      // tables), so the set-up is not made twice.
      auto other = engine_.twin();
      tbb::parallel_for(std::size_t(0), std::size_t(2), [&](std::size_t half) {
        if(half == 0) {
          pass(Side::u1, engine_);
          pass(Side::u2, engine_);
        } else {
          pass(Side::v1, other);
          pass(Side::v2, other);
        }
      });
    } else
#endif
    {
      (void)parallel_passes;
      for(Side s : all_sides) {
        pass(s, engine_);
        if(!status[static_cast<std::size_t>(s)]) return status[static_cast<std::size_t>(s)];
      }
    }
    for(const Status& st : status)
      if(!st) return st;

    using Point_2 = typename boost::property_traits<UvMap>::value_type;
    std::size_t unreachable = 0;
    both_sides_ = 0;
    for(vertex_descriptor v : boost::make_iterator_range(vertices(graph_))) {
      const std::size_t i = get(index, v);
      const double du1 = distances(Side::u1)[i], du2 = distances(Side::u2)[i];
      const double dv1 = distances(Side::v1)[i], dv2 = distances(Side::v2)[i];
      if(std::isinf(du1) || std::isinf(du2) || std::isinf(dv1) || std::isinf(dv2)) ++unreachable;
      if((du1 == 0. && du2 == 0.) || (dv1 == 0. && dv2 == 0.)) ++both_sides_;
      put(uv, v, Point_2(diffusion_ratio(du1, du2), diffusion_ratio(dv1, dv2)));
    }
    if(unreachable > 0)
      return Status(Status_code::unreachable_vertices, internal::count_text(unreachable, "vertex", "vertices"));
    return Status();
  }

  /// The distance of every vertex to side `s` of the last `compute()`, indexed by vertex index.
  const std::vector<double>& distances(Side s) const { return distance_[static_cast<std::size_t>(s)]; }

  /// How many vertices of the last `compute()` lie on two opposite sides (their coordinate is 0.5).
  std::size_t vertices_on_opposite_sides() const { return both_sides_; }

private:
  const Graph& graph_;
  internal::Distance_engine<Graph, DistanceTag, HeapTag> engine_;
  std::array<std::vector<double>, 4> distance_;
  std::size_t both_sides_ = 0;
};

/// Computes diffusion coordinates on a disc patch (one-shot form of `Diffusion_coordinates`).
template <class DistanceTag = Default_distance_tag, class HeapTag = Fibonacci_heap_tag, class Graph, class WeightMap,
          class UvMap>
Status diffusion_coordinates(const Graph& g,
                             const Four_sides<typename boost::graph_traits<Graph>::vertex_descriptor>& sides,
                             WeightMap weight, UvMap uv)
{
  Diffusion_coordinates<Graph, DistanceTag, HeapTag> coordinates(g);
  return coordinates.compute(sides, weight, uv);
}

} // namespace diffuv

#endif // DIFFUV_PARAMETERIZATION_DIFFUSION_COORDINATES_H
