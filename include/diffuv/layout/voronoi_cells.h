// diffuv: graph-Voronoi cells of a set of faces, with seeds placed by
// farthest-point sampling and relaxed (Lloyd-like) so that cells are round.
//
// The cells are the first step of the four-sided layout (layout/quad_layout.h):
// each cell is later split into quads through its centre and the midpoints
// of its arcs. Distances run on the dual graph (faces joined across edges,
// weighted by the distance between their centroids), so every rule here
// depends on the surface only, not on vertex or face numbering.
#ifndef DIFFUV_LAYOUT_VORONOI_CELLS_H
#define DIFFUV_LAYOUT_VORONOI_CELLS_H

#include <diffuv/graph/multi_source_dijkstra.h>
#include <diffuv/layout/voronoi_discs.h>
#include <diffuv/patches/segmentation.h>
#include <diffuv/patches/smooth_region_borders.h>

#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/centroid.h>
#include <CGAL/squared_distance_3.h>

#include <boost/graph/compressed_sparse_row_graph.hpp>
#include <boost/property_map/function_property_map.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numeric>
#include <unordered_map>
#include <utility>
#include <vector>

namespace diffuv {

/// Graph-Voronoi cells of a connected set of faces ("the region").
///
/// The dual graph is built once; seeds (positions in the region's face list)
/// are added one at a time, each by a bounded Dijkstra run (only the faces
/// that the new seed takes are visited). Faces are numbered by their position
/// in `faces()`.
template <class TriangleMesh, class VertexPointMap>
class Voronoi_cells {
public:
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  static constexpr int outside = std::numeric_limits<int>::min();  ///< label of faces not in the region

  /// Prepares the dual graph of `region` (a connected set of faces of `tm`).
  /// With `bend_length` > 0, a step between two faces also costs `bend_length`
  /// times the angle between their normals (radians): crossing a crease or going
  /// round a thin part counts more, so cells grow along tubes and shrink where
  /// the surface bends.
  Voronoi_cells(const TriangleMesh& tm, std::vector<face_descriptor> region, VertexPointMap vpm, double bend_length = 0.)
    : tm_(tm), vpm_(vpm), faces_(std::move(region)), dual_(faces_.size()),
      distance_(faces_.size(), std::numeric_limits<double>::infinity()), origin_(faces_.size(), 0), dijkstra_(dual_)
  {
    auto findex = get(boost::face_index, tm_);
    const std::size_t n = faces_.size();
    // A region much smaller than the mesh (one of thousands of painted
    // regions) keeps its positions in a hash table: an array of the mesh's
    // size per region made such meshes quadratic.
    if(16 * n < static_cast<std::size_t>(num_faces(tm_))) {
      sparse_position_.reserve(n);
      for(std::size_t i = 0; i < n; ++i) sparse_position_.emplace(get(findex, faces_[i]), i);
    } else {
      position_.assign(num_faces(tm_), n);
      for(std::size_t i = 0; i < n; ++i) position_[get(findex, faces_[i])] = i;
    }
    for(std::size_t i = 0; i < n; ++i) centroids_.push_back(centroid(faces_[i]));
    // Both directions of each dual edge, in the order the edges are found:
    // each face's neighbours come out in that order (the compressed rows keep
    // it), as they did from the adjacency list this graph replaced.
    std::vector<std::pair<std::size_t, std::size_t>> arcs;
    std::vector<Dual_edge> weights;
    for(std::size_t i = 0; i < n; ++i)
      for(auto h : CGAL::halfedges_around_face(halfedge(faces_[i], tm_), tm_)) {
        const auto g = face(opposite(h, tm_), tm_);
        if(g == boost::graph_traits<TriangleMesh>::null_face()) continue;
        const std::size_t j = position_of(get(findex, g));
        if(j < n && i < j) {
          double w = std::sqrt(CGAL::to_double(CGAL::squared_distance(centroids_[i], centroids_[j])));
          if(bend_length > 0) {
            const auto ni = CGAL::Polygon_mesh_processing::compute_face_normal(faces_[i], tm_, CGAL::parameters::vertex_point_map(vpm_));
            const auto nj = CGAL::Polygon_mesh_processing::compute_face_normal(g, tm_, CGAL::parameters::vertex_point_map(vpm_));
            w += bend_length * std::acos(std::clamp(CGAL::to_double(ni * nj), -1.0, 1.0));
          }
          arcs.emplace_back(i, j);
          arcs.emplace_back(j, i);
          weights.push_back(Dual_edge{w});
          weights.push_back(Dual_edge{w});
        }
      }
    dual_ = Dual(boost::edges_are_unsorted_multi_pass, arcs.begin(), arcs.end(), weights.begin(), n);
  }

