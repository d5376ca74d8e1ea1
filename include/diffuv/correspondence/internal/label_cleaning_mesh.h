// diffuv: the surface as the label cleaning rules read it (clean_labels.h):
// indices, rounded integer areas and lengths, rings of faces around vertices.
#ifndef DIFFUV_CORRESPONDENCE_INTERNAL_LABEL_CLEANING_MESH_H
#define DIFFUV_CORRESPONDENCE_INTERNAL_LABEL_CLEANING_MESH_H

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/number_utils.h>
#include <CGAL/squared_distance_3.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <numeric>
#include <queue>
#include <stdexcept>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

namespace diffuv {

namespace internal {

/// The surface as the cleaning rules read it: faces and vertices as indices,
/// areas and lengths as integers.
struct Label_cleaning_mesh {
  static constexpr std::size_t none = (std::numeric_limits<std::size_t>::max)();

  std::vector<std::size_t> adjacent_begin;    ///< #F+1 entries: face f's neighbours are [begin[f], begin[f+1])
  std::vector<std::size_t> adjacent_face;     ///< the face across each edge of f that is not on the mesh border
  std::vector<std::int64_t> adjacent_length;  ///< the (rounded) 3D length of that edge
  std::vector<std::int64_t> area;             ///< #F entries: (rounded) face areas
  std::vector<std::size_t> ring_begin;        ///< #V+1 entries: vertex v's faces are [begin[v], begin[v+1])
  std::vector<std::size_t> ring_face;         ///< faces around each vertex in rotation order; `none` for a border gap
  std::vector<std::size_t> corner_begin;      ///< #F+1 entries: face f's vertices are [begin[f], begin[f+1])
  std::vector<std::size_t> corner_vertex;     ///< vertex indices of the faces

  std::size_t number_of_faces() const { return area.size(); }
};

/// Rounds `x` to a multiple of 2^-32 `scale` (integers add up the same in any order).
inline std::int64_t rounded_measure(double x, double scale)
{
  if(!(scale > 0.) || !(x > 0.)) return 0;
  return static_cast<std::int64_t>(std::llround(x / scale * 4294967296.));
}

/// Reads `tm` once: adjacency across edges, faces around vertices, rounded
/// areas and edge lengths, all indexed by the mesh's face and vertex indices.
template <class TriangleMesh, class VertexPointMap>
Label_cleaning_mesh make_label_cleaning_mesh(const TriangleMesh& tm, VertexPointMap vpm)
{
  using Graph_traits = boost::graph_traits<TriangleMesh>;
  using face_descriptor = typename Graph_traits::face_descriptor;
  using vertex_descriptor = typename Graph_traits::vertex_descriptor;
  const auto findex = get(boost::face_index, tm);
  const auto vindex = get(boost::vertex_index, tm);
  const std::size_t nf = num_faces(tm), nv = num_vertices(tm);
  std::vector<face_descriptor> face_of(nf);
  for(face_descriptor f : faces(tm)) face_of[get(findex, f)] = f;
  std::vector<vertex_descriptor> vertex_of(nv);
  for(vertex_descriptor v : vertices(tm)) vertex_of[get(vindex, v)] = v;

  Label_cleaning_mesh m;
  std::vector<double> area(nf), length;
  double largest_area = 0., longest_edge = 0.;
  m.adjacent_begin.push_back(0);
  m.corner_begin.push_back(0);
  for(std::size_t i = 0; i < nf; ++i) {
    area[i] = CGAL::to_double(CGAL::Polygon_mesh_processing::face_area(face_of[i], tm, CGAL::parameters::vertex_point_map(vpm)));
    largest_area = (std::max)(largest_area, area[i]);
    for(auto h : CGAL::halfedges_around_face(halfedge(face_of[i], tm), tm)) {
      m.corner_vertex.push_back(get(vindex, target(h, tm)));
      const auto g = face(opposite(h, tm), tm);
      if(g == Graph_traits::null_face()) continue;
      const double l = std::sqrt(CGAL::to_double(CGAL::squared_distance(get(vpm, source(h, tm)), get(vpm, target(h, tm)))));
      longest_edge = (std::max)(longest_edge, l);
      m.adjacent_face.push_back(get(findex, g));
      length.push_back(l);
    }
    m.adjacent_begin.push_back(m.adjacent_face.size());
    m.corner_begin.push_back(m.corner_vertex.size());
  }
  // The largest face and the longest edge do not depend on the numbering: safe scales.
  for(std::size_t i = 0; i < nf; ++i) m.area.push_back(rounded_measure(area[i], largest_area));
  for(double l : length) m.adjacent_length.push_back(rounded_measure(l, longest_edge));

  m.ring_begin.push_back(0);
  for(std::size_t i = 0; i < nv; ++i) {
    const auto h = halfedge(vertex_of[i], tm);
    if(h != Graph_traits::null_halfedge())
      for(auto g : CGAL::halfedges_around_target(h, tm)) {
        const auto f = face(g, tm);
        m.ring_face.push_back(f == Graph_traits::null_face() ? Label_cleaning_mesh::none
                                                              : static_cast<std::size_t>(get(findex, f)));
      }
    m.ring_begin.push_back(m.ring_face.size());
  }
  return m;
}

/// The label of `counts` (label -> count) with the largest count, ties to the
/// smaller label (a std::map iterates labels in increasing order); `fallback` if empty.
template <class Count>
int most_common_label(const std::map<int, Count>& counts, int fallback)
{
  int best = fallback;
  Count most = 0;
  bool found = false;
  for(const auto& [label, n] : counts)
    if(!found || n > most) {
      best = label;
      most = n;
      found = true;
    }
  return best;
}

} // namespace internal

} // namespace diffuv

#endif // DIFFUV_CORRESPONDENCE_INTERNAL_LABEL_CLEANING_MESH_H
