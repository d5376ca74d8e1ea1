// diffuv: the rectangle a chart is written on.
//
// The diffusion map sends a patch onto the unit square; a texture drawn on
// the unit square is stretched across a long patch. Written on a rectangle
// (width, height) instead, (u, v) -> (u * width, v * height), the chart keeps
// the patch's proportions. Of all rectangles, the one whose aspect is
// sqrt(P / Q), with P and Q the area-weighted means of |dx/du|^2 and
// |dx/dv|^2 over the chart's triangles, has the least L2 stretch (Sander et
// al. 2001): the L2 stretch on a rectangle of aspect a = width / height is
// proportional to P / a + Q * a.
#ifndef DIFFUV_PARAMETERIZATION_CHART_RECTANGLE_H
#define DIFFUV_PARAMETERIZATION_CHART_RECTANGLE_H

#include <diffuv/core/four_sides.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_utils.h>
#include <CGAL/squared_distance_3.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace diffuv {

/// The rectangle, its larger side 1, on which the chart given by `uv` (a map
/// of the faces `faces` onto the unit square) has the least L2 stretch.
///
/// Triangles whose (u,v) area is at most 1e-14 of the chart's are left out
/// (as `measure_distortion()` leaves degenerate triangles out).
///
/// \tparam FaceRange a range of face descriptors of `tm`, triangles
/// \tparam UvMap a readable property map from vertex descriptor to a 2D point with `x()` and `y()`
/// \returns {width, height}, or `fallback` if the chart has no measurable triangle
template <class TriangleMesh, class FaceRange, class VertexPointMap, class UvMap>
std::array<double, 2> stretch_optimal_rectangle(const TriangleMesh& tm, VertexPointMap vpm, const FaceRange& faces, UvMap uv,
                                                std::array<double, 2> fallback = {1., 1.})
{
  struct Triangle {
    std::array<double, 3> dp1, dp2;  // 3D edges from the first vertex
    double du1, dv1, du2, dv2, area_3d;
  };
  std::vector<Triangle> triangles;
  double total_uv = 0;
  for(auto f : faces) {
    const auto h = halfedge(f, tm);
    const auto a = source(h, tm), b = target(h, tm), c = target(next(h, tm), tm);
    const auto pa = get(vpm, a), pb = get(vpm, b), pc = get(vpm, c);
    const auto qa = get(uv, a), qb = get(uv, b), qc = get(uv, c);
    Triangle t;
    t.dp1 = {CGAL::to_double(pb.x() - pa.x()), CGAL::to_double(pb.y() - pa.y()), CGAL::to_double(pb.z() - pa.z())};
    t.dp2 = {CGAL::to_double(pc.x() - pa.x()), CGAL::to_double(pc.y() - pa.y()), CGAL::to_double(pc.z() - pa.z())};
    t.du1 = CGAL::to_double(qb.x() - qa.x());
    t.dv1 = CGAL::to_double(qb.y() - qa.y());
    t.du2 = CGAL::to_double(qc.x() - qa.x());
    t.dv2 = CGAL::to_double(qc.y() - qa.y());
    const std::array<double, 3> n = {t.dp1[1] * t.dp2[2] - t.dp1[2] * t.dp2[1], t.dp1[2] * t.dp2[0] - t.dp1[0] * t.dp2[2],
                                     t.dp1[0] * t.dp2[1] - t.dp1[1] * t.dp2[0]};
    t.area_3d = 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    total_uv += 0.5 * std::abs(t.du1 * t.dv2 - t.du2 * t.dv1);
    triangles.push_back(t);
  }
  double p = 0, q = 0;
  for(const Triangle& t : triangles) {
    const double det = t.du1 * t.dv2 - t.du2 * t.dv1;
    if(!(0.5 * std::abs(det) > 1e-14 * total_uv)) continue;
    // The inverse Jacobian's columns dx/du and dx/dv, from [dp1 dp2] = [dx/du dx/dv] [du1 du2; dv1 dv2].
    double along_u = 0, along_v = 0;
    for(int k = 0; k < 3; ++k) {
      const double xu = (t.dp1[k] * t.dv2 - t.dp2[k] * t.dv1) / det;
      const double xv = (t.dp2[k] * t.du1 - t.dp1[k] * t.du2) / det;
      along_u += xu * xu;
      along_v += xv * xv;
    }
    p += t.area_3d * along_u;
    q += t.area_3d * along_v;
  }
  if(!(p > 0 && q > 0 && std::isfinite(p) && std::isfinite(q))) return fallback;
  const double aspect = std::sqrt(p / q);  // width / height
  return aspect >= 1 ? std::array<double, 2>{1., 1. / aspect} : std::array<double, 2>{aspect, 1.};
}

/// A chart's rectangle by its sides: the mean 3D length of its sides v1
/// and v2 (along u) and of u1 and u2 (along v), scaled so that the larger is 1.
/// A texture drawn on the rectangle (width, height) is then not stretched
/// across the patch, where the unit square would stretch a long patch.
///
/// \returns {1, 1} if a pair of sides has no length
template <class VertexDescriptor, class VertexPointMap>
std::array<double, 2> side_length_rectangle(const Four_sides<VertexDescriptor>& sides, VertexPointMap vpm)
{
  auto length = [&](const std::vector<VertexDescriptor>& side) {
    double sum = 0;
    for(std::size_t i = 0; i + 1 < side.size(); ++i)
      sum += std::sqrt(CGAL::to_double(CGAL::squared_distance(get(vpm, side[i]), get(vpm, side[i + 1]))));
    return sum;
  };
  const double width = (length(sides.v1) + length(sides.v2)) / 2, height = (length(sides.u1) + length(sides.u2)) / 2;
  if(!(width > 0 && height > 0 && std::isfinite(width) && std::isfinite(height))) return {1., 1.};
  const double larger = std::max(width, height);
  return {width / larger, height / larger};
}

} // namespace diffuv

#endif // DIFFUV_PARAMETERIZATION_CHART_RECTANGLE_H
