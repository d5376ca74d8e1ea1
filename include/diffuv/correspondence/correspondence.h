// diffuv: points of mesh A to points of mesh B through (region, u, v).
//
// A patch of A and a patch of B correspond when they have the same key
// (`Patch_key`: region label, part, rank). A point of A takes its (u,v) in its chart, and the point of
// B's corresponding chart with that (u,v) is found by the atlas's point
// location (kd-tree nearest vertex, then the triangle containing (u,v); the
// nearest point of the chart if none does). Nothing uses 3D positions of one
// mesh against the other: the meshes may differ in position, scale and pose.
#ifndef DIFFUV_CORRESPONDENCE_CORRESPONDENCE_H
#define DIFFUV_CORRESPONDENCE_CORRESPONDENCE_H

#include <diffuv/atlas/Uv_atlas.h>
#include <diffuv/correspondence/labelled_atlas.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Polygon_mesh_processing/locate.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

namespace diffuv {

/// Where a point of mesh A lands on mesh B.
template <class TriangleMesh, class Point_3>
struct Surface_point {
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  static constexpr std::size_t no_chart = Uv_atlas<TriangleMesh>::no_chart;

  face_descriptor face = boost::graph_traits<TriangleMesh>::null_face();  ///< the face of B
  /// Barycentric coordinates in CGAL's `Face_location` order: source(halfedge(f)),
  /// target(halfedge(f)), target(next(halfedge(f))).
  std::array<double, 3> barycentric{{0., 0., 0.}};
  Point_3 point;                  ///< the 3D point on B
  std::size_t chart = no_chart;   ///< B's chart (`no_chart`: not mapped, the patch has no counterpart)
  bool inside = false;            ///< (u,v) fell in a triangle of B's chart (else: the chart's nearest point)
  double uv_distance = 0.;        ///< uv distance from (u,v) to the located point (0 when inside)

  bool mapped() const { return chart != no_chart; }
};

/// How the patches of two labelled atlases were paired.
struct Region_match_report {
  std::size_t matched_patches = 0;        ///< patches of A with a counterpart in B
  std::vector<int> matched_labels;        ///< labels with at least one matched patch, increasing
  std::vector<int> labels_only_in_a;      ///< labels of A's patches that B lacks
  std::vector<int> labels_only_in_b;      ///< labels of B's patches that A lacks
  /// Patches whose label is in both meshes but whose piece is not (the label
  /// was cut into different pieces, or a patch could not be mapped), by key
  /// (`patch_name()` names them).
  std::vector<Patch_key> unmatched_patches_a, unmatched_patches_b;
  /// Labels in both meshes cut into a different number of patches (pieces of
  /// a label pair by decreasing area, which is then a guess: check them).
  std::vector<int> labels_with_different_pieces;
};

/// Maps points of mesh A to mesh B through (region, u, v).
///
/// \tparam MeshA, MeshB models of `FaceListGraph` with internal indices (as `Uv_atlas` needs)
/// \tparam VertexPointMapB a readable property map from B's vertices to points
template <class MeshA, class MeshB,
          class VertexPointMapB = typename boost::property_map<MeshB, CGAL::vertex_point_t>::const_type>
class Atlas_correspondence {
public:
  using vertex_a = typename boost::graph_traits<MeshA>::vertex_descriptor;
  using face_a = typename boost::graph_traits<MeshA>::face_descriptor;
  using halfedge_a = typename boost::graph_traits<MeshA>::halfedge_descriptor;
  using Point_3 = typename boost::property_traits<VertexPointMapB>::value_type;
  using Point = Surface_point<MeshB, Point_3>;
  using Point_2 = typename Uv_atlas<MeshA>::Point_2;
  using Key = Patch_key;  // (label, part, rank among patches of that label and part)
  static constexpr std::size_t no_chart = Uv_atlas<MeshA>::no_chart;

  /// Pairs the charts of `a` and `b` by patch key. Both atlases must outlive this object.
  Atlas_correspondence(const Labelled_atlas<MeshA>& a, const Labelled_atlas<MeshB>& b, VertexPointMapB vpm_b)
    : a_(a), b_(b), vpm_b_(vpm_b)
  {
    pair_charts();
  }

  /// Same, with B's internal vertex points.
  Atlas_correspondence(const Labelled_atlas<MeshA>& a, const Labelled_atlas<MeshB>& b)
    : Atlas_correspondence(a, b, get(CGAL::vertex_point, b.mesh()))
  {}

