// diffuv: each face's distance to the centre of its cell, the point the
// four-sided layout's fans start from and its arcs' midpoints are measured to.
#ifndef DIFFUV_LAYOUT_INTERNAL_CELL_CENTRES_H
#define DIFFUV_LAYOUT_INTERNAL_CELL_CENTRES_H

#include <diffuv/graph/multi_source_dijkstra.h>
#include <diffuv/internal/index_list_hash.h>
#include <diffuv/patches/segmentation.h>

#include <CGAL/boost/graph/iterator.h>

#include <boost/graph/adjacency_list.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <unordered_map>
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
  using Dual = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, boost::no_property,
                                     boost::property<boost::edge_weight_t, double>>;
  auto findex = get(boost::face_index, tm);
  const std::size_t nf = num_faces(tm);
  auto centroid = [&](auto f) {
    auto h = halfedge(f, tm);
    return CGAL::centroid(get(vpm, source(h, tm)), get(vpm, target(h, tm)), get(vpm, target(next(h, tm), tm)));
  };
  std::vector<double> depth(nf, 0.), distance(nf, std::numeric_limits<double>::infinity());
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
  Dual dual(nf);
  std::vector<std::size_t> border;
  for(auto f : faces(tm)) {
    const std::size_t i = get(findex, f);
    if(cells.face_patch[i] == Segmentation<TriangleMesh>::no_patch || !to_compute[cells.face_patch[i]]) continue;
    bool on_border = false;
    for(auto h : CGAL::halfedges_around_face(halfedge(f, tm), tm)) {
      const auto g = face(opposite(h, tm), tm);
      if(g == boost::graph_traits<TriangleMesh>::null_face() || cells.face_patch[get(findex, g)] != cells.face_patch[i]) {
        on_border = true;
        continue;
      }
      const std::size_t j = get(findex, g);
      if(i < j) boost::add_edge(i, j, std::sqrt(CGAL::to_double(CGAL::squared_distance(centroid(f), centroid(g)))), dual);
    }
    if(on_border) border.push_back(i);
  }
  auto dindex = get(boost::vertex_index, dual);
  if(border.empty()) return distance;
  // Distances only (no nearest source), the same bit for bit with any heap:
  // the 4-ary one is the fastest (doc/performance.md).
  multi_source_dijkstra<Quaternary_heap_tag>(dual, border, get(boost::edge_weight, dual), boost::make_iterator_property_map(depth.begin(), dindex));
  // The deepest face of each cell (on a tie, the one whose centroid comes
  // first in lexicographic order: a rule of the surface, not of the numbering).
  std::vector<std::size_t> deepest;
  for(std::size_t p = 0; p < nc; ++p) {
    if(cells.patch_faces[p].empty() || !to_compute[p]) continue;
    auto best = cells.patch_faces[p].front();
    for(auto f : cells.patch_faces[p]) {
      const double df = depth[get(findex, f)], db = depth[get(findex, best)];
      if(df > db || (df == db && centroid(f) < centroid(best))) best = f;
    }
    deepest.push_back(get(findex, best));
  }
  std::vector<double> found(nf, std::numeric_limits<double>::infinity());
  multi_source_dijkstra<Quaternary_heap_tag>(dual, deepest, get(boost::edge_weight, dual), boost::make_iterator_property_map(found.begin(), dindex));
  for(std::size_t p = 0; p < nc; ++p) {
    if(!to_compute[p]) continue;
    for(auto f : cells.patch_faces[p]) distance[get(findex, f)] = found[get(findex, f)];
    if(memo) {
      std::vector<double> values;
      for(std::size_t i : keys[p]) values.push_back(found[i]);
      memo->emplace(std::move(keys[p]), std::move(values));
    }
  }
  return distance;
}

} // namespace internal
} // namespace diffuv

#endif // DIFFUV_LAYOUT_INTERNAL_CELL_CENTRES_H
