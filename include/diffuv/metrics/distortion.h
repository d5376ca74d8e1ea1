// diffuv: how far a (u,v) chart is from an isometry, and whether it is one-to-one.
//
// Every measure is computed per triangle from the Jacobian J of the affine map
// that sends the 3D triangle, laid in its own orthonormal 2D frame, onto its
// (u,v) triangle. With sigma_max >= sigma_min the singular values of J:
//   - angle distortion is sigma_max / sigma_min (1 for a conformal map);
//   - Sander et al. 2001 ("Texture mapping progressive meshes") measure the
//     inverse map uv -> 3D, whose singular values are 1/sigma_min and
//     1/sigma_max, giving the L2 and L-infinity stretch.
// Area and stretch are normalised by the chart's total areas, so that a map
// that is an isometry up to a uniform scale scores exactly 1 everywhere.
#ifndef DIFFUV_METRICS_DISTORTION_H
#define DIFFUV_METRICS_DISTORTION_H

#include <diffuv/internal/index_marks.h>
#include <diffuv/internal/uv_triangle.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Bbox_2.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

namespace diffuv {

/// The distortion of one triangle of a chart.
///
/// For a degenerate triangle, `angle`, `area`, `stretch_l2` and `stretch_linf`
/// are `+inf`: the map squashes the triangle, which no finite number describes.
struct Triangle_distortion {
  double area_3d = 0;         ///< area of the 3D triangle
  double signed_area_uv = 0;  ///< signed area of the (u,v) triangle, positive when counter-clockwise in the face's vertex order
  double angle = 1;           ///< sigma_max / sigma_min of the 3D -> uv Jacobian (1 = conformal); reflections included, see `flipped`
  double area = 1;            ///< max(r, 1/r) with r = (A_uv / sum A_uv) / (A_3d / sum A_3d); 1 = area kept up to the chart's scale
  double stretch_l2 = 1;      ///< Sander's L2 stretch times sqrt(sum A_uv / sum A_3d); 1 = isometry up to scale
  double stretch_linf = 1;    ///< Sander's L-infinity stretch (largest singular value of uv -> 3D), same normalisation
  bool flipped = false;       ///< orientation opposite to the chart's majority (the sign of the total signed uv area); never set on a degenerate triangle
  bool degenerate = false;    ///< |signed uv area| or 3D area <= 1e-14 times the chart's total, or a face that is not a triangle
};

/// The distortion of a whole chart.
///
/// Means and maxima are taken over the non-degenerate faces only, weighted by
/// their 3D area; they are 0 when there is no such face.
struct Distortion_summary {
  std::size_t faces = 0;              ///< number of faces measured
  std::size_t flipped = 0;            ///< faces with `Triangle_distortion::flipped`
  std::size_t degenerate = 0;         ///< faces with `Triangle_distortion::degenerate`
  std::size_t overlapping_pairs = 0;  ///< pairs of faces whose (u,v) interiors overlap, see `count_overlapping_pairs()`
  double angle_mean = 0;              ///< 3D-area-weighted mean of the angle distortion
  double angle_max = 0;               ///< largest angle distortion
  double area_mean = 0;               ///< 3D-area-weighted mean of the area distortion
  double area_max = 0;                ///< largest area distortion
  double stretch_l2 = 0;              ///< Sander's global L2 stretch sqrt(sum L2_t^2 A3d_t / sum A3d_t), >= 1, 1 = isometry up to scale
  double stretch_linf = 0;            ///< largest L-infinity stretch of a face
  double measured_area = 0;           ///< 3D area of the non-degenerate faces: the weight of the means

