// diffuv: the automatic segmentation: a region cut into topological discs by
// farthest-point seeds and a graph-Voronoi partition of its faces, refined
// until every piece is a disc. `disc_patches()` uses it for the
// `Patch_layout::discs` layout and to cut labelled regions that are not discs.
#ifndef DIFFUV_LAYOUT_VORONOI_DISCS_H
#define DIFFUV_LAYOUT_VORONOI_DISCS_H

#include <diffuv/graph/multi_source_dijkstra.h>
#include <diffuv/patches/merge_small_patches.h>
#include <diffuv/patches/patches_from_labels.h>
#include <diffuv/patches/segmentation.h>
#include <diffuv/patches/smooth_region_borders.h>

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

namespace internal {

// The position in `region` of the face whose centroid (`centroids`, one per
// face of `region`) is farthest from the region's area-weighted centroid,
// `before(i, j)` deciding ties: the first seed of farthest-point sampling, the
// same face whatever the numbering, the position or the orientation of the mesh.
template <class TriangleMesh, class VertexPointMap, class Point, class Before>
std::size_t farthest_from_area_centroid(const TriangleMesh& tm,
                                        VertexPointMap vpm,
                                        const std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>& region, const std::vector<Point>& centroids, Before before)
{
  double cx = 0, cy = 0, cz = 0, area = 0;
  for(std::size_t i = 0; i < region.size(); ++i) {
    const double a = CGAL::to_double(CGAL::Polygon_mesh_processing::face_area(region[i], tm, CGAL::parameters::vertex_point_map(vpm)));
    cx += a * CGAL::to_double(centroids[i].x());
    cy += a * CGAL::to_double(centroids[i].y());
    cz += a * CGAL::to_double(centroids[i].z());
    area += a;
  }
  if(area > 0) { cx /= area; cy /= area; cz /= area; }
  std::size_t first = 0;
  double far = -1;
  for(std::size_t i = 0; i < region.size(); ++i) {
    const double dx = CGAL::to_double(centroids[i].x()) - cx, dy = CGAL::to_double(centroids[i].y()) - cy,
                 dz = CGAL::to_double(centroids[i].z()) - cz;
    const double d = dx * dx + dy * dy + dz * dz;
    if(d > far || (d == far && before(i, first))) {
      far = d;
      first = i;
    }
  }
  return first;
}

} // namespace internal

/// Options of `voronoi_discs()`.
struct Voronoi_options {
  std::size_t patches = 12;       ///< how many seeds to start from (farthest-point sampling)
  std::size_t max_patches = 400;  ///< stop adding seeds beyond this many, even if some patch is not a disc
};

