// diffuv: each face's distance to the centre of its cell, the point the
// four-sided layout's fans start from and its arcs' midpoints are measured to.
#ifndef DIFFUV_LAYOUT_INTERNAL_CELL_CENTRES_H
#define DIFFUV_LAYOUT_INTERNAL_CELL_CENTRES_H

#include <diffuv/graph/multi_source_dijkstra.h>
#include <diffuv/internal/index_list_hash.h>
#include <diffuv/patches/segmentation.h>

#include <CGAL/boost/graph/iterator.h>

#include <boost/graph/compressed_sparse_row_graph.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <unordered_map>
#include <utility>
#include <vector>

namespace diffuv {
namespace internal {

/// Distances to cell centres already found, by cell (its faces, sorted), in
/// the order of the key: `quad_layout()` asks after every refinement round.
using Centre_distance_memo = std::unordered_map<std::vector<std::size_t>, std::vector<double>, Index_list_hash>;

/// For every face, its distance (through the dual graph) to the deepest face
/// of its cell (the face farthest from the cell's border). The paths stay in
/// their cell, so a cell's distances depend on its faces alone; with a memo,
/// the cells seen before are looked up.
template <class TriangleMesh, class VertexPointMap>
std::vector<double> distance_to_cell_centres(const TriangleMesh& tm, VertexPointMap vpm,
                                             const Segmentation<TriangleMesh>& cells, Centre_distance_memo* memo = nullptr)
{
  struct Dual_edge {
    double length;
  };
  using Dual = boost::compressed_sparse_row_graph<boost::directedS, boost::no_property, Dual_edge>;
  auto findex = get(boost::face_index, tm);
  const std::size_t nf = num_faces(tm);
  auto centroid = [&](auto f) {
    auto h = halfedge(f, tm);
    return CGAL::centroid(get(vpm, source(h, tm)), get(vpm, target(h, tm)), get(vpm, target(next(h, tm), tm)));
  };
  std::vector<double> distance(nf, std::numeric_limits<double>::infinity());
  const std::size_t nc = cells.number_of_patches();
  std::vector<char> to_compute(nc, 1);
  std::vector<std::vector<std::size_t>> keys(memo ? nc : 0);
  if(memo)
    for(std::size_t p = 0; p < nc; ++p) {
      for(auto f : cells.patch_faces[p]) keys[p].push_back(get(findex, f));
      std::sort(keys[p].begin(), keys[p].end());
      const auto found = memo->find(keys[p]);
      if(found == memo->end()) continue;
      to_compute[p] = 0;
      for(std::size_t i = 0; i < keys[p].size(); ++i) distance[keys[p][i]] = found->second[i];
    }
  // The dual graph of the faces to compute only, in compressed rows over
  // local numbers (a graph of the whole mesh each round cost O(mesh) when
  // most cells are in the memo). Distances do not depend on the numbering.
  std::vector<std::size_t> local(nf, nf), mesh_face;
  for(auto f : faces(tm)) {
    const std::size_t i = get(findex, f);
    if(cells.face_patch[i] == Segmentation<TriangleMesh>::no_patch || !to_compute[cells.face_patch[i]]) continue;
    local[i] = mesh_face.size();
    mesh_face.push_back(i);
  }
  std::vector<std::pair<std::size_t, std::size_t>> arcs;
  std::vector<Dual_edge> lengths;
  std::vector<std::size_t> border;
  for(auto f : faces(tm)) {
    const std::size_t i = get(findex, f);
    if(local[i] == nf) continue;
    bool on_border = false;
    for(auto h : CGAL::halfedges_around_face(halfedge(f, tm), tm)) {
      const auto g = face(opposite(h, tm), tm);
      if(g == boost::graph_traits<TriangleMesh>::null_face() || cells.face_patch[get(findex, g)] != cells.face_patch[i]) {
        on_border = true;
        continue;
      }
      const std::size_t j = get(findex, g);
      if(i < j) {
        const double length = std::sqrt(CGAL::to_double(CGAL::squared_distance(centroid(f), centroid(g))));
        arcs.emplace_back(local[i], local[j]);
        arcs.emplace_back(local[j], local[i]);
        lengths.push_back(Dual_edge{length});
        lengths.push_back(Dual_edge{length});
      }
    }
    if(on_border) border.push_back(local[i]);
  }
  if(border.empty()) return distance;
  const Dual dual(boost::edges_are_unsorted_multi_pass, arcs.begin(), arcs.end(), lengths.begin(), mesh_face.size());
  const auto weight = get(&Dual_edge::length, dual);
  auto dindex = get(boost::vertex_index, dual);
  std::vector<double> depth(mesh_face.size(), 0.);
  // Distances only (no nearest source), the same bit for bit with any heap:
  // the 4-ary one is the fastest (doc/performance.md).
  multi_source_dijkstra<Quaternary_heap_tag>(dual, border, weight, boost::make_iterator_property_map(depth.begin(), dindex));
  // The deepest face of each cell (on a tie, the one whose centroid comes
  // first in lexicographic order: a rule of the surface, not of the numbering).
  std::vector<std::size_t> deepest;
  for(std::size_t p = 0; p < nc; ++p) {
    if(cells.patch_faces[p].empty() || !to_compute[p]) continue;
    auto best = cells.patch_faces[p].front();
    for(auto f : cells.patch_faces[p]) {
      const double df = depth[local[get(findex, f)]], db = depth[local[get(findex, best)]];
      if(df > db || (df == db && centroid(f) < centroid(best))) best = f;
    }
    deepest.push_back(local[get(findex, best)]);
  }
  std::vector<double> found(mesh_face.size(), std::numeric_limits<double>::infinity());
  multi_source_dijkstra<Quaternary_heap_tag>(dual, deepest, weight, boost::make_iterator_property_map(found.begin(), dindex));
  for(std::size_t p = 0; p < nc; ++p) {
    if(!to_compute[p]) continue;
    for(auto f : cells.patch_faces[p]) distance[get(findex, f)] = found[local[get(findex, f)]];
    if(memo) {
      std::vector<double> values;
      for(std::size_t i : keys[p]) values.push_back(found[local[i]]);
      memo->emplace(std::move(keys[p]), std::move(values));
    }
  }
  return distance;
}

} // namespace internal
} // namespace diffuv

#endif // DIFFUV_LAYOUT_INTERNAL_CELL_CENTRES_H