  /// Whether the chart is one-to-one: no flipped, degenerate or overlapping face.
  bool injective() const { return flipped == 0 && degenerate == 0 && overlapping_pairs == 0; }
};

namespace internal {

/// The vertices of face `f`, and how many it has (only the first three are stored).
template <class TriangleMesh>
std::pair<std::array<typename boost::graph_traits<TriangleMesh>::vertex_descriptor, 3>, std::size_t>
face_vertices(typename boost::graph_traits<TriangleMesh>::face_descriptor f, const TriangleMesh& tm)
{
  std::array<typename boost::graph_traits<TriangleMesh>::vertex_descriptor, 3> vs{};
  std::size_t n = 0;
  for(auto v : CGAL::vertices_around_face(halfedge(f, tm), tm)) {
    if(n < 3) vs[n] = v;
    ++n;
  }
  return {vs, n};
}

template <class UvMap, class Vertex>
Uv_point uv_point(const UvMap& uv, const Vertex& v)
{
  const auto& q = get(uv, v);
  return Uv_point(CGAL::to_double(q.x()), CGAL::to_double(q.y()));
}

/// Whether every vertex of `t` lies on or to the right of the directed line (p, q).
inline bool weakly_right_of(const Uv_point& p, const Uv_point& q, const Uv_triangle& t)
{
  for(const Uv_point& x : t)
    if(CGAL::orientation(p, q, x) == CGAL::LEFT_TURN) return false;
  return true;
}

/// Whether two counter-clockwise triangles have overlapping interiors.
///
/// Why it is correct: the interiors of convex sets A and B meet iff the origin
/// is interior to the Minkowski difference A - B, a convex polygon whose edges
/// are parallel to edges of A or of B. The origin is outside or on the
/// boundary of A - B iff one of those edge lines weakly separates it, which
/// translates back to: one edge line of A or of B has the other triangle
/// entirely on its outer (right) side, boundary included. Every orientation
/// is exact, so shared edges and vertices are never mistaken for overlaps.
inline bool interiors_overlap(const Uv_triangle& a, const Uv_triangle& b)
{
  for(int i = 0; i < 3; ++i) {
    if(weakly_right_of(a[i], a[(i + 1) % 3], b)) return false;
    if(weakly_right_of(b[i], b[(i + 1) % 3], a)) return false;
  }
  return true;
}

/// Counts the overlapping pairs among the triangles flagged `usable`.
inline std::size_t count_overlaps(std::vector<Uv_triangle> triangles, const std::vector<bool>& usable)
{
  using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 2, std::size_t>;
  std::vector<Box> boxes;
  boxes.reserve(triangles.size());
  for(std::size_t i = 0; i < triangles.size(); ++i) {
    Uv_triangle& t = triangles[i];
    if(!usable[i]) continue;
    // The area test passed, but it is rounded: let the exact predicate decide.
    const CGAL::Orientation o = CGAL::orientation(t[0], t[1], t[2]);
    if(o == CGAL::COLLINEAR) continue;
    if(o == CGAL::CLOCKWISE) std::swap(t[1], t[2]);
    boxes.emplace_back(t[0].bbox() + t[1].bbox() + t[2].bbox(), i);
  }
  std::size_t count = 0;
  // Overlapping interiors imply overlapping open boxes, so every true pair is
  // a candidate; the default CLOSED topology adds touching boxes (neighbours
  // in a grid), which the exact test rejects.
  CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box& a, const Box& b) {
    if(interiors_overlap(triangles[a.info()], triangles[b.info()])) ++count;
  });
  return count;
}

template <class T, class = void>
struct is_less_comparable : std::false_type {};
template <class T>
struct is_less_comparable<T, std::void_t<decltype(std::declval<const T&>() < std::declval<const T&>())>> : std::true_type {};

// Walks the border of the chart whose faces are `faces` (each listed once)
// and tells whether it is one loop mapped onto a simple polygon; `in_chart`
// says whether a face belongs to the chart.
template <class TriangleMesh, class FaceRange, class InChart, class UvMap>
bool border_loop_maps_to_simple_polygon(const TriangleMesh& tm, const FaceRange& faces, std::size_t number_of_faces,
                                        InChart in_chart, UvMap uv)
{
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  using halfedge_descriptor = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;
  // Border halfedges: in a face of the chart, their opposite not.
  std::size_t border_edges = 0;
  halfedge_descriptor start = boost::graph_traits<TriangleMesh>::null_halfedge();
  for(face_descriptor f : faces)
    for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, tm), tm))
      if(!in_chart(face(opposite(h, tm), tm))) {
        if(border_edges++ == 0) start = h;
      }
  if(border_edges < 3) return false;
  std::vector<Uv_point> polygon;
  polygon.reserve(border_edges);
  const std::size_t most_turns = 3 * number_of_faces;
  halfedge_descriptor h = start;
  do {
    polygon.push_back(uv_point(uv, source(h, tm)));
    if(polygon.size() > border_edges) return false;
    // The next border halfedge leaves target(h): turn around it through the chart's faces.
    halfedge_descriptor g = next(h, tm);
    for(std::size_t turns = 0; in_chart(face(opposite(g, tm), tm)); ++turns) {
      if(turns > most_turns) return false;
      g = next(opposite(g, tm), tm);
    }
    h = g;
  } while(h != start);
  if(polygon.size() != border_edges) return false;  // several loops
  return CGAL::is_simple_2(polygon.begin(), polygon.end(), CGAL::Exact_predicates_inexact_constructions_kernel());
}

