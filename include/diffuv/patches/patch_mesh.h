// diffuv: one patch of a mesh copied as a mesh of its own, for the distance
// runs, the fold repair and the chart of that patch.
//
// A `CGAL::Face_filtered_graph` over the whole mesh costs O(mesh) per patch:
// its set-up resizes three bit sets and three index arrays of the mesh's size,
// and every `vertices()` or `faces()` walk tests every vertex or face of the
// mesh. The layout maps each of its ~1,000 patches several times (the judge,
// the corner choices, then the atlas), so on man those walks were ~6 % of the
// whole run, more on larger meshes. Here the patch is copied once, in
// O(patch), into a `CGAL::Surface_mesh` that the same algorithms walk.
//
// The copy numbers its vertices and faces in the order of the mesh's indices,
// as the filtered graph does, and gives each face and vertex the halfedge the
// filtered graph gives it, so that every walk visits the same elements in the
// same order and the maps come out bit for bit the same.
#ifndef DIFFUV_PATCHES_PATCH_MESH_H
#define DIFFUV_PATCHES_PATCH_MESH_H

#include <diffuv/core/four_sides.h>

#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace diffuv {

/// A patch of a triangle mesh as a `CGAL::Surface_mesh` of its own (see the
/// top of this header). The object keeps an array of the mesh's size (mesh
/// vertex -> local vertex) between `build()` calls, so that one object rebuilt
/// for each patch costs O(patch log patch) per patch after the first.
///
/// \tparam TriangleMesh a model of `FaceGraph` with internal vertex and face indices
/// \tparam VertexPointMap a `ReadablePropertyMap` from the mesh's vertices to points
template <class TriangleMesh, class VertexPointMap>
class Patch_mesh {
public:
  using Point = typename boost::property_traits<VertexPointMap>::value_type;
  using Mesh = CGAL::Surface_mesh<Point>;
  using vertex_descriptor = typename Mesh::Vertex_index;
  using Mesh_vertex = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using Mesh_face = typename boost::graph_traits<TriangleMesh>::face_descriptor;

  /// Copies the patch `faces` (triangles of `tm`, each once).
  /// \param in_patch a predicate on mesh faces (possibly the null face): true for the patch's faces
  /// \returns false if the faces cannot form a manifold mesh (then the copy is empty)
  template <class FaceRange, class InPatch>
  bool build(const TriangleMesh& tm, VertexPointMap vpm, const FaceRange& faces, InPatch in_patch)
  {
    auto vindex = get(boost::vertex_index, tm);
    auto findex = get(boost::face_index, tm);
    mesh_.clear_without_removing_property_maps();
    mesh_vertex_.clear();
    if(local_of_.size() != num_vertices(tm)) local_of_.assign(num_vertices(tm), none);
    // Vertices and faces in the order of the mesh's indices.
    sorted_faces_.assign(faces.begin(), faces.end());
    std::sort(sorted_faces_.begin(), sorted_faces_.end(), [&](Mesh_face a, Mesh_face b) { return get(findex, a) < get(findex, b); });
    for(Mesh_face f : sorted_faces_)
      for(auto h : CGAL::halfedges_around_face(halfedge(f, tm), tm)) mesh_vertex_.push_back(target(h, tm));
    std::sort(mesh_vertex_.begin(), mesh_vertex_.end(), [&](Mesh_vertex a, Mesh_vertex b) { return get(vindex, a) < get(vindex, b); });
    mesh_vertex_.erase(std::unique(mesh_vertex_.begin(), mesh_vertex_.end()), mesh_vertex_.end());
    mesh_.reserve(static_cast<typename Mesh::size_type>(mesh_vertex_.size()),
                  static_cast<typename Mesh::size_type>(mesh_vertex_.size() + sorted_faces_.size() + 2),
                  static_cast<typename Mesh::size_type>(sorted_faces_.size()));
    for(std::size_t i = 0; i < mesh_vertex_.size(); ++i) {
      local_of_[get(vindex, mesh_vertex_[i])] = static_cast<std::uint32_t>(i);
      mesh_.add_vertex(get(vpm, mesh_vertex_[i]));
    }
    auto fail = [&] {
      mesh_.clear_without_removing_property_maps();
      mesh_vertex_.clear();
      return false;
    };
    for(Mesh_face f : sorted_faces_) {
      const auto h0 = halfedge(f, tm);
      const std::array<vertex_descriptor, 3> corners = {local(tm, source(h0, tm)), local(tm, target(h0, tm)),
                                                        local(tm, target(next(h0, tm), tm))};
      const auto lf = mesh_.add_face(corners[0], corners[1], corners[2]);
      if(lf == Mesh::null_face()) return fail();
      // The face's halfedge is the mesh's: source corners[0], target corners[1].
      for(auto h : CGAL::halfedges_around_face(mesh_.halfedge(lf), mesh_))
        if(mesh_.target(h) == corners[1]) {
          mesh_.set_halfedge(lf, h);
          break;
        }
    }
    // Each vertex's halfedge as the filtered graph picks it: the first one, turning
    // around the vertex from the mesh's own, that belongs to a face of the patch
    // or to the opposite of one.
    for(std::size_t i = 0; i < mesh_vertex_.size(); ++i) {
      const auto start = halfedge(mesh_vertex_[i], tm);
      auto h = start;
      do {
        if(in_patch(face(h, tm)) || in_patch(face(opposite(h, tm), tm))) break;
        h = opposite(next(h, tm), tm);
      } while(h != start);
      const auto local_h = CGAL::halfedge(local(tm, source(h, tm)), local(tm, target(h, tm)), mesh_);
      if(!local_h.second) return fail();
      mesh_.set_halfedge(vertex_descriptor(static_cast<typename Mesh::size_type>(i)), local_h.first);
    }
    return true;
  }

