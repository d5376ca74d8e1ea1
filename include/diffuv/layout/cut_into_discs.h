// diffuv: a patch that is not a disc cut into disc pieces by the automatic segmentation.
#ifndef DIFFUV_LAYOUT_CUT_INTO_DISCS_H
#define DIFFUV_LAYOUT_CUT_INTO_DISCS_H

#include <diffuv/layout/voronoi_discs.h>
#include <diffuv/patches/segmentation.h>

#include <algorithm>
#include <map>
#include <vector>

namespace diffuv {

/// Cuts non-disc patch `p` into disc pieces with `voronoi_discs()` (parts 1, 2, ...).
/// \returns the number of pieces (1: nothing was cut)
///
/// The number of seeds to start from is `options.patches` times the share of
/// the mesh's faces in the patch, at least 2: a band needs two pieces, a whole
/// closed mesh labelled as one region as many as automatic patches would use.
template <class TriangleMesh, class VertexPointMap>
std::size_t cut_into_discs(const TriangleMesh& tm, VertexPointMap vpm, Segmentation<TriangleMesh>& seg, std::size_t p,
                           Voronoi_options options = Voronoi_options())
{
  auto findex = get(boost::face_index, tm);
  std::vector<int> cells(num_faces(tm), -1);
  options.patches = std::max<std::size_t>(2, options.patches * seg.patch_faces[p].size() / num_faces(tm));
  voronoi_discs(tm, vpm, seg.patch_faces[p], cells, 0, options);
  std::map<int, std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>> by_cell;
  for(auto f : seg.patch_faces[p]) by_cell[cells[get(findex, f)]].push_back(f);
  if(by_cell.size() < 2) return 1;
  std::vector<std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>> pieces;
  for(auto& [cell, faces] : by_cell) pieces.push_back(std::move(faces));
  const std::size_t count = pieces.size();
  seg.split(p, std::move(pieces), findex);
  return count;
}

} // namespace diffuv

#endif // DIFFUV_LAYOUT_CUT_INTO_DISCS_H