  const Region_match_report& report() const { return report_; }

  /// B's chart paired with A's chart `chart_a`, or `no_chart`.
  std::size_t chart_b(std::size_t chart_a) const
  {
    return chart_a < b_chart_of_.size() ? b_chart_of_[chart_a] : no_chart;
  }

  /// The point of B with coordinates `uv` in the chart paired with A's chart `chart_a`.
  Point map_uv(std::size_t chart_a, const Point_2& uv) const
  {
    Point result;
    const std::size_t cb = chart_b(chart_a);
    if(cb == no_chart) return result;
    const auto loc = b_.atlas.locate(cb, uv);
    result.face = loc.location.first;
    result.barycentric = {{loc.location.second[0], loc.location.second[1], loc.location.second[2]}};
    result.point = CGAL::Polygon_mesh_processing::construct_point(
        loc.location, b_.mesh(), CGAL::parameters::vertex_point_map(vpm_b_));
    result.chart = cb;
    result.inside = loc.inside;
    result.uv_distance = loc.uv_distance;
    return result;
  }

  /// The image of vertex `v` of A. A vertex on the border between patches is
  /// in several charts; its image is taken from the one with the smallest key
  /// that has a counterpart, so it does not depend on where it is asked from.
  /// Unmapped (`mapped()` false) if none of its charts has a counterpart.
  Point map_vertex(vertex_a v) const
  {
    const std::size_t c = canonical_chart(v);
    if(c == no_chart) return Point();
    return map_uv(c, uv_in(v, c));
  }

  /// The image of vertex `v` taken from A's chart `chart_a` (for seam studies).
  /// Unmapped if `v` is not in that chart or the chart has no counterpart.
  Point map_vertex(vertex_a v, std::size_t chart_a) const
  {
    const Point_2 uv = uv_in(v, chart_a);
    return std::isnan(uv.x()) ? Point() : map_uv(chart_a, uv);
  }

  /// The image of the point of face `f` of A with barycentric coordinates
  /// `bary` (CGAL's `Face_location` order). A point on an edge between two
  /// patches, or at a vertex, is mapped from the same chart whichever face it
  /// is given on (the one with the smallest key, as `map_vertex()`).
  Point map_point(face_a f, const std::array<double, 3>& bary) const
  {
    const MeshA& tm = a_.mesh();
    const halfedge_a h = halfedge(f, tm);
    const vertex_a corner[3] = {source(h, tm), target(h, tm), target(next(h, tm), tm)};
    int nonzero = 0, last = 0;
    for(int k = 0; k < 3; ++k)
      if(bary[k] != 0.) { ++nonzero; last = k; }
    if(nonzero == 1) return map_vertex(corner[last]);

    std::size_t c = a_.atlas.chart_of(f);
    if(nonzero == 2) {
      // On an edge: the chart of the face across it may take precedence.
      int zero = 0;
      while(bary[zero] != 0.) ++zero;
      const vertex_a p = corner[(zero + 1) % 3], q = corner[(zero + 2) % 3];
      const auto he = halfedge(p, q, tm);
      if(he.second && !is_border(opposite(he.first, tm), tm)) {
        const std::size_t other = a_.atlas.chart_of(face(opposite(he.first, tm), tm));
        if(other != c && other != no_chart && chart_b(other) != no_chart &&
           (chart_b(c) == no_chart || key_a_[other] < key_a_[c]))
          c = other;
      }
    }
    if(c == no_chart) return Point();
    double u = 0., w = 0.;
    for(int k = 0; k < 3; ++k) {
      if(bary[k] == 0.) continue;
      const Point_2 p = uv_in(corner[k], c);
      u += bary[k] * p.x();
      w += bary[k] * p.y();
    }
    return map_uv(c, Point_2(u, w));
  }

  /// The images of all vertices of A, by vertex index.
  std::vector<Point> map_vertices() const
  {
    const MeshA& tm = a_.mesh();
    auto vindex = get(boost::vertex_index, tm);
    std::vector<Point> images(num_vertices(tm));
    for(vertex_a v : vertices(tm)) images[get(vindex, v)] = map_vertex(v);
    return images;
  }

  /// The key (label, part, rank) of A's chart `c`.
  const Key& key_a(std::size_t c) const { return key_a_.at(c); }

private:
  // The (u,v) of v in A's chart c; NaN if v is not in it.
  Point_2 uv_in(vertex_a v, std::size_t c) const { return get(a_.atlas.chart_uv_map(c), v); }

