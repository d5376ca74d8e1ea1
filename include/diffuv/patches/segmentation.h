// diffuv: a mesh cut into patches (the paper's section 2.7).
//
// A segmentation gives every face a patch; a patch is a connected set of
// faces of one region label. This header has the type and what is asked of
// a patch (its boundary loops, whether it is a disc); patches come from
// labels (patches_from_labels.h: painted by a person, read from a file) or
// from the layout (layout/disc_patches.h).
#ifndef DIFFUV_PATCHES_SEGMENTATION_H
#define DIFFUV_PATCHES_SEGMENTATION_H

#include <diffuv/core/error.h>
#include <diffuv/internal/index_marks.h>
#include <diffuv/patches/disc_topology.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/centroid.h>
#include <CGAL/squared_distance_3.h>

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>
#include <map>
#include <numeric>
#include <string>
#include <vector>

namespace diffuv {

/// The point type of a vertex point map.
template <class VertexPointMap>
using Point_of = typename boost::property_traits<VertexPointMap>::value_type;

/// Every face of a mesh assigned to a patch.
template <class TriangleMesh>
struct Segmentation {
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  static constexpr std::size_t no_patch = std::numeric_limits<std::size_t>::max();

  std::vector<std::size_t> face_patch;                    ///< #F entries (by face index): the face's patch
  std::vector<int> patch_label;                           ///< #P entries: the region label of each patch
  std::vector<int> patch_part;                            ///< #P entries: 0, or 1, 2, ... for the pieces of a region cut in parts
  std::vector<std::vector<face_descriptor>> patch_faces;  ///< #P entries: the faces of each patch
  /// Empty, or #P entries: the four corners of each patch, counter-clockwise
  /// with (0,0) first, when they were chosen together with the patch (the
  /// four-sided layout, layout/quad_layout.h). An entry of null vertices
  /// (`boost::graph_traits<TriangleMesh>::null_vertex()`) leaves the corners
  /// to `region_sides()`.
  std::vector<std::array<vertex_descriptor, 4>> patch_corners;

  std::size_t number_of_patches() const { return patch_faces.size(); }

  /// The corners chosen with patch `p`, or null if `region_sides()` chooses them.
  const std::array<vertex_descriptor, 4>* corners(std::size_t p) const
  {
    if(p >= patch_corners.size() || patch_corners[p][0] == boost::graph_traits<TriangleMesh>::null_vertex()) return nullptr;
    return &patch_corners[p];
  }
  /// No chosen corners: `region_sides()` picks them for every patch.
  static std::array<vertex_descriptor, 4> no_corners()
  {
    const vertex_descriptor none = boost::graph_traits<TriangleMesh>::null_vertex();
    return {none, none, none, none};
  }

  /// Replaces patch `p` by `pieces` (same label, parts 1, 2, ... in the given
  /// order), inserted where `p` was so that the order of the others is kept.
  template <class FaceIndexMap>
  void split(std::size_t p, std::vector<std::vector<face_descriptor>> pieces, FaceIndexMap findex)
  {
    const int label = patch_label[p];
    const int base = patch_part[p] == 0 ? 0 : patch_part[p] * 10; // a piece of a piece keeps a distinct part number
    patch_label.erase(patch_label.begin() + static_cast<std::ptrdiff_t>(p));
    patch_part.erase(patch_part.begin() + static_cast<std::ptrdiff_t>(p));
    patch_faces.erase(patch_faces.begin() + static_cast<std::ptrdiff_t>(p));
    if(!patch_corners.empty()) patch_corners.erase(patch_corners.begin() + static_cast<std::ptrdiff_t>(p));
    for(std::size_t k = 0; k < pieces.size(); ++k) {
      patch_label.insert(patch_label.begin() + static_cast<std::ptrdiff_t>(p + k), label);
      patch_part.insert(patch_part.begin() + static_cast<std::ptrdiff_t>(p + k), base + static_cast<int>(k) + 1);
      patch_faces.insert(patch_faces.begin() + static_cast<std::ptrdiff_t>(p + k), std::move(pieces[k]));
      if(!patch_corners.empty()) patch_corners.insert(patch_corners.begin() + static_cast<std::ptrdiff_t>(p + k), no_corners());
    }
    for(std::size_t q = 0; q < patch_faces.size(); ++q)
      for(face_descriptor f : patch_faces[q]) face_patch[get(findex, f)] = q;
  }
};

/// A boundary loop of a patch, walked counter-clockwise (interior on the left).
template <class TriangleMesh>
struct Patch_loop {
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;
  static constexpr std::size_t mesh_border = std::numeric_limits<std::size_t>::max();

