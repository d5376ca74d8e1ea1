// diffuv: whether the colours of a mesh file look like painted regions or
// like data (a coloured scan, a transferred field): a scan's every vertex
// colour taken as a region gives tens of thousands of one-face regions.
#ifndef DIFFUV_IO_PAINT_LOOK_H
#define DIFFUV_IO_PAINT_LOOK_H

#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <cstddef>
#include <numeric>
#include <vector>

namespace diffuv {

/// What the colours taken as regions would give.
struct Paint_look {
  std::size_t colors = 0;  ///< distinct colours (labels)
  std::size_t areas = 0;   ///< connected areas of faces of one colour
  bool painted = false;    ///< few colours (at most `max_colors`) in few areas (at most 2 per colour + 16)

  static constexpr std::size_t max_colors = 256;
};

/// Looks at the regions that colours give: painted when there are at most
/// `Paint_look::max_colors` colours and at most 2 connected areas per colour
/// plus 16 (a painter's colour may cover two eyes or four legs; a scan's
/// colours are scattered over thousands of specks).
///
/// \tparam TriangleMesh a `FaceListGraph` with an internal face index
/// \param face_labels one label per face (by face index): a colour's number
template <class TriangleMesh>
Paint_look look_of_paint(const TriangleMesh& tm, const std::vector<int>& face_labels)
{
  Paint_look look;
  std::vector<int> distinct = face_labels;
  std::sort(distinct.begin(), distinct.end());
  look.colors = static_cast<std::size_t>(std::unique(distinct.begin(), distinct.end()) - distinct.begin());
  auto findex = get(boost::face_index, tm);
  std::vector<std::size_t> parent(num_faces(tm));
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  const auto root = [&](std::size_t i) {
    while(parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for(auto f : faces(tm))
    for(auto h : CGAL::halfedges_around_face(halfedge(f, tm), tm)) {
      const auto g = face(opposite(h, tm), tm);
      if(g == boost::graph_traits<TriangleMesh>::null_face()) continue;
      const std::size_t i = get(findex, f), j = get(findex, g);
      if(face_labels[i] != face_labels[j]) continue;
      const std::size_t a = root(i), b = root(j);
      if(a != b) parent[a] = b;
    }
  for(std::size_t i = 0; i < parent.size(); ++i) look.areas += root(i) == i ? 1 : 0;
  look.painted = look.colors <= Paint_look::max_colors && look.areas <= 2 * look.colors + 16;
  return look;
}

} // namespace diffuv

#endif // DIFFUV_IO_PAINT_LOOK_H