/// Whether the border of the chart `faces` is a single loop whose (u,v) image
/// is a simple polygon. False where that cannot be told (face descriptors that
/// cannot be sorted, a face listed twice, no border, several loops, a loop
/// through a vertex twice).
template <class TriangleMesh, class FaceRange, class UvMap>
bool border_maps_to_simple_polygon(const TriangleMesh& tm, const FaceRange& faces, UvMap uv)
{
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  const face_descriptor null_face = boost::graph_traits<TriangleMesh>::null_face();
  // A chart that is most of its mesh (a disc mapped whole: 2.2M faces) is
  // told by marks on the faces' indices; binary searches in its sorted faces
  // took a third of the distortion's time there. A small chart of a large
  // mesh keeps the sorted list, whose cost does not grow with the mesh.
  if constexpr(CGAL::graph_has_property<TriangleMesh, boost::face_index_t>::value) {
    const auto index = get(boost::face_index, tm);
    std::size_t count = 0, top = 0;
    for(face_descriptor f : faces) {
      ++count;
      const std::size_t i = static_cast<std::size_t>(get(index, f));
      if(i >= (std::numeric_limits<std::size_t>::max)() / 16) { top = i; break; }  // no such index: the sorted list
      top = (std::max)(top, i + 1);
    }
    if(top <= 8 * count) {
      thread_local Index_marks marked;  // kept from chart to chart, at most 8 x the largest such chart
      marked.reset(top);
      for(face_descriptor f : faces)
        if(!marked.insert(static_cast<std::size_t>(get(index, f)))) return false; // listed twice
      auto in_chart = [&](face_descriptor f) {
        if(f == null_face) return false;
        const std::size_t i = static_cast<std::size_t>(get(index, f));
        return i < top && marked.contains(i);
      };
      return border_loop_maps_to_simple_polygon(tm, faces, count, in_chart, uv);
    }
  }
  if constexpr(!is_less_comparable<face_descriptor>::value) {
    return false;
  } else {
    std::vector<face_descriptor> sorted(std::begin(faces), std::end(faces));
    std::sort(sorted.begin(), sorted.end());
    if(std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) return false;
    auto in_chart = [&](face_descriptor f) {
      return f != null_face && std::binary_search(sorted.begin(), sorted.end(), f);
    };
    return border_loop_maps_to_simple_polygon(tm, sorted, sorted.size(), in_chart, uv);
  }
}

template <class TriangleMesh, class FaceRange, class UvMap>
void check_map_types()
{
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  static_assert(std::is_convertible<vertex_descriptor, typename boost::property_traits<UvMap>::key_type>::value,
                "UvMap must be a property map whose key is the mesh's vertex_descriptor");
  static_assert(std::is_convertible<decltype(*std::begin(std::declval<const FaceRange&>())), face_descriptor>::value,
                "FaceRange must be a range of the mesh's face_descriptor");
}

} // namespace internal