  std::vector<vertex_descriptor> vertices;      ///< n entries; edge i goes from vertices[i] to vertices[i+1 mod n]
  std::vector<halfedge_descriptor> halfedges;   ///< n entries: edge i as the patch's halfedge
  std::vector<std::size_t> neighbour;           ///< n entries: patch across edge i, or `mesh_border`
  std::vector<double> length;                   ///< n entries: 3D length of edge i
};

/// Returns the boundary loops of patch `p`, each counter-clockwise, with the
/// patch across each edge. A disc patch has exactly one.
template <class TriangleMesh, class VertexPointMap>
std::vector<Patch_loop<TriangleMesh>> patch_loops(const TriangleMesh& tm, VertexPointMap vpm,
                                                  const Segmentation<TriangleMesh>& seg, std::size_t p)
{
  using halfedge_descriptor = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;
  auto findex = get(boost::face_index, tm);
  auto hindex = get(boost::halfedge_index, tm);
  auto patch_of = [&](halfedge_descriptor h) {
    const auto f = face(h, tm);
    return f == boost::graph_traits<TriangleMesh>::null_face() ? Patch_loop<TriangleMesh>::mesh_border
                                                                : seg.face_patch[get(findex, f)];
  };
  // A boundary halfedge of p: in a face of p, its opposite in another patch or on the border.
  auto on_boundary = [&](halfedge_descriptor h) { return patch_of(h) == p && patch_of(opposite(h, tm)) != p; };

  std::vector<Patch_loop<TriangleMesh>> loops;
  // The boundary halfedges already walked, sorted: O(boundary) memory, where
  // a flag per halfedge of the mesh made each call O(mesh).
  std::vector<std::size_t> used;
  auto walked = [&](halfedge_descriptor h) {
    return std::binary_search(used.begin(), used.end(), static_cast<std::size_t>(get(hindex, h)));
  };
  for(auto f : seg.patch_faces[p])
    for(halfedge_descriptor start : CGAL::halfedges_around_face(halfedge(f, tm), tm)) {
      if(!on_boundary(start) || walked(start)) continue;
      Patch_loop<TriangleMesh> loop;
      halfedge_descriptor h = start;
      do {
        loop.vertices.push_back(source(h, tm));
        loop.halfedges.push_back(h);
        loop.neighbour.push_back(patch_of(opposite(h, tm)));
        loop.length.push_back(std::sqrt(CGAL::to_double(
            CGAL::squared_distance(get(vpm, source(h, tm)), get(vpm, target(h, tm))))));
        // The next boundary halfedge leaves target(h): turn around it through p's faces.
        halfedge_descriptor g = next(h, tm);
        while(!on_boundary(g)) g = next(opposite(g, tm), tm);
        h = g;
      } while(h != start);
      for(halfedge_descriptor b : loop.halfedges) used.push_back(static_cast<std::size_t>(get(hindex, b)));
      std::sort(used.begin(), used.end());
      loops.push_back(std::move(loop));
    }
  return loops;
}

/// Checks that patch `p` is a topological disc: triangles only, connected,
/// one boundary loop that passes each vertex once, V - E + F = 1.
/// Costs O(patch size) (unlike `check_disc()` on a `Face_filtered_graph`,
/// which touches the whole mesh), so it can run on every patch of every
/// refinement step.
///
/// This form also gives the loops it walked: `loops` receives
/// `patch_loops(tm, vpm, seg, p)` once the patch is found to be made of
/// triangles and connected (whether or not it is a disc), and is left empty
/// otherwise. Callers that go on to walk a disc's border use them instead of
/// walking it again.
template <class TriangleMesh, class VertexPointMap>
Status check_patch_disc(const TriangleMesh& tm, VertexPointMap vpm, const Segmentation<TriangleMesh>& seg, std::size_t p,
                        std::vector<Patch_loop<TriangleMesh>>& loops)
{
  loops.clear();
  const auto& pf = seg.patch_faces[p];
  auto fail = [&](Status_code code, const std::string& what) {
    return Status(code, what, "patch " + std::to_string(p) + " (label " + std::to_string(seg.patch_label[p]) + ")");
  };
  if(pf.empty()) return fail(Status_code::empty_mesh, "");
  auto findex = get(boost::face_index, tm);
  auto vindex = get(boost::vertex_index, tm);
  auto in_patch = [&](auto f) {
    return f != boost::graph_traits<TriangleMesh>::null_face() && seg.face_patch[get(findex, f)] == p;
  };

  // Triangles, vertices, boundary edges; connectivity by a walk over edges.
  // The marks are kept per thread from one call to the next (4 bytes per
  // vertex and per face of the largest mesh seen) so that a call is O(patch).
  thread_local internal::Index_marks seen_vertices, seen_faces;
  seen_vertices.reset(num_vertices(tm));
  seen_faces.reset(num_faces(tm));
  std::size_t V = 0, boundary_edges = 0;
  for(auto f : pf) {
    if(!CGAL::is_triangle(halfedge(f, tm), tm))
      return fail(Status_code::not_triangle_mesh, "face " + std::to_string(get(findex, f)));
    for(auto h : CGAL::halfedges_around_face(halfedge(f, tm), tm)) {
      if(seen_vertices.insert(get(vindex, target(h, tm)))) ++V;
      if(!in_patch(face(opposite(h, tm), tm))) ++boundary_edges;
    }
  }
  std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor> queue = {pf.front()};
  queue.reserve(pf.size());
  seen_faces.insert(get(findex, pf.front()));
  for(std::size_t q = 0; q < queue.size(); ++q)
    for(auto h : CGAL::halfedges_around_face(halfedge(queue[q], tm), tm)) {
      const auto g = face(opposite(h, tm), tm);
      if(in_patch(g) && seen_faces.insert(get(findex, g))) queue.push_back(g);
    }
  if(queue.size() != pf.size())
    return fail(Status_code::disconnected_mesh, "");

  loops = patch_loops(tm, vpm, seg, p);
  if(loops.empty()) return fail(Status_code::no_border, "");
  if(loops.size() > 1) return fail(Status_code::several_borders, std::to_string(loops.size()) + " boundary loops");
  std::vector<std::size_t> loop_ids;
  for(auto v : loops.front().vertices) loop_ids.push_back(get(vindex, v));
  std::sort(loop_ids.begin(), loop_ids.end());
  const auto repeat = std::adjacent_find(loop_ids.begin(), loop_ids.end());
  if(repeat != loop_ids.end())
    return fail(Status_code::non_manifold, "the boundary passes vertex " + std::to_string(*repeat) + " twice");
  const std::size_t F = pf.size(), E = (3 * F + boundary_edges) / 2;
  const Status disc = internal::disc_euler_status(static_cast<long long>(V) - static_cast<long long>(E) + static_cast<long long>(F));
  return disc ? disc : fail(disc.code, disc.detail);
}

/// Checks that patch `p` is a topological disc (the form above, without its loops).
template <class TriangleMesh>
Status check_patch_disc(const TriangleMesh& tm, const Segmentation<TriangleMesh>& seg, std::size_t p)
{
  std::vector<Patch_loop<TriangleMesh>> loops;
  return check_patch_disc(tm, get(CGAL::vertex_point, tm), seg, p, loops);
}

} // namespace diffuv

#endif // DIFFUV_PATCHES_SEGMENTATION_H