  const std::vector<face_descriptor>& faces() const { return faces_; }
  const std::vector<std::size_t>& seeds() const { return seeds_; }
  /// #faces() entries: distance (through the dual graph) to the nearest seed.
  const std::vector<double>& distance() const { return distance_; }
  /// #faces() entries: the position in `seeds()` of the nearest seed.
  const std::vector<std::size_t>& origin() const { return origin_; }
  /// The position of face `f` in `faces()`, or `faces().size()` if it is not in the region.
  std::size_t position(face_descriptor f) const { return position_of(get(get(boost::face_index, tm_), f)); }

  /// Replaces the seeds (positions in `faces()`) and recomputes every distance.
  void set_seeds(std::vector<std::size_t> seeds)
  {
    seeds_ = std::move(seeds);
    dijkstra_.run(seeds_, weight_map(), distance_map(), origin_map());
  }

  /// Adds one seed: only the faces now nearer to it than to every other seed change.
  void add_seed(std::size_t s)
  {
    seeds_.push_back(s);
    dijkstra_.add_source(s, seeds_.size() - 1, weight_map(), distance_map(), origin_map());
  }

  /// The face farthest from the seeds among those for which `keep(i)` holds
  /// (on a tie, the one whose centroid comes first lexicographically: a rule
  /// of the surface, not of the numbering), or `faces().size()` if none.
  template <class Keep>
  std::size_t farthest(Keep keep) const
  {
    std::size_t best = faces_.size();
    for(std::size_t i = 0; i < faces_.size(); ++i)
      if(keep(i) && distance_[i] < std::numeric_limits<double>::infinity() &&
         (best == faces_.size() || distance_[i] > distance_[best] ||
          (distance_[i] == distance_[best] && centroids_[i] < centroids_[best])))
        best = i;
    return best;
  }

  /// Replaces seed `k` by three seeds around it, half-way to the farthest face
  /// of its cell and as far from each other as that ring allows: a cap (a cell
  /// with one neighbour all around) becomes three cells meeting in its middle.
  /// Returns false, changing nothing, if the ring has fewer than three faces.
  bool split_in_three(std::size_t k)
  {
    double radius = 0;
    for(std::size_t i = 0; i < faces_.size(); ++i)
      if(origin_[i] == k && distance_[i] < std::numeric_limits<double>::infinity()) radius = std::max(radius, distance_[i]);
    std::vector<std::size_t> ring;
    for(std::size_t i = 0; i < faces_.size(); ++i)
      if(origin_[i] == k && std::abs(distance_[i] - radius / 2) <= radius / 6) ring.push_back(i);
    if(ring.size() < 3 || !(radius > 0)) return false;
    auto squared = [&](std::size_t a, std::size_t b) { return CGAL::to_double(CGAL::squared_distance(centroids_[a], centroids_[b])); };
    // The first: nearest the half radius; then each one as far as possible
    // from those chosen (ties to the centroid first in lexicographic order).
    std::vector<std::size_t> chosen;
    auto better = [&](std::size_t i, std::size_t best, double di, double db) {
      return di > db || (di == db && centroids_[i] < centroids_[best]);
    };
    std::size_t first = ring.front();
    for(std::size_t i : ring)
      if(better(i, first, -std::abs(distance_[i] - radius / 2), -std::abs(distance_[first] - radius / 2))) first = i;
    chosen.push_back(first);
    while(chosen.size() < 3) {
      std::size_t best = faces_.size();
      double best_d = -1;
      for(std::size_t i : ring) {
        double d = std::numeric_limits<double>::infinity();
        for(std::size_t c : chosen) d = std::min(d, squared(i, c));
        if(best == faces_.size() || better(i, best, d, best_d)) { best = i; best_d = d; }
      }
      if(!(best_d > 0)) return false;
      chosen.push_back(best);
    }
    // Only cell k and the cells next to it change: moved and added seeds
    // instead of a whole run (a mesh with many fingers has tens of caps).
    seeds_[k] = chosen[0];
    dijkstra_.move_source(k, chosen[0], weight_map(), distance_map(), origin_map());
    add_seed(chosen[1]);
    add_seed(chosen[2]);
    return true;
  }