/// Counts the pairs of faces of a chart whose interiors overlap in (u,v).
///
/// Candidate pairs come from `CGAL::box_self_intersection_d` on the faces'
/// 2D bounding boxes (O(F log F) in practice); each candidate is then decided
/// exactly with `CGAL::Exact_predicates_inexact_constructions_kernel`'s
/// orientation predicate. Faces sharing only an edge or a vertex do not
/// overlap; a face folded over its neighbour does. Degenerate (u,v) triangles
/// (area <= 1e-14 times the chart's total, exactly collinear, or not finite)
/// and faces that are not triangles are skipped.
///
/// \tparam TriangleMesh a model of `FaceGraph` (`CGAL::Surface_mesh`, `CGAL::Face_filtered_graph`, ...)
/// \tparam FaceRange a range of `boost::graph_traits<TriangleMesh>::face_descriptor`
/// \tparam UvMap a `ReadablePropertyMap` from vertices to a 2D point with `x()` and `y()`
///         (e.g. `Epick::Point_2`); coordinates are rounded to `double`
/// \param tm the mesh
/// \param faces the faces of the chart
/// \param uv the (u,v) coordinates of the vertices of `faces`
/// \returns the number of unordered pairs of faces whose (u,v) interiors overlap
template <class TriangleMesh, class FaceRange, class UvMap>
std::size_t count_overlapping_pairs(const TriangleMesh& tm, const FaceRange& faces, UvMap uv)
{
  internal::check_map_types<TriangleMesh, FaceRange, UvMap>();
  std::vector<internal::Uv_triangle> triangles;
  std::vector<bool> is_triangle;
  std::vector<double> areas;
  double total = 0;
  for(auto f : faces) {
    const auto fv = internal::face_vertices(f, tm);
    internal::Uv_triangle t;
    for(int k = 0; k < 3; ++k) t[k] = fv.second == 3 ? internal::uv_point(uv, fv.first[k]) : internal::Uv_point(0, 0);
    triangles.push_back(t);
    is_triangle.push_back(fv.second == 3);
    areas.push_back(fv.second == 3 ? internal::signed_area(t) : 0.0);
    if(std::isfinite(areas.back())) total += std::abs(areas.back());
  }
  std::vector<bool> usable(triangles.size());
  for(std::size_t i = 0; i < triangles.size(); ++i)
    usable[i] = is_triangle[i] && !internal::is_degenerate_area(areas[i], total);
  return internal::count_overlaps(std::move(triangles), usable);
}

