// diffuv: edge lengths computed once, read on every relaxation.
#ifndef DIFFUV_GRAPH_EDGE_LENGTH_MAP_H
#define DIFFUV_GRAPH_EDGE_LENGTH_MAP_H

#include <boost/graph/graph_traits.hpp>
#include <boost/graph/properties.hpp>
#include <boost/property_map/vector_property_map.hpp>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/squared_distance_3.h>

#include <cmath>

namespace diffuv {

/// The type returned by `edge_length_map()`: a property map from edges to
/// `double` that owns its storage (copies share it).
template <class Graph>
using Edge_length_map =
    boost::vector_property_map<double, typename boost::property_map<Graph, boost::edge_index_t>::const_type>;

/// Computes the 3D length of every edge of `g` once.
///
/// The map is indexed by the graph's edge index, so a map computed on a mesh
/// also serves every `CGAL::Face_filtered_graph` patch of that mesh when the
/// patch is built with the mesh's own index maps.
///
/// \tparam Graph a model of `EdgeListGraph` with an internal edge index (e.g. `CGAL::Surface_mesh`)
/// \tparam VertexPointMap a `ReadablePropertyMap` from vertices to a CGAL `Point_3`
template <class Graph, class VertexPointMap>
Edge_length_map<Graph> edge_length_map(const Graph& g, VertexPointMap vpm)
{
  Edge_length_map<Graph> lengths(num_edges(g), get(boost::edge_index, g));
  for(auto e : edges(g)) {
    const auto a = get(vpm, source(e, g));
    const auto b = get(vpm, target(e, g));
    put(lengths, e, std::sqrt(CGAL::to_double(CGAL::squared_distance(a, b))));
  }
  return lengths;
}

/// Same as above with the graph's internal vertex point map.
template <class Graph>
Edge_length_map<Graph> edge_length_map(const Graph& g)
{
  return edge_length_map(g, get(CGAL::vertex_point, g));
}

} // namespace diffuv

#endif // DIFFUV_GRAPH_EDGE_LENGTH_MAP_H
