// diffuv: exact polyhedral geodesic distances from a set of source vertices.
//
// The reference distance backend: CGAL's `Surface_mesh_shortest_path`
// (Xin and Wang's improved Chen-Han algorithm) gives the length of the
// shortest path on the surface of the triangle mesh, which may cross faces
// and bends only at saddle or border vertices. It is slow — the four passes
// of a patch take milliseconds for a few hundred vertices and seconds for
// several thousands — and serves to measure the graph and fast marching
// backends, or to compute reference maps.
#ifndef DIFFUV_GRAPH_EXACT_GEODESICS_H
#define DIFFUV_GRAPH_EXACT_GEODESICS_H

#include <diffuv/core/error.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_shortest_path.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/graph_concepts.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/number_utils.h>

#include <boost/iterator/function_output_iterator.hpp>
#include <boost/graph/graph_traits.hpp>
#include <boost/graph/properties.hpp>
#include <boost/property_map/property_map.hpp>
#include <boost/range/empty.hpp>
#include <boost/range/iterator_range.hpp>

#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace diffuv {

/// Computes, for every vertex of a triangle mesh, its exact geodesic distance
/// on the surface (polyhedral: the shortest path on the faces of `g`) to the
/// nearest vertex of `sources`, with CGAL's `Surface_mesh_shortest_path`.
///
/// The algorithm runs on a temporary `CGAL::Surface_mesh` copy of `g` made
/// with `CGAL::copy_face_graph()`. The copy costs O(#V), little next to the
/// algorithm, and makes any input work alike: a whole mesh, a
/// `CGAL::Face_filtered_graph` patch (paths then stay on the patch's faces),
/// a `Surface_mesh` with removed elements (whose indices are not contiguous,
/// which `Surface_mesh_shortest_path` requires), any vertex point map.
///
/// Each source vertex is passed as a face location (`face_location(v, mesh)`:
/// a barycentric corner of one of its faces). **Build with `NDEBUG`** (or
/// `CGAL_NO_ASSERTIONS`) when sources may lie on the border, as the sides of a
/// patch do: CGAL 5.5 then fails the internal assertion
/// `!node->is_null_face()` (Surface_mesh_shortest_path.h, line 1473) during
/// the propagation, whether the source is given as a vertex or as a face
/// location (checked on nefertiti.off and mushroom.off). With assertions off
/// the distances are right: equal to Euclidean distances on flat grids with a
/// border column as sources, never above edge-path distances (test_distances.cpp).
///
/// \tparam TriangleMesh a model of `FaceListGraph` and `VertexListGraph` with an
///         internal vertex index in `[0, num_vertices(g))`; triangle faces
/// \tparam VertexPointMap a `ReadablePropertyMap` from vertices to a CGAL `Point_3`
/// \tparam SourceRange a range of vertex descriptors of `g`; duplicates are allowed
/// \tparam DistanceMap a `WritablePropertyMap` from vertices of `g` to `double`
/// \param g the mesh or patch
/// \param vpm the points of the vertices of `g`
/// \param sources the vertices at distance 0
/// \param distance receives the distance of every vertex of `g`; sources get
///        0, vertices not reached (another connected component, an isolated
///        vertex) `+infinity`
/// \returns `empty_source_range` if `sources` is empty (every distance is then
///          `+infinity`), `not_triangle_mesh` if a face of `g` is not a triangle
///          (nothing is written), `ok` otherwise
template <class TriangleMesh, class VertexPointMap, class SourceRange, class DistanceMap>
Status exact_geodesic_distances(const TriangleMesh& g, VertexPointMap vpm, const SourceRange& sources,
                                DistanceMap distance)
{
  BOOST_CONCEPT_ASSERT((CGAL::concepts::FaceListGraphConcept<TriangleMesh>));
  BOOST_CONCEPT_ASSERT((boost::VertexListGraphConcept<TriangleMesh>));
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using Point = typename boost::property_traits<VertexPointMap>::value_type;
  using Kernel = typename CGAL::Kernel_traits<Point>::Kernel;
  using Copy = CGAL::Surface_mesh<Point>;
  using Copy_vertex = typename Copy::Vertex_index;
  using Traits = CGAL::Surface_mesh_shortest_path_traits<Kernel, Copy>;
  using Shortest_path = CGAL::Surface_mesh_shortest_path<Traits>;
  constexpr double infinity = std::numeric_limits<double>::infinity();

  for(auto f : boost::make_iterator_range(faces(g))) {
    const auto h = halfedge(f, g);
    if(next(next(next(h, g), g), g) != h)
      return Status(Status_code::not_triangle_mesh, "exact geodesics need triangle faces");
  }
  const auto vindex = get(boost::vertex_index, g);
  if(boost::empty(sources)) {
    for(vertex_descriptor v : boost::make_iterator_range(vertices(g))) put(distance, v, infinity);
    return Status(Status_code::empty_source_range);
  }

  // The copy, and each vertex of g's copy (none for an isolated vertex, which
  // copy_face_graph() does not copy).
  Copy copy;
  std::vector<Copy_vertex> to_copy(num_vertices(g), Copy::null_vertex());
  CGAL::copy_face_graph(g, copy,
      CGAL::parameters::vertex_point_map(vpm).vertex_to_vertex_output_iterator(
          boost::make_function_output_iterator([&](const std::pair<vertex_descriptor, Copy_vertex>& p) {
            to_copy[get(vindex, p.first)] = p.second;
          })));

  std::vector<bool> is_source(num_vertices(g), false);
  std::vector<typename Shortest_path::Face_location> locations;
  for(vertex_descriptor s : sources) {
    const std::size_t i = get(vindex, s);
    if(is_source[i]) continue; // listed twice
    is_source[i] = true;
    if(to_copy[i] != Copy::null_vertex())
      locations.push_back(Shortest_path::face_location(to_copy[i], copy));
  }

  Shortest_path shortest_path(copy);
  shortest_path.add_source_points(locations.begin(), locations.end());
  for(vertex_descriptor v : boost::make_iterator_range(vertices(g))) {
    const std::size_t i = get(vindex, v);
    double d = infinity;
    if(is_source[i]) {
      d = 0.; // also an isolated source, unknown to the copy
    } else if(to_copy[i] != Copy::null_vertex() && !locations.empty()) {
      // A negative distance means no source is reachable (another component).
      const double found = CGAL::to_double(shortest_path.shortest_distance_to_source_points(to_copy[i]).first);
      if(found >= 0.) d = found;
    }
    put(distance, v, d);
  }
  return Status();
}

} // namespace diffuv

#endif // DIFFUV_GRAPH_EXACT_GEODESICS_H