/// Measures the distortion of one chart: the faces in `faces`, their 3D
/// positions from `vpm`, their (u,v) from `uv`.
///
/// Each triangle is laid in an orthonormal frame of its own plane and the
/// 2x2 Jacobian J of the affine map onto its (u,v) triangle is formed; its
/// singular values give every measure (see `Triangle_distortion`). A flipped
/// triangle (det J of the sign opposite to the chart's majority) is still
/// given the angle and stretch of its singular values, i.e. of the map
/// followed by a reflection: the fold is reported by `flipped` and by
/// `overlapping_pairs`, while `angle` keeps saying how much shapes are bent.
/// The overlaps are counted as by `count_overlapping_pairs()`.
///
/// \tparam TriangleMesh a model of `FaceGraph` (`CGAL::Surface_mesh`, `CGAL::Face_filtered_graph`, ...)
/// \tparam FaceRange a range of `boost::graph_traits<TriangleMesh>::face_descriptor`
/// \tparam VertexPointMap a `ReadablePropertyMap` from vertices to a 3D point with `x()`, `y()`, `z()`
/// \tparam UvMap a `ReadablePropertyMap` from vertices to a 2D point with `x()` and `y()` (e.g. `Epick::Point_2`)
/// \param tm the mesh
/// \param faces the faces of the chart; a face that is not a triangle is reported as degenerate
/// \param vpm the 3D positions of the vertices
/// \param uv the (u,v) coordinates of the vertices
/// \param per_face if not null, receives one entry per face of `faces`, in range order
/// \returns the chart's summary
template <class TriangleMesh, class FaceRange, class VertexPointMap, class UvMap>
Distortion_summary measure_distortion(const TriangleMesh& tm, VertexPointMap vpm, const FaceRange& faces, UvMap uv,
                                      std::vector<Triangle_distortion>* per_face = nullptr)
{
  internal::check_map_types<TriangleMesh, FaceRange, UvMap>();
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  static_assert(std::is_convertible<vertex_descriptor, typename boost::property_traits<VertexPointMap>::key_type>::value,
                "VertexPointMap must be a property map whose key is the mesh's vertex_descriptor");

  // Pass 1: areas, and the Jacobian of each triangle (needs no chart total).
  struct Face_data {
    internal::Uv_triangle uv;
    std::array<double, 4> jacobian{}; // [[a, b], [c, d]] row by row
    bool is_triangle = false;
  };
  std::vector<Face_data> data;
  std::vector<Triangle_distortion> local;
  std::vector<Triangle_distortion>& out = per_face != nullptr ? *per_face : local;
  out.clear();
  // Sized once: grown by doubling, a 2.2M-face chart's 100 MB were copied and
  // their fresh pages zeroed twice.
  if constexpr(std::is_base_of<std::forward_iterator_tag, typename std::iterator_traits<decltype(std::begin(faces))>::iterator_category>::value) {
    const auto count = static_cast<std::size_t>(std::distance(std::begin(faces), std::end(faces)));
    data.reserve(count);
    out.reserve(count);
  }
  double sum_3d = 0, sum_uv = 0, sum_signed_uv = 0;
  for(auto f : faces) {
    Face_data fd;
    Triangle_distortion td;
    const auto fv = internal::face_vertices(f, tm);
    fd.is_triangle = fv.second == 3;
    if(fd.is_triangle) {
      std::array<std::array<double, 3>, 3> p;
      for(int k = 0; k < 3; ++k) {
        const auto& q = get(vpm, fv.first[k]);
        p[k] = {CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z())};
        fd.uv[k] = internal::uv_point(uv, fv.first[k]);
      }
      const std::array<double, 3> d1{p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2]};
      const std::array<double, 3> d2{p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2]};
      const double l1 = std::sqrt(d1[0] * d1[0] + d1[1] * d1[1] + d1[2] * d1[2]);
      const double twice_area = std::sqrt(std::pow(d1[1] * d2[2] - d1[2] * d2[1], 2) +
                                          std::pow(d1[2] * d2[0] - d1[0] * d2[2], 2) +
                                          std::pow(d1[0] * d2[1] - d1[1] * d2[0], 2));
      td.area_3d = twice_area / 2;
      td.signed_area_uv = internal::signed_area(fd.uv);
      if(l1 > 0 && twice_area > 0) {
        // Local frame: p0 at the origin, p1 on the x axis, p2 above it, so the
        // 3D triangle becomes (0,0), (x1,0), (x2,y2) with y2 > 0.
        const double x1 = l1;
        const double x2 = (d1[0] * d2[0] + d1[1] * d2[1] + d1[2] * d2[2]) / l1;
        const double y2 = twice_area / l1;
        const double a1 = fd.uv[1].x() - fd.uv[0].x(), a2 = fd.uv[2].x() - fd.uv[0].x();
        const double b1 = fd.uv[1].y() - fd.uv[0].y(), b2 = fd.uv[2].y() - fd.uv[0].y();
        // J sends (x1,0) to (a1,b1) and (x2,y2) to (a2,b2).
        fd.jacobian = {a1 / x1, (a2 - a1 * x2 / x1) / y2, b1 / x1, (b2 - b1 * x2 / x1) / y2};
      }
      if(std::isfinite(td.area_3d)) sum_3d += td.area_3d;
      if(std::isfinite(td.signed_area_uv)) {
        sum_uv += std::abs(td.signed_area_uv);
        sum_signed_uv += td.signed_area_uv;
      }
    }
    data.push_back(fd);
    out.push_back(td);
  }

  // Pass 2: what needs the chart's totals.
  constexpr double inf = std::numeric_limits<double>::infinity();
  const double majority = sum_signed_uv >= 0 ? 1.0 : -1.0;
  const double scale = sum_3d > 0 ? std::sqrt(sum_uv / sum_3d) : 0.0;
  Distortion_summary s;
  s.faces = out.size();
  double weight = 0, angle_sum = 0, area_sum = 0, l2_sum = 0;
  std::vector<bool> usable(out.size());
  for(std::size_t i = 0; i < out.size(); ++i) {
    Triangle_distortion& td = out[i];
    usable[i] = data[i].is_triangle && !internal::is_degenerate_area(td.signed_area_uv, sum_uv);
    td.degenerate = !usable[i] || internal::is_degenerate_area(td.area_3d, sum_3d);
    const auto sv = internal::singular_values_2x2(data[i].jacobian[0], data[i].jacobian[1],
                                                  data[i].jacobian[2], data[i].jacobian[3]);
    if(td.degenerate || !(sv.second > 0)) {
      td.degenerate = true;
      td.angle = td.area = td.stretch_l2 = td.stretch_linf = inf;
      ++s.degenerate;
      continue;
    }
    td.flipped = td.signed_area_uv * majority < 0;
    if(td.flipped) ++s.flipped;
    td.angle = sv.first / sv.second;
    const double r = (std::abs(td.signed_area_uv) / sum_uv) / (td.area_3d / sum_3d);
    td.area = std::max(r, 1 / r);
    // uv -> 3D has singular values 1/sigma_min >= 1/sigma_max (Sander's Gamma, gamma).
    const double big = 1 / sv.second, small = 1 / sv.first;
    td.stretch_l2 = std::sqrt((big * big + small * small) / 2) * scale;
    td.stretch_linf = big * scale;

    weight += td.area_3d;
    angle_sum += td.angle * td.area_3d;
    area_sum += td.area * td.area_3d;
    l2_sum += td.stretch_l2 * td.stretch_l2 * td.area_3d;
    s.angle_max = std::max(s.angle_max, td.angle);
    s.area_max = std::max(s.area_max, td.area);
    s.stretch_linf = std::max(s.stretch_linf, td.stretch_linf);
  }
  s.measured_area = weight;
  if(weight > 0) {
    s.angle_mean = angle_sum / weight;
    s.area_mean = area_sum / weight;
    s.stretch_l2 = std::sqrt(l2_sum / weight);
  }

  // Overlaps. A chart with no flipped or degenerate face whose border is one
  // loop mapped onto a simple polygon is one-to-one: with every triangle
  // keeping its orientation, the number of faces over a point is the winding
  // number of the border's image around it, one inside and zero outside. So
  // the pairwise test runs only where that cannot be shown (folds, or a border
  // that crosses itself); both give the same count (tested).
  if(s.flipped == 0 && s.degenerate == 0 && internal::border_maps_to_simple_polygon(tm, faces, uv)) return s;
  std::vector<internal::Uv_triangle> triangles;
  triangles.reserve(data.size());
  for(const Face_data& fd : data) triangles.push_back(fd.uv);
  s.overlapping_pairs = internal::count_overlaps(std::move(triangles), usable);
  return s;
}