/// Cuts the faces `region` of `tm` into topological discs: farthest-point
/// seeds and a graph-Voronoi partition of the faces, computed by our
/// multi-source Dijkstra on the dual graph (faces joined across edges,
/// weighted by the distance between their centroids), region borders
/// smoothed (`smooth_region_borders()`), pieces with fewer than four boundary
/// vertices merged into a neighbour, and a new seed in each non-disc patch
/// (its face farthest from the seeds), until every patch is a disc.
///
/// Deterministic: the first seed is the face farthest from the region's
/// centroid, then farthest-point sampling, so the result does not depend on the
/// vertex or face order, nor on the mesh's position or orientation (except
/// when two faces are exactly equally far).
///
/// \param region the faces to cut (a connected set)
/// \param face_labels #F entries: receives, for the faces of `region`, labels
///        `first_label`, `first_label + 1`, ... (one per final patch); other faces untouched
/// \returns the number of seeds used
template <class TriangleMesh, class VertexPointMap>
std::size_t voronoi_discs(const TriangleMesh& tm,
                          VertexPointMap vpm,
                          const std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>& region, std::vector<int>& face_labels, int first_label,
                          const Voronoi_options& options = Voronoi_options())
{
  using Dual = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, boost::no_property,
                                     boost::property<boost::edge_weight_t, double>>;
  auto findex = get(boost::face_index, tm);
  const std::size_t n = region.size();
  if(n == 0) return 0;
  std::vector<std::size_t> local(num_faces(tm), n); // face index -> position in region
  for(std::size_t i = 0; i < n; ++i) local[get(findex, region[i])] = i;
  auto centroid = [&](auto f) {
    auto h = halfedge(f, tm);
    return CGAL::centroid(get(vpm, source(h, tm)), get(vpm, target(h, tm)), get(vpm, target(next(h, tm), tm)));
  };
  std::vector<Point_of<VertexPointMap>> centroids;
  for(std::size_t i = 0; i < n; ++i) centroids.push_back(centroid(region[i]));
  Dual dual(n);
  for(std::size_t i = 0; i < n; ++i)
    for(auto h : CGAL::halfedges_around_face(halfedge(region[i], tm), tm)) {
      const auto g = face(opposite(h, tm), tm);
      if(g == boost::graph_traits<TriangleMesh>::null_face()) continue;
      const std::size_t j = local[get(findex, g)];
      if(j < n && i < j)
        boost::add_edge(i, j, std::sqrt(CGAL::to_double(CGAL::squared_distance(centroids[i], centroids[j]))), dual);
    }

  Multi_source_dijkstra<Dual> dijkstra(dual);
  std::vector<double> distance(n);
  std::vector<std::size_t> origin(n, 0);
  auto dindex = get(boost::vertex_index, dual);
  auto dmap = boost::make_iterator_property_map(distance.begin(), dindex);
  auto omap = boost::make_iterator_property_map(origin.begin(), dindex);
  auto weight = get(boost::edge_weight, dual);
  auto farthest = [&](auto keep) { // the reached face with the largest distance among those kept, or n
    std::size_t best = n;
    for(std::size_t i = 0; i < n; ++i)
      if(keep(i) && distance[i] < std::numeric_limits<double>::infinity() && (best == n || distance[i] > distance[best]))
        best = i;
    return best;
  };
  auto all = [](std::size_t) { return true; };

  // The first seed (lowest face index on a tie).
  const std::size_t first_seed = internal::farthest_from_area_centroid(
      tm, vpm, region, centroids, [&](std::size_t i, std::size_t j) { return get(findex, region[i]) < get(findex, region[j]); });
  std::vector<std::size_t> seeds = {first_seed};
  const std::size_t target = options.patches > 0 ? options.patches : 1;
  dijkstra.run(seeds, weight, dmap, omap);
  // Each new seed only lowers the distances of the faces nearer to it: one
  // bounded run per seed instead of a whole run on all the seeds.
  auto add_seed = [&](std::size_t s) {
    seeds.push_back(s);
    dijkstra.add_source(s, seeds.size() - 1, weight, dmap, omap);
  };
  while(seeds.size() < target && seeds.size() < n) add_seed(farthest(all));

  while(true) {
    // Labels of the region's faces by cell; faces outside hidden behind one sentinel.
    std::vector<int> labels(num_faces(tm), std::numeric_limits<int>::min());
    for(std::size_t i = 0; i < n; ++i) labels[get(findex, region[i])] = static_cast<int>(origin[i]);
    // Visit faces farthest from the seeds first (an order of the surface, not of the numbering).
    std::vector<std::size_t> by_distance(n);
    std::iota(by_distance.begin(), by_distance.end(), 0);
    std::sort(by_distance.begin(), by_distance.end(), [&](std::size_t a, std::size_t b) {
      return distance[a] != distance[b] ? distance[a] > distance[b] : origin[a] < origin[b];
    });
    std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor> order;
    for(std::size_t i : by_distance) order.push_back(region[i]);
    smooth_region_borders(tm, labels, 3, std::numeric_limits<int>::min(), &order);
    Segmentation<TriangleMesh> seg = patches_from_labels(tm, vpm, labels);
    merge_small_patches(tm, vpm, labels, seg);

    // One new seed in every patch that is not a disc, where it is farthest from the seeds.
    std::vector<std::size_t> added;
    if(seeds.size() < options.max_patches) {
      std::vector<std::size_t> bad_patch(n, seg.number_of_patches());
      for(std::size_t p = 0; p < seg.number_of_patches(); ++p)
        if(!check_patch_disc(tm, seg, p))
          for(auto f : seg.patch_faces[p]) bad_patch[local[get(findex, f)]] = p;
      std::vector<std::size_t> best(seg.number_of_patches(), n);
      for(std::size_t i = 0; i < n; ++i) {
        const std::size_t p = bad_patch[i];
        if(p < seg.number_of_patches() && distance[i] > 0. &&
           (best[p] == n || distance[i] > distance[best[p]]))
          best[p] = i;
      }
      for(std::size_t i : best)
        if(i != n && seeds.size() + added.size() < options.max_patches) added.push_back(i);
    }
    if(added.empty()) { // every patch is a disc, or no seed can be added
      for(std::size_t p = 0; p < seg.number_of_patches(); ++p)
        for(auto f : seg.patch_faces[p]) face_labels[get(findex, f)] = first_label + static_cast<int>(p);
      return seeds.size();
    }
    for(std::size_t i : added) add_seed(i);
  }
}

} // namespace diffuv

#endif // DIFFUV_LAYOUT_VORONOI_DISCS_H
