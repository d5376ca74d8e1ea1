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

} // namespace diffuv

#endif // DIFFUV_PATCHES_SMOOTH_REGION_BORDERS_H