/// The summary of two sets of charts together (e.g. the patches of a mesh,
/// one at a time): counts add up, maxima are maxima, means and the L2 stretch
/// are weighted by each side's `measured_area`, as within one chart. Each
/// chart keeps its own normalisation (area, stretch) and overlaps are counted
/// within charts only, since every chart has its own square.
inline Distortion_summary combined(const Distortion_summary& a, const Distortion_summary& b)
{
  Distortion_summary s;
  s.faces = a.faces + b.faces;
  s.flipped = a.flipped + b.flipped;
  s.degenerate = a.degenerate + b.degenerate;
  s.overlapping_pairs = a.overlapping_pairs + b.overlapping_pairs;
  s.angle_max = std::max(a.angle_max, b.angle_max);
  s.area_max = std::max(a.area_max, b.area_max);
  s.stretch_linf = std::max(a.stretch_linf, b.stretch_linf);
  s.measured_area = a.measured_area + b.measured_area;
  if(s.measured_area > 0) {
    const double wa = a.measured_area / s.measured_area, wb = b.measured_area / s.measured_area;
    s.angle_mean = wa * a.angle_mean + wb * b.angle_mean;
    s.area_mean = wa * a.area_mean + wb * b.area_mean;
    s.stretch_l2 = std::sqrt(wa * a.stretch_l2 * a.stretch_l2 + wb * b.stretch_l2 * b.stretch_l2);
  }
  return s;
}

} // namespace diffuv

#endif // DIFFUV_METRICS_DISTORTION_H