  /// Farthest-point sampling up to `count` seeds. The first seed is the face
  /// farthest from the region's area-weighted centroid: the same face whatever
  /// the numbering, the position or the orientation of the mesh.
  void farthest_point_seeds(std::size_t count)
  {
    if(faces_.empty()) return;
    set_seeds({internal::farthest_from_area_centroid(
        tm_, vpm_, faces_, centroids_, [&](std::size_t i, std::size_t j) { return centroids_[i] < centroids_[j]; })});
    auto all = [](std::size_t) { return true; };
    while(seeds_.size() < std::min(count, faces_.size())) {
      const std::size_t s = farthest(all);
      if(s == faces_.size() || !(distance_[s] > 0.)) break;
      add_seed(s);
    }
  }

  /// Labels of the faces of the mesh (#F entries): the seed of each face of
  /// the region, borders smoothed (`smooth_region_borders()`, faces visited
  /// farthest from the seeds first), `outside` for the other faces.
  std::vector<int> labels() const
  {
    auto findex = get(boost::face_index, tm_);
    std::vector<int> result(num_faces(tm_), outside);
    for(std::size_t i = 0; i < faces_.size(); ++i) result[get(findex, faces_[i])] = static_cast<int>(origin_[i]);
    // The keys are sorted next to their positions rather than through them
    // (fewer cache misses). std::sort moves elements as the comparisons
    // decide, so faces with equal keys end in the same order as before.
    struct Keyed {
      double distance;
      std::size_t origin, i;
    };
    std::vector<Keyed> by_distance(faces_.size());
    for(std::size_t i = 0; i < faces_.size(); ++i) by_distance[i] = {distance_[i], origin_[i], i};
    std::sort(by_distance.begin(), by_distance.end(), [](const Keyed& a, const Keyed& b) {
      return a.distance != b.distance ? a.distance > b.distance : a.origin < b.origin;
    });
    std::vector<face_descriptor> order;
    order.reserve(faces_.size());
    for(const Keyed& k : by_distance) order.push_back(faces_[k.i]);
    smooth_region_borders(tm_, result, 3, outside, &order);
    return result;
  }

