// diffuv: is this mesh (or patch) a topological disc?
//
// The diffusion coordinates are only bijective on a disc (paper, section
// 2.7): one connected piece, one boundary loop, Euler characteristic 1.
#ifndef DIFFUV_PATCHES_DISC_TOPOLOGY_H
#define DIFFUV_PATCHES_DISC_TOPOLOGY_H

#include <diffuv/core/error.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>

#include <boost/graph/graph_traits.hpp>

#include <string>
#include <vector>

namespace diffuv {
namespace internal {

/// `ok` for a connected surface with one border whose Euler characteristic
/// is 1 (a disc), else `not_a_disc` naming the characteristic and the genus.
inline Status disc_euler_status(long long euler)
{
  if(euler == 1) return Status();
  return Status(Status_code::not_a_disc,
                "Euler characteristic " + std::to_string(euler) + ", genus " + std::to_string((1 - euler) / 2));
}

} // namespace internal

/// Returns the border halfedges (face is null) starting each boundary loop of `tm`, one per loop.
template <class FaceGraph>
std::vector<typename boost::graph_traits<FaceGraph>::halfedge_descriptor>
boundary_loops(const FaceGraph& tm)
{
  using halfedge_descriptor = typename boost::graph_traits<FaceGraph>::halfedge_descriptor;
  std::vector<halfedge_descriptor> starts;
  std::vector<bool> seen(num_halfedges(tm), false);
  auto hindex = get(boost::halfedge_index, tm);
  for(halfedge_descriptor h : halfedges(tm)) {
    if(!is_border(h, tm) || seen[get(hindex, h)]) continue;
    starts.push_back(h);
    for(halfedge_descriptor b : CGAL::halfedges_around_face(h, tm))
      seen[get(hindex, b)] = true;
  }
  return starts;
}

/// Checks that `tm` is a triangulated topological disc: at least one face,
/// triangles only, every vertex on a face, manifold vertices, one connected
/// component, exactly one boundary loop and Euler characteristic V - E + F = 1.
///
/// \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph` with internal indices
/// \param isolated_vertices_allowed if true, vertices on no face (such as the
///        points that reading's repair merged into others) are left out of
///        the check instead of refused
/// \returns `ok`, or the first problem found with the vertex or count in the detail
template <class TriangleMesh>
Status check_disc(const TriangleMesh& tm, bool isolated_vertices_allowed = false)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  if(faces(tm).empty())
    return Status(Status_code::empty_mesh);
  auto vindex = get(boost::vertex_index, tm);
  auto findex = get(boost::face_index, tm);
  for(auto f : faces(tm))
    if(!CGAL::is_triangle(halfedge(f, tm), tm))
      return Status(Status_code::not_triangle_mesh, "face " + std::to_string(get(findex, f)));
  // A vertex is manifold when the halfedges around it (one fan, walked from
  // halfedge(v)) are all the halfedges pointing to it. Counting both in one
  // pass is O(H); PMP::is_non_manifold_vertex() is O(H) per vertex.
  std::vector<std::size_t> incoming(num_vertices(tm), 0);
  for(auto h : halfedges(tm)) ++incoming[get(vindex, target(h, tm))];
  std::size_t isolated = 0;
  for(auto v : vertices(tm)) {
    if(halfedge(v, tm) == boost::graph_traits<TriangleMesh>::null_halfedge() && isolated_vertices_allowed) {
      ++isolated;
      continue;
    }
    if(halfedge(v, tm) == boost::graph_traits<TriangleMesh>::null_halfedge())
      return Status(Status_code::disconnected_mesh,
                    "vertex " + std::to_string(get(vindex, v)) + " belongs to no face");
    std::size_t fan = 0;
    for(auto h : CGAL::halfedges_around_target(halfedge(v, tm), tm)) { (void)h; ++fan; }
    if(fan != incoming[get(vindex, v)])
      return Status(Status_code::non_manifold, "vertex " + std::to_string(get(vindex, v)));
  }
  std::vector<std::size_t> component(num_faces(tm));
  const std::size_t components =
      PMP::connected_components(tm, boost::make_iterator_property_map(component.begin(), findex));
  if(components != 1)
    return Status(Status_code::disconnected_mesh, std::to_string(components) + " components");

  const std::size_t loops = boundary_loops(tm).size();
  if(loops == 0) return Status(Status_code::no_border);
  if(loops > 1) return Status(Status_code::several_borders, std::to_string(loops) + " boundary loops");

  return internal::disc_euler_status(static_cast<long long>(num_vertices(tm) - isolated) - static_cast<long long>(num_edges(tm)) +
                                     static_cast<long long>(num_faces(tm)));
}

} // namespace diffuv

#endif // DIFFUV_PATCHES_DISC_TOPOLOGY_H