  std::size_t canonical_chart(vertex_a v) const
  {
    const auto e = a_.atlas.entries(v);
    std::size_t best = no_chart;
    for(auto it = e.first; it != e.second; ++it)
      if(chart_b(it->chart) != no_chart && (best == no_chart || key_a_[it->chart] < key_a_[best])) best = it->chart;
    return best;
  }

  // Keys of the mapped patches of an atlas, by chart.
  template <class Mesh>
  static std::vector<Key> chart_keys(const Labelled_atlas<Mesh>& la, std::vector<Key>& unmapped)
  {
    std::vector<Key> keys(la.atlas.number_of_charts());
    const std::vector<Patch_key> by_patch = patch_keys(la.segmentation);
    for(std::size_t p = 0; p < by_patch.size(); ++p) {
      const std::size_t c = p < la.patches.size() ? la.patches[p].chart : no_chart;
      if(c == no_chart) unmapped.push_back(by_patch[p]);
      else keys[c] = by_patch[p];
    }
    return keys;
  }

  void pair_charts()
  {
    std::vector<Key> unmapped_a, unmapped_b;
    key_a_ = chart_keys(a_, unmapped_a);
    const std::vector<Key> key_b = chart_keys(b_, unmapped_b);
    std::map<Key, std::size_t> chart_of_key_b;
    for(std::size_t c = 0; c < key_b.size(); ++c) chart_of_key_b.emplace(key_b[c], c);

    std::set<int> labels_a, labels_b, matched;
    for(const Key& k : key_a_) labels_a.insert(std::get<0>(k));
    for(const Key& k : unmapped_a) labels_a.insert(std::get<0>(k));
    for(const Key& k : key_b) labels_b.insert(std::get<0>(k));
    for(const Key& k : unmapped_b) labels_b.insert(std::get<0>(k));

    b_chart_of_.assign(key_a_.size(), no_chart);
    std::vector<bool> b_used(key_b.size(), false);
    for(std::size_t c = 0; c < key_a_.size(); ++c) {
      auto it = chart_of_key_b.find(key_a_[c]);
      if(it == chart_of_key_b.end()) {
        if(labels_b.count(std::get<0>(key_a_[c])))
          report_.unmatched_patches_a.push_back(key_a_[c]);
        continue;
      }
      b_chart_of_[c] = it->second;
      b_used[it->second] = true;
      matched.insert(std::get<0>(key_a_[c]));
      ++report_.matched_patches;
    }
    for(const Key& k : unmapped_a)
      if(labels_b.count(std::get<0>(k))) report_.unmatched_patches_a.push_back(k);
    for(std::size_t c = 0; c < key_b.size(); ++c)
      if(!b_used[c] && labels_a.count(std::get<0>(key_b[c])))
        report_.unmatched_patches_b.push_back(key_b[c]);
    for(const Key& k : unmapped_b)
      if(labels_a.count(std::get<0>(k))) report_.unmatched_patches_b.push_back(k);
    std::map<int, std::size_t> pieces_a, pieces_b;
    for(const Key& k : key_a_) ++pieces_a[std::get<0>(k)];
    for(const Key& k : unmapped_a) ++pieces_a[std::get<0>(k)];
    for(const Key& k : key_b) ++pieces_b[std::get<0>(k)];
    for(const Key& k : unmapped_b) ++pieces_b[std::get<0>(k)];
    for(const auto& [label, count] : pieces_a) {
      const auto it = pieces_b.find(label);
      if(it != pieces_b.end() && it->second != count) report_.labels_with_different_pieces.push_back(label);
    }
    report_.matched_labels.assign(matched.begin(), matched.end());
    std::set_difference(labels_a.begin(), labels_a.end(), labels_b.begin(), labels_b.end(),
                        std::back_inserter(report_.labels_only_in_a));
    std::set_difference(labels_b.begin(), labels_b.end(), labels_a.begin(), labels_a.end(),
                        std::back_inserter(report_.labels_only_in_b));
  }

  const Labelled_atlas<MeshA>& a_;
  const Labelled_atlas<MeshB>& b_;
  VertexPointMapB vpm_b_;
  std::vector<Key> key_a_;              // by chart of A
  std::vector<std::size_t> b_chart_of_; // by chart of A
  Region_match_report report_;
};

} // namespace diffuv

#endif // DIFFUV_CORRESPONDENCE_CORRESPONDENCE_H