  /// Same, with the patch's own faces telling which faces belong to it (a
  /// binary search among them).
  template <class FaceRange>
  bool build(const TriangleMesh& tm, VertexPointMap vpm, const FaceRange& faces)
  {
    auto findex = get(boost::face_index, tm);
    std::vector<std::size_t> sorted;
    for(Mesh_face f : faces) sorted.push_back(get(findex, f));
    std::sort(sorted.begin(), sorted.end());
    return build(tm, vpm, faces, [&](Mesh_face f) {
      return f != boost::graph_traits<TriangleMesh>::null_face() && std::binary_search(sorted.begin(), sorted.end(), get(findex, f));
    });
  }

  const Mesh& mesh() const { return mesh_; }
  /// The mesh's vertex of each local vertex, by local index.
  const std::vector<Mesh_vertex>& mesh_vertices() const { return mesh_vertex_; }

  /// The local vertex of a mesh vertex of the last built patch.
  vertex_descriptor local(const TriangleMesh& tm, Mesh_vertex v) const
  {
    return vertex_descriptor(static_cast<typename Mesh::size_type>(local_of_[get(get(boost::vertex_index, tm), v)]));
  }

  /// Whether `v` is a vertex of the last built patch.
  bool has(const TriangleMesh& tm, Mesh_vertex v) const
  {
    const std::size_t i = get(get(boost::vertex_index, tm), v);
    return i < local_of_.size() && local_of_[i] < mesh_vertex_.size() && mesh_vertex_[local_of_[i]] == v;
  }

  /// `sides` (vertices of the mesh) as local vertices; false if one is not a vertex of the patch.
  bool local_sides(const TriangleMesh& tm, const Four_sides<Mesh_vertex>& sides, Four_sides<vertex_descriptor>& out) const
  {
    bool ok = true;
    auto to_local = [&](const std::vector<Mesh_vertex>& side, std::vector<vertex_descriptor>& ids) {
      ids.clear();
      ids.reserve(side.size());
      for(Mesh_vertex v : side) {
        ok = ok && has(tm, v);
        ids.push_back(ok ? local(tm, v) : vertex_descriptor());
      }
    };
    to_local(sides.u1, out.u1);
    to_local(sides.u2, out.u2);
    to_local(sides.v1, out.v1);
    to_local(sides.v2, out.v2);
    for(std::size_t k = 0; k < 4; ++k) {
      ok = ok && has(tm, sides.corners[k]);
      out.corners[k] = ok ? local(tm, sides.corners[k]) : vertex_descriptor();
    }
    return ok;
  }

private:
  static constexpr std::uint32_t none = (std::numeric_limits<std::uint32_t>::max)();
  Mesh mesh_;
  std::vector<Mesh_vertex> mesh_vertex_;
  std::vector<Mesh_face> sorted_faces_;
  std::vector<std::uint32_t> local_of_;  // #V of the mesh; valid only where it points back
};

} // namespace diffuv

#endif // DIFFUV_PATCHES_PATCH_MESH_H
