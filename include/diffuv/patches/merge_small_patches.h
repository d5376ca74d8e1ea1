// diffuv: patches too small to have four sides merged into a neighbour.
#ifndef DIFFUV_PATCHES_MERGE_SMALL_PATCHES_H
#define DIFFUV_PATCHES_MERGE_SMALL_PATCHES_H

#include <diffuv/patches/patches_from_labels.h>
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

/// Relabels the faces of every patch whose boundary has fewer than
/// `min_boundary_vertices` vertices (a sliver or a lone face cannot have four
/// sides) with the label of the neighbouring patch that shares the longest
/// boundary with it, then rebuilds the patches; repeats until none is left.
///
/// The merges go in passes over the patches, each pass followed by one
/// rebuild. In a pass a small patch merges unless another merged into it,
/// and never into a patch that merged away or a small patch that took one
/// in (their borders are no longer the ones measured); a large patch may
/// take in several. Each pass merges at least the first small patch that has
/// a neighbour and costs one walk of all patches' borders: a mesh with
/// thousands of small patches (a scan whose every colour is a region) takes
/// a few passes, not one rebuild per merge.
///
/// \returns how many patches were merged
template <class TriangleMesh, class VertexPointMap>
std::size_t merge_small_patches(const TriangleMesh& tm, VertexPointMap vpm,
                                std::vector<int>& face_labels, Segmentation<TriangleMesh>& seg,
                                std::size_t min_boundary_vertices = 4)
{
  auto findex = get(boost::face_index, tm);
  std::size_t merged = 0;
  for(bool changed = true; changed;) {
    changed = false;
    const std::size_t np = seg.number_of_patches();
    // The small patches and their borders, as the pass starts.
    std::vector<char> small(np, 0);
    std::vector<std::vector<Patch_loop<TriangleMesh>>> small_loops(np);
    for(std::size_t p = 0; p < np; ++p) {
      auto loops = patch_loops(tm, vpm, seg, p);
      std::size_t boundary_vertices = 0;
      for(const auto& loop : loops) boundary_vertices += loop.vertices.size();
      if(boundary_vertices >= min_boundary_vertices) continue;
      small[p] = 1;
      small_loops[p] = std::move(loops);
    }
    // A patch that merged away, or a small patch that took one in, is done
    // for this pass: the borders measured are no longer its own. (A large
    // patch may take in several.)
    std::vector<char> done(np, 0);
    for(std::size_t p = 0; p < np; ++p) {
      if(!small[p] || done[p]) continue;
      const auto& loops = small_loops[p];
      std::map<std::size_t, double> shared; // neighbour patch -> shared length
      for(const auto& loop : loops)
        for(std::size_t i = 0; i < loop.vertices.size(); ++i)
          if(loop.neighbour[i] != Patch_loop<TriangleMesh>::mesh_border) shared[loop.neighbour[i]] += loop.length[i];
      if(shared.empty()) continue;
      // The neighbour sharing the longest border (the lowest on a tie) whose
      // union with p has enough boundary edges; if none has, the one sharing the
      // longest border. Without the first rule the faces of a tiny closed
      // component (a tetrahedron) pile up into one closed patch, one after the
      // other, where two two-triangle discs were possible.
      std::vector<std::pair<std::size_t, double>> candidates(shared.begin(), shared.end());
      std::stable_sort(candidates.begin(), candidates.end(),
                       [](const auto& a, const auto& b) { return a.second > b.second; });
      std::size_t best = candidates.front().first;
      for(const auto& candidate : candidates) {
        const std::size_t q = candidate.first;
        std::size_t edges = 0; // boundary edges of the union: p's not along q, then q's not along p
        for(const auto& loop : loops)
          for(std::size_t n : loop.neighbour) edges += n != q ? 1 : 0;
        for(auto f : seg.patch_faces[q]) {
          for(auto h : CGAL::halfedges_around_face(halfedge(f, tm), tm)) {
            const auto g = face(opposite(h, tm), tm);
            const std::size_t across = g == boost::graph_traits<TriangleMesh>::null_face()
                                           ? Segmentation<TriangleMesh>::no_patch
                                           : seg.face_patch[get(findex, g)];
            if(across != q && across != p) ++edges;
          }
          if(edges >= min_boundary_vertices) break; // enough: a large neighbour stops early
        }
        if(edges >= min_boundary_vertices) {
          best = q;
          break;
        }
      }
      if(done[best]) continue; // the next pass decides
      for(auto f : seg.patch_faces[p]) face_labels[get(findex, f)] = seg.patch_label[best];
      done[p] = 1;
      if(small[best]) done[best] = 1;
      ++merged;
      changed = true;
    }
    if(changed) seg = patches_from_labels(tm, vpm, face_labels);
  }
  return merged;
}

} // namespace diffuv

#endif // DIFFUV_PATCHES_MERGE_SMALL_PATCHES_H
