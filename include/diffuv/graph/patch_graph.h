// diffuv: one patch of a mesh as a compact graph for the distance runs.
//
// The four Dijkstra runs of a patch only need, per vertex, its neighbours and
// the lengths of the edges to them. Walking them on the mesh through a
// `CGAL::Face_filtered_graph` tests every halfedge against the patch and maps
// every vertex through two index arrays of the whole mesh; its set-up is
// O(mesh) per patch. Here the patch is copied once, in O(patch), into Boost's
// `compressed_sparse_row_graph` with local vertex ids 0..n-1 (in the order the
// patch's faces first reach them) and the edge lengths stored next to the
// targets; the four runs then read contiguous arrays (doc/performance.md).
#ifndef DIFFUV_GRAPH_PATCH_GRAPH_H
#define DIFFUV_GRAPH_PATCH_GRAPH_H

#include <diffuv/core/four_sides.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <boost/graph/compressed_sparse_row_graph.hpp>
#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

namespace diffuv {

/// A patch of a triangle mesh as a directed graph in compressed rows: both
/// directions of every edge of the patch's faces, each with its length.
///
/// The object keeps an array of the mesh's size (mesh vertex -> local id)
/// between `build()` calls, so that one object rebuilt for each patch costs
/// O(patch) per patch after the first.
///
/// \tparam TriangleMesh a model of `FaceGraph` with an internal vertex index
template <class TriangleMesh>
class Patch_graph {
public:
  using Mesh_vertex = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  /// The length of an edge, the graph's bundled edge property.
  struct Edge {
    double length;
  };
  /// The graph: a model of `IncidenceGraph` and `VertexListGraph` with vertex index = vertex.
  using Graph = boost::compressed_sparse_row_graph<boost::directedS, boost::no_property, Edge, boost::no_property,
                                                   std::uint32_t, std::uint32_t>;
  using vertex_descriptor = typename boost::graph_traits<Graph>::vertex_descriptor;
  static constexpr vertex_descriptor none = (std::numeric_limits<vertex_descriptor>::max)();

  /// Rebuilds the graph from the faces of one patch.
  ///
  /// \param faces the patch's faces (triangles)
  /// \param in_patch a predicate on mesh faces (possibly the null face): true for the patch's faces
  /// \param length a `ReadablePropertyMap` from mesh edges to their length (`edge_length_map()`)
  template <class FaceRange, class InPatch, class EdgeLengthMap>
  void build(const TriangleMesh& tm, const FaceRange& faces, InPatch in_patch, EdgeLengthMap length)
  {
    auto vindex = get(boost::vertex_index, tm);
    if(local_of_.size() != num_vertices(tm)) local_of_.assign(num_vertices(tm), none);
    mesh_vertex_.clear();
    arcs_.clear();
    arc_lengths_.clear();
    auto local = [&](Mesh_vertex v) {
      vertex_descriptor& id = local_of_[get(vindex, v)];
      // Entries of earlier patches are stale unless they point back to v.
      if(id == none || id >= mesh_vertex_.size() || mesh_vertex_[id] != v) {
        id = static_cast<vertex_descriptor>(mesh_vertex_.size());
        mesh_vertex_.push_back(v);
      }
      return id;
    };
    for(auto f : faces)
      for(auto h : CGAL::halfedges_around_face(halfedge(f, tm), tm)) {
        const vertex_descriptor a = local(source(h, tm)), b = local(target(h, tm));
        const double l = get(length, edge(h, tm));
        arcs_.emplace_back(a, b);
        arc_lengths_.push_back(Edge{l});
        if(!in_patch(face(opposite(h, tm), tm))) { // a boundary edge: its other direction has no face here
          arcs_.emplace_back(b, a);
          arc_lengths_.push_back(Edge{l});
        }
      }
    graph_ = Graph(boost::edges_are_unsorted_multi_pass, arcs_.begin(), arcs_.end(), arc_lengths_.begin(),
                   static_cast<vertex_descriptor>(mesh_vertex_.size()));
  }

  const Graph& graph() const { return graph_; }
  /// The edge lengths, a `ReadablePropertyMap` from the graph's edges to `double`.
  auto length_map() const { return get(&Edge::length, graph_); }
  std::size_t number_of_vertices() const { return mesh_vertex_.size(); }
  /// The mesh vertex of each local id.
  const std::vector<Mesh_vertex>& mesh_vertices() const { return mesh_vertex_; }
  /// The local id of mesh vertex `v`, or `none` if `v` is not in the patch.
  vertex_descriptor local(const TriangleMesh& tm, Mesh_vertex v) const
  {
    const std::size_t i = get(get(boost::vertex_index, tm), v);
    if(i >= local_of_.size()) return none;
    const vertex_descriptor id = local_of_[i];
    return id < mesh_vertex_.size() && mesh_vertex_[id] == v ? id : none;
  }

  /// The four sides of the patch in local ids (corners included).
  /// \throws std::invalid_argument if a side vertex is not in the patch
  Four_sides<vertex_descriptor> local_sides(const TriangleMesh& tm, const Four_sides<Mesh_vertex>& sides) const
  {
    Four_sides<vertex_descriptor> out;
    auto to_local = [&](const std::vector<Mesh_vertex>& side, std::vector<vertex_descriptor>& ids) {
      ids.reserve(side.size());
      for(Mesh_vertex v : side) {
        ids.push_back(local(tm, v));
        if(ids.back() == none) throw std::invalid_argument("Patch_graph::local_sides: a side vertex is not a vertex of the patch");
      }
    };
    to_local(sides.u1, out.u1);
    to_local(sides.u2, out.u2);
    to_local(sides.v1, out.v1);
    to_local(sides.v2, out.v2);
    for(std::size_t k = 0; k < 4; ++k) out.corners[k] = local(tm, sides.corners[k]);
    return out;
  }

private:
  Graph graph_;
  std::vector<Mesh_vertex> mesh_vertex_;
  std::vector<vertex_descriptor> local_of_; // #V of the mesh; valid only where it points back
  std::vector<std::pair<vertex_descriptor, vertex_descriptor>> arcs_;
  std::vector<Edge> arc_lengths_;
};

} // namespace diffuv

#endif // DIFFUV_GRAPH_PATCH_GRAPH_H