  /// Moves every seed to the deepest face of its cell (the face farthest,
  /// through the dual graph, from the cell's border), `steps` times: a
  /// Lloyd-like relaxation that makes cells round and evenly sized.
  void relax(std::size_t steps)
  {
    for(std::size_t step = 0; step < steps && !seeds_.empty(); ++step) {
      const std::vector<std::size_t> cell = origin_;
      std::vector<std::size_t> border;
      for(std::size_t i = 0; i < faces_.size(); ++i) {
        bool on_border = false;
        for(auto h : CGAL::halfedges_around_face(halfedge(faces_[i], tm_), tm_)) {
          const auto g = face(opposite(h, tm_), tm_);
          const std::size_t j = g == boost::graph_traits<TriangleMesh>::null_face() ? faces_.size() : position(g);
          if(j == faces_.size() || cell[j] != cell[i]) on_border = true;
        }
        if(on_border) border.push_back(i);
      }
      // Depth inside each cell: edges between two cells cost +infinity.
      const auto base = weight_map();
      auto inside = boost::make_function_property_map<typename boost::graph_traits<Dual>::edge_descriptor, double>(
          [&](const typename boost::graph_traits<Dual>::edge_descriptor& e) {
            return cell[source(e, dual_)] == cell[target(e, dual_)] ? get(base, e)
                                                                    : std::numeric_limits<double>::infinity();
          });
      std::vector<double> depth(faces_.size(), 0.);
      // Only distances are used here, and those are the same bit for bit
      // with any heap: the 4-ary one is the fastest (doc/performance.md).
      if(!border.empty())
        multi_source_dijkstra<Quaternary_heap_tag>(dual_, border, inside,
                              boost::make_iterator_property_map(depth.begin(), get(boost::vertex_index, dual_)));
      std::vector<std::size_t> deepest(seeds_.size(), faces_.size());
      for(std::size_t i = 0; i < faces_.size(); ++i) {
        std::size_t& d = deepest[cell[i]];
        if(d == faces_.size() || depth[i] > depth[d] || (depth[i] == depth[d] && centroids_[i] < centroids_[d])) d = i;
      }
      std::vector<std::size_t> moved;
      for(std::size_t s = 0; s < seeds_.size(); ++s) moved.push_back(deepest[s] == faces_.size() ? seeds_[s] : deepest[s]);
      if(moved == seeds_) break;
      set_seeds(std::move(moved));
    }
  }

private:
  // The dual graph in compressed rows: both directions of each edge, its
  // weight stored next to its target (faster to build and to walk than an
  // adjacency list).
  struct Dual_edge {
    double weight;
  };
  using Dual = boost::compressed_sparse_row_graph<boost::directedS, boost::no_property, Dual_edge>;
  using Point = typename boost::property_traits<VertexPointMap>::value_type;

  Point centroid(face_descriptor f) const
  {
    const auto h = halfedge(f, tm_);
    return CGAL::centroid(get(vpm_, source(h, tm_)), get(vpm_, target(h, tm_)), get(vpm_, target(next(h, tm_), tm_)));
  }
  auto weight_map() const { return get(&Dual_edge::weight, dual_); }
  auto distance_map() { return boost::make_iterator_property_map(distance_.begin(), get(boost::vertex_index, dual_)); }
  auto origin_map() { return boost::make_iterator_property_map(origin_.begin(), get(boost::vertex_index, dual_)); }

  const TriangleMesh& tm_;
  VertexPointMap vpm_;
  std::vector<face_descriptor> faces_;
  std::vector<std::size_t> position_;  // by face index (empty for a small region)
  std::unordered_map<std::size_t, std::size_t> sparse_position_;  // face index -> position, for a small region

  std::size_t position_of(std::size_t face_index) const
  {
    if(!position_.empty()) return position_[face_index];
    const auto found = sparse_position_.find(face_index);
    return found == sparse_position_.end() ? faces_.size() : found->second;
  }
  std::vector<Point> centroids_;
  Dual dual_;
  std::vector<std::size_t> seeds_;
  std::vector<double> distance_;
  std::vector<std::size_t> origin_;
  // The 4-ary heap: the nearest seed on an exact tie of distances depends on
  // the order of settling, and this heap gives the Fibonacci heap's layouts
  // on every mesh of the data set (doc/layout.md, "Layout time", 8).
  Multi_source_dijkstra<Dual, Quaternary_heap_tag> dijkstra_;  // after dual_: sized by its vertices
};

} // namespace diffuv

#endif // DIFFUV_LAYOUT_VORONOI_CELLS_H
