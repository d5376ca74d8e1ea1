// diffuv: region borders straightened by moving ear faces across them.
#ifndef DIFFUV_PATCHES_SMOOTH_REGION_BORDERS_H
#define DIFFUV_PATCHES_SMOOTH_REGION_BORDERS_H

#include <diffuv/patches/segmentation.h>

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
#include <utility>
#include <vector>

namespace diffuv {

/// Moves "ear" faces across region borders: a face with two or more edges on
/// the border of its region towards one same other region joins that region.
/// Such a face has all three vertices on one side of its patch, so any map onto
/// the square flattens it; moving it also straightens the border.
///
/// \param face_labels #F entries, changed in place
/// \param ignore_label faces with this label are left alone, and no face takes it
/// \param order the faces to visit, in this order (default: `faces(tm)`)
/// \returns how many faces changed label
template <class TriangleMesh>
std::size_t smooth_region_borders(
    const TriangleMesh& tm, std::vector<int>& face_labels, std::size_t passes = 3,
    int ignore_label = std::numeric_limits<int>::min(),
    const std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>* order = nullptr)
{
  auto findex = get(boost::face_index, tm);
  const std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor> all =
      order ? std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>() :
              std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>(faces(tm).begin(), faces(tm).end());
  const auto& visit = order ? *order : all;
  std::size_t changed = 0;
  // Faces are visited one after the other (a move can make the next face an
  // ear): pass an `order` that does not depend on the face numbering for a
  // result that does not either.
  for(std::size_t pass = 0; pass < passes; ++pass) {
    std::size_t this_pass = 0;
    for(auto f : visit) {
      const int own = face_labels[get(findex, f)];
      if(own == ignore_label) continue; // outside the faces being cut
      int across[3];
      int k = 0;
      for(auto h : CGAL::halfedges_around_face(halfedge(f, tm), tm)) {
        const auto g = face(opposite(h, tm), tm);
        across[k++] = g == boost::graph_traits<TriangleMesh>::null_face() ? own : face_labels[get(findex, g)];
        if(k == 3) break;
      }
      if(k != 3) continue;
      for(int a = 0; a < 3; ++a)
        if(across[a] != own && across[a] != ignore_label &&
           (across[a] == across[(a + 1) % 3] || across[a] == across[(a + 2) % 3])) {
          face_labels[get(findex, f)] = across[a];
          ++this_pass;
          break;
        }
    }
    changed += this_pass;
    if(this_pass == 0) break;
  }
  return changed;
}

/// Moves the faces that jut out of their region into the region they jut
/// into: a face with two edges on its region's border towards one same other
/// region is flat in any map of its patch onto the square (its three vertices
/// lie on the side that border becomes), unless a corner sits on its tip.
/// Unlike `smooth_region_borders()`, which visits faces one after the other,
/// each pass decides every move from the labels as they were before it, so
/// the result depends on neither the face numbering nor an order: the moves
/// are taken larger face first (ties: the lexicographically smaller
/// centroid), each unless a neighbour moved already in this pass (the teeth
/// of a zigzag border jut into each other's region: every other one moves),
/// and the faces left are decided again in the next pass. Each move takes two
/// edges off the borders and adds at most one, so the passes end. A label
/// never loses its last face.
///
/// \param vpm the points (face areas and centroids order the moves)
/// \param face_labels #F entries, changed in place
/// \param ignore_label faces with this label neither move nor take a face
/// \returns how many faces changed label
template <class TriangleMesh, class VertexPointMap>
std::size_t move_ear_faces_across_borders(const TriangleMesh& tm, VertexPointMap vpm, std::vector<int>& face_labels,
                                          std::size_t passes = 1000,
                                          int ignore_label = std::numeric_limits<int>::min())
{
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  using Point_3 = typename boost::property_traits<VertexPointMap>::value_type;
  auto findex = get(boost::face_index, tm);
  auto null_face = boost::graph_traits<TriangleMesh>::null_face();
  // Which of two faces goes first: the larger, then the smaller centroid.
  auto key = [&](face_descriptor f) {
    const auto h = halfedge(f, tm);
    const Point_3 a = get(vpm, source(h, tm)), b = get(vpm, target(h, tm)), c = get(vpm, target(next(h, tm), tm));
    return std::make_pair(-CGAL::to_double(CGAL::squared_area(a, b, c)), CGAL::centroid(a, b, c));
  };
  auto first = [&](face_descriptor f, face_descriptor g) { return key(f) < key(g); };
  std::size_t changed = 0;
  for(std::size_t pass = 0; pass < passes; ++pass) {
    // Every move of this pass, from the labels before it.
    std::vector<std::pair<face_descriptor, int>> moves;
    std::vector<char> moving(face_labels.size(), 0);
    for(face_descriptor f : faces(tm)) {
      const int own = face_labels[get(findex, f)];
      if(own == ignore_label || !CGAL::is_triangle(halfedge(f, tm), tm)) continue;
      std::array<int, 3> across{};
      int k = 0;
      for(auto h : CGAL::halfedges_around_face(halfedge(f, tm), tm)) {
        const face_descriptor g = face(opposite(h, tm), tm);
        across[k++] = g == null_face ? own : face_labels[get(findex, g)];
      }
      for(int a = 0; a < 3; ++a)
        if(across[a] != own && across[a] != ignore_label &&
           (across[a] == across[(a + 1) % 3] || across[a] == across[(a + 2) % 3])) {
          moves.emplace_back(f, across[a]);
          moving[get(findex, f)] = 1;
          break;
        }
    }
    // Accept the moves in the order of `first`, each unless a neighbour was
    // accepted already (a face's move changes what its neighbours see) or
    // ties with it; none that would empty a label.
    std::sort(moves.begin(), moves.end(), [&](const auto& a, const auto& b) { return first(a.first, b.first); });
    std::map<int, std::size_t> region_size, leaving;
    for(int label : face_labels) ++region_size[label];
    std::vector<char> accepted(face_labels.size(), 0);
    std::vector<std::pair<face_descriptor, int>> kept;
    for(const auto& [f, to] : moves) {
      bool blocked = false;
      for(auto h : CGAL::halfedges_around_face(halfedge(f, tm), tm)) {
        const face_descriptor g = face(opposite(h, tm), tm);
        if(g == null_face) continue;
        blocked |= accepted[get(findex, g)] || (moving[get(findex, g)] && !first(g, f) && !first(f, g));
      }
      const int own = face_labels[get(findex, f)];
      if(blocked || leaving[own] + 1 >= region_size[own]) continue;
      accepted[get(findex, f)] = 1;
      ++leaving[own];
      kept.emplace_back(f, to);
    }
    for(const auto& [f, to] : kept) face_labels[get(findex, f)] = to;
    const std::size_t this_pass = kept.size();
    changed += this_pass;
    if(this_pass == 0) break;
  }
  return changed;
}

} // namespace diffuv

#endif // DIFFUV_PATCHES_SMOOTH_REGION_BORDERS_H
