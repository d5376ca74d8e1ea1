// diffuv: what cutting a patch needs: the pieces a cut leaves, a face's centroid.
#ifndef DIFFUV_PATCHES_INTERNAL_FACE_PIECES_H
#define DIFFUV_PATCHES_INTERNAL_FACE_PIECES_H

#include <diffuv/patches/segmentation.h>

#include <CGAL/boost/graph/Face_filtered_graph.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/centroid.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <queue>
#include <set>
#include <tuple>
#include <unordered_map>
#include <vector>

namespace diffuv {

namespace internal {

// The faces of `faces`, grouped into components that do not cross an edge of `cut`
// (edge indices) nor leave `faces`. Components come in the order of their first face.
template <class TriangleMesh>
std::vector<std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>>
components_across(const TriangleMesh& tm, const std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>& faces,
                  const std::set<std::size_t>& cut)
{
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  auto findex = get(boost::face_index, tm);
  auto eindex = get(boost::edge_index, tm);
  constexpr std::size_t none = std::numeric_limits<std::size_t>::max();
  std::vector<std::size_t> piece(num_faces(tm), none);
  std::vector<bool> member(num_faces(tm), false);
  for(face_descriptor f : faces) member[get(findex, f)] = true;
  std::vector<std::vector<face_descriptor>> pieces;
  for(face_descriptor start : faces) {
    if(piece[get(findex, start)] != none) continue;
    pieces.emplace_back();
    std::vector<face_descriptor> queue = {start};
    piece[get(findex, start)] = pieces.size() - 1;
    for(std::size_t q = 0; q < queue.size(); ++q) {
      pieces.back().push_back(queue[q]);
      for(auto h : CGAL::halfedges_around_face(halfedge(queue[q], tm), tm)) {
        if(cut.count(get(eindex, edge(h, tm)))) continue;
        const face_descriptor g = face(opposite(h, tm), tm);
        if(g == boost::graph_traits<TriangleMesh>::null_face()) continue;
        const std::size_t gi = get(findex, g);
        if(member[gi] && piece[gi] == none) {
          piece[gi] = pieces.size() - 1;
          queue.push_back(g);
        }
      }
    }
  }
  return pieces;
}

// The centroid of face f.
template <class TriangleMesh, class VertexPointMap>
typename boost::property_traits<VertexPointMap>::value_type
face_centroid(const TriangleMesh& tm, typename boost::graph_traits<TriangleMesh>::face_descriptor f, VertexPointMap vpm)
{
  const auto h = halfedge(f, tm);
  return CGAL::centroid(get(vpm, source(h, tm)), get(vpm, target(h, tm)), get(vpm, target(next(h, tm), tm)));
}

} // namespace internal

} // namespace diffuv

#endif // DIFFUV_PATCHES_INTERNAL_FACE_PIECES_H
