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
//
// On that rectangle, `fit_chart_drawing()` then warps each axis
// (`Axis_warp`): u drawn at f(u) and v at g(v), f and g increasing, chosen
// with the aspect to lower the chart's symmetric Dirichlet energy (stretch
// and shrink alike). The diffusion map's iso-lines stay iso-lines and its
// border stays on the rectangle's border, so the chart still fills its
// rectangle and packs as before; only the spacing of the iso-lines changes.
#ifndef DIFFUV_PARAMETERIZATION_CHART_RECTANGLE_H
#define DIFFUV_PARAMETERIZATION_CHART_RECTANGLE_H

#include <diffuv/atlas/Uv_atlas.h>
#include <diffuv/core/four_sides.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_utils.h>
#include <CGAL/squared_distance_3.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <deque>
#include <limits>
#include <numeric>
#include <optional>
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

/// Options of `fit_chart_drawing()`.
struct Chart_drawing_options {
  std::size_t pieces = 6;          ///< linear pieces of each axis's warp (0: no fit at all; 1: the aspect alone)
  std::size_t max_iterations = 30; ///< quasi-Newton steps at most
};

/// How a chart is drawn on its rectangle: the rectangle (larger side 1) and
/// the warps of u and v, with the symmetric Dirichlet energy before and after
/// (area-weighted mean over the chart's triangles of s1^2 + s2^2 + 1/s1^2 +
/// 1/s2^2, s1 and s2 the singular values of the map from the surface to the
/// rectangle scaled to the chart's 3D area; 4 for an isometry).
struct Chart_drawing {
  std::array<double, 2> size{{1., 1.}};
  Axis_warp u, v;
  double energy_before = std::numeric_limits<double>::infinity();
  double energy_after = std::numeric_limits<double>::infinity();
};

namespace internal {

// The energy of fit_chart_drawing() and its gradient, for one chart.
class Chart_drawing_energy {
public:
  // 3D triangles in their own plane (P = [[p00, p01], [0, p11]]), the
  // chart's (u,v) per local vertex and the triangles' local vertices.
  struct Triangle {
    std::array<std::size_t, 3> v;
    double p00, p01, p11, weight, beta;  // weight: 3D area / chart's; beta: mu^2 / det(P)^2
  };

  Chart_drawing_energy(std::vector<Triangle> triangles, const std::vector<std::array<double, 2>>& uv, std::size_t pieces,
                       double alpha)
    : triangles_(std::move(triangles)), pieces_(pieces), alpha_(alpha), piece_(uv.size()), offset_(uv.size())
  {
    const double k = static_cast<double>(pieces_);
    for(std::size_t i = 0; i < uv.size(); ++i)
      for(int a = 0; a < 2; ++a) {
        const double x = std::isfinite(uv[i][a]) ? std::clamp(uv[i][a], 0., 1.) * k : 0.;  // NaN: a vertex in no triangle
        piece_[i][a] = std::min(static_cast<std::size_t>(x), pieces_ - 1);
        offset_[i][a] = x - static_cast<double>(piece_[i][a]);
      }
  }

  std::size_t variables() const { return 2 * pieces_ + 1; }

  // Knots (pieces + 1 values from 0 to 1) from the log widths z[first, first + pieces).
  std::vector<double> knots(const std::vector<double>& z, std::size_t first) const
  {
    std::vector<double> w(z.begin() + first, z.begin() + first + pieces_);
    const double top = *std::max_element(w.begin(), w.end());
    double sum = 0;
    for(double& x : w) sum += (x = std::exp(x - top));
    std::vector<double> out(pieces_ + 1, 0.);
    for(std::size_t j = 0; j < pieces_; ++j) out[j + 1] = out[j] + w[j] / sum;
    out[pieces_] = 1.;
    return out;
  }

  // The energy at z (log widths of u's pieces, of v's, log aspect), and its
  // gradient into `gradient`; +infinity where a triangle turns over.
  double operator()(const std::vector<double>& z, std::vector<double>& gradient) const
  {
    const std::size_t n = piece_.size();
    const std::array<std::vector<double>, 2> knot = {knots(z, 0), knots(z, pieces_)};
    const std::array<double, 2> scale = {std::exp(z[2 * pieces_] / 2), std::exp(-z[2 * pieces_] / 2)};
    std::vector<std::array<double, 2>> drawn(n), pull(n, {0., 0.});
    for(std::size_t i = 0; i < n; ++i)
      for(int a = 0; a < 2; ++a) {
        const std::size_t j = piece_[i][a];
        drawn[i][a] = scale[a] * (knot[a][j] + offset_[i][a] * (knot[a][j + 1] - knot[a][j]));
      }
    double energy = 0;
    for(const Triangle& t : triangles_) {
      const auto& a = drawn[t.v[0]];
      const auto& b = drawn[t.v[1]];
      const auto& c = drawn[t.v[2]];
      const double d00 = b[0] - a[0], d01 = c[0] - a[0], d10 = b[1] - a[1], d11 = c[1] - a[1];
      const double det = d00 * d11 - d01 * d10;
      if(!(det > 0)) return std::numeric_limits<double>::infinity();
      // D^-1 and J = P D^-1 (the map from the drawing to the surface).
      const double i00 = d11 / det, i01 = -d01 / det, i10 = -d10 / det, i11 = d00 / det;
      const double j00 = t.p00 * i00 + t.p01 * i10, j01 = t.p00 * i01 + t.p01 * i11;
      const double j10 = t.p11 * i10, j11 = t.p11 * i11;
      const double tr = j00 * j00 + j01 * j01 + j10 * j10 + j11 * j11;
      const double det2 = det * det;
      energy += t.weight * tr * (alpha_ + t.beta * det2);
      // d tr / dD = -2 J^T J D^-T, d det^2 / dD = 2 det^2 D^-T.
      const double m00 = j00 * j00 + j10 * j10, m01 = j00 * j01 + j10 * j11, m11 = j01 * j01 + j11 * j11;
      const double g = -2 * t.weight * (alpha_ + t.beta * det2), h = 2 * t.weight * tr * t.beta * det2;
      // (J^T J D^-T)_{rc} = sum_k M_{rk} Dinv_{ck}
      const double g00 = g * (m00 * i00 + m01 * i01) + h * i00, g01 = g * (m00 * i10 + m01 * i11) + h * i10;
      const double g10 = g * (m01 * i00 + m11 * i01) + h * i01, g11 = g * (m01 * i10 + m11 * i11) + h * i11;
      pull[t.v[1]][0] += g00;
      pull[t.v[2]][0] += g01;
      pull[t.v[1]][1] += g10;
      pull[t.v[2]][1] += g11;
      pull[t.v[0]][0] -= g00 + g01;
      pull[t.v[0]][1] -= g10 + g11;
    }
    // Back through the drawing to the knots, the widths and the aspect.
    gradient.assign(variables(), 0.);
    std::array<double, 2> by_scale = {0., 0.};
    for(int a = 0; a < 2; ++a) {
      std::vector<double> by_knot(pieces_ + 1, 0.);
      for(std::size_t i = 0; i < n; ++i) {
        const std::size_t j = piece_[i][a];
        by_knot[j] += pull[i][a] * scale[a] * (1 - offset_[i][a]);
        by_knot[j + 1] += pull[i][a] * scale[a] * offset_[i][a];
        by_scale[a] += pull[i][a] * drawn[i][a] / scale[a];
      }
      // knot j = sum of widths before j (the last knot is 1 whatever the widths).
      std::vector<double> by_width(pieces_, 0.);
      double running = 0;
      for(std::size_t j = pieces_; j-- > 0;) {
        if(j + 1 < pieces_) running += by_knot[j + 1];
        by_width[j] = running;
      }
      double mean = 0;
      for(std::size_t j = 0; j < pieces_; ++j) mean += (knot[a][j + 1] - knot[a][j]) * by_width[j];
      for(std::size_t j = 0; j < pieces_; ++j)
        gradient[a * pieces_ + j] = (knot[a][j + 1] - knot[a][j]) * (by_width[j] - mean);
    }
    gradient[2 * pieces_] = 0.5 * (scale[0] * by_scale[0] - scale[1] * by_scale[1]);
    return energy;
  }

private:
  std::vector<Triangle> triangles_;
  std::size_t pieces_;
  double alpha_;
  std::vector<std::array<std::size_t, 2>> piece_;
  std::vector<std::array<double, 2>> offset_;
};

// Limited-memory BFGS with a backtracking line search, from z; returns the
// least energy found and leaves its point in z.
template <class Energy>
double minimize_chart_energy(const Energy& energy, std::vector<double>& z, std::size_t max_iterations)
{
  const std::size_t n = z.size(), memory = 6;
  std::vector<double> g(n), trial_g(n), trial(n);
  double e = energy(z, g);
  if(!std::isfinite(e)) return e;
  std::deque<std::vector<double>> ss, ys;
  std::deque<double> rhos;
  auto dot = [](const std::vector<double>& a, const std::vector<double>& b) {
    return std::inner_product(a.begin(), a.end(), b.begin(), 0.);
  };
  for(std::size_t it = 0; it < max_iterations; ++it) {
    // Two-loop recursion: d = -H g.
    std::vector<double> d = g;
    std::vector<double> alphas(ss.size());
    for(std::size_t k = ss.size(); k-- > 0;) {
      alphas[k] = rhos[k] * dot(ss[k], d);
      for(std::size_t i = 0; i < n; ++i) d[i] -= alphas[k] * ys[k][i];
    }
    const double gamma = ss.empty() ? 1. / std::max(1., std::sqrt(dot(g, g))) : dot(ss.back(), ys.back()) / dot(ys.back(), ys.back());
    for(double& x : d) x *= gamma;
    for(std::size_t k = 0; k < ss.size(); ++k) {
      const double beta = rhos[k] * dot(ys[k], d);
      for(std::size_t i = 0; i < n; ++i) d[i] += ss[k][i] * (alphas[k] - beta);
    }
    for(double& x : d) x = -x;
    double slope = dot(g, d);
    if(!(slope < 0)) { // not a descent direction: steepest descent
      for(std::size_t i = 0; i < n; ++i) d[i] = -g[i] * gamma;
      slope = dot(g, d);
      if(!(slope < 0)) break;
    }
    double step = 1, trial_e = std::numeric_limits<double>::infinity();
    bool found = false;
    for(int halvings = 0; halvings < 40; ++halvings, step /= 2) {
      for(std::size_t i = 0; i < n; ++i) trial[i] = z[i] + step * d[i];
      trial_e = energy(trial, trial_g);
      if(std::isfinite(trial_e) && trial_e <= e + 1e-4 * step * slope) { found = true; break; }
    }
    if(!found) break;
    std::vector<double> s(n), y(n);
    for(std::size_t i = 0; i < n; ++i) { s[i] = trial[i] - z[i]; y[i] = trial_g[i] - g[i]; }
    const double sy = dot(s, y);
    const double drop = e - trial_e;
    z = trial;
    g = trial_g;
    e = trial_e;
    if(sy > 1e-300) {
      ss.push_back(std::move(s));
      ys.push_back(std::move(y));
      rhos.push_back(1 / sy);
      if(ss.size() > memory) { ss.pop_front(); ys.pop_front(); rhos.pop_front(); }
    }
    if(drop <= 1e-6 * e) break;
  }
  return e;
}

} // namespace internal

namespace internal {

// The energy of fit_chart_drawing() for chart c, or nothing if the chart has
// no area, or a triangle flat or turned over in (u,v).
template <class TriangleMesh, class Kernel, class VertexPointMap>
std::optional<Chart_drawing_energy> chart_drawing_energy(const Uv_atlas<TriangleMesh, Kernel>& atlas, std::size_t c,
                                                         VertexPointMap vpm, std::size_t pieces)
{
  const auto& chart = atlas.chart(c);
  if(pieces == 0 || chart.triangles.empty()) return std::nullopt;
  std::vector<std::array<double, 2>> uv(chart.uv.size());
  for(std::size_t i = 0; i < uv.size(); ++i) uv[i] = {CGAL::to_double(chart.uv[i].x()), CGAL::to_double(chart.uv[i].y())};
  using Triangle = Chart_drawing_energy::Triangle;
  std::vector<Triangle> triangles;
  triangles.reserve(chart.triangles.size());
  double area_3d = 0, area_uv = 0;
  for(const auto& t : chart.triangles) {
    const auto pa = get(vpm, chart.vertices[t[0]]), pb = get(vpm, chart.vertices[t[1]]), pc = get(vpm, chart.vertices[t[2]]);
    const std::array<double, 3> e1 = {CGAL::to_double(pb.x() - pa.x()), CGAL::to_double(pb.y() - pa.y()), CGAL::to_double(pb.z() - pa.z())};
    const std::array<double, 3> e2 = {CGAL::to_double(pc.x() - pa.x()), CGAL::to_double(pc.y() - pa.y()), CGAL::to_double(pc.z() - pa.z())};
    const double l1 = std::sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
    const std::array<double, 3> n = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
    const double twice_area = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    // The 3D triangle in its own plane: a at the origin, b on the x axis.
    Triangle tri;
    tri.v = {t[0], t[1], t[2]};
    tri.p00 = l1;
    tri.p01 = l1 > 0 ? (e1[0] * e2[0] + e1[1] * e2[1] + e1[2] * e2[2]) / l1 : 0.;
    tri.p11 = l1 > 0 ? twice_area / l1 : 0.;
    tri.weight = twice_area / 2;
    area_3d += tri.weight;
    const auto& a = uv[t[0]];
    const auto& b = uv[t[1]];
    const auto& q = uv[t[2]];
    const double twice_uv = (b[0] - a[0]) * (q[1] - a[1]) - (q[0] - a[0]) * (b[1] - a[1]);
    if(!(twice_uv > 0)) return std::nullopt;
    area_uv += twice_uv / 2;
    triangles.push_back(tri);
  }
  if(!(area_3d > 0) || !(area_uv > 0) || !std::isfinite(area_3d) || !std::isfinite(area_uv)) return std::nullopt;
  // Drawn on a rectangle of area 1 scaled to the chart's 3D area:
  // mu^2 = area_3d / area_uv, the same for every warp and aspect (they keep
  // the area of the rectangle, which the chart fills).
  const double mu2 = area_3d / area_uv;
  for(Triangle& t : triangles) {
    // Triangles with no 3D area weigh nothing, but still may not turn over.
    const double det_p = t.p00 * t.p11;
    t.beta = det_p > 1e-14 * area_3d ? mu2 / (det_p * det_p) : 0.;
    t.weight = t.beta > 0 ? t.weight / area_3d : 0.;
  }
  return Chart_drawing_energy(std::move(triangles), uv, pieces, 1 / mu2);
}

} // namespace internal

/// Chooses how chart `c` of `atlas` is drawn: its rectangle's aspect and a
/// monotone warp of each axis (`Axis_warp`), which together lower the
/// chart's symmetric Dirichlet energy, starting from the rectangle `size`
/// (e.g. `stretch_optimal_rectangle()`'s). Every triangle stays turned the
/// way it was (the energy is infinite where one turns over), and the border
/// stays on the rectangle's border, so a one-to-one chart stays one-to-one.
///
/// The chart is left as it is (the result holds `size` and no warps) if any
/// of its triangles is flat or turned over in (u,v), or if the fit lowers
/// nothing.
///
/// \tparam VertexPointMap a readable property map from the atlas mesh's vertices to 3D points
template <class TriangleMesh, class Kernel, class VertexPointMap>
Chart_drawing fit_chart_drawing(const Uv_atlas<TriangleMesh, Kernel>& atlas, std::size_t c, VertexPointMap vpm,
                                std::array<double, 2> size, const Chart_drawing_options& options = Chart_drawing_options())
{
  Chart_drawing result;
  result.size = size;
  if(!(size[0] > 0 && size[1] > 0)) return result;
  const auto energy = internal::chart_drawing_energy(atlas, c, vpm, options.pieces);
  if(!energy) return result;
  std::vector<double> z(energy->variables(), 0.), gradient;
  z.back() = std::log(size[0] / size[1]);
  result.energy_before = result.energy_after = (*energy)(z, gradient);
  if(!std::isfinite(result.energy_before)) return result;
  const double after = internal::minimize_chart_energy(*energy, z, options.max_iterations);
  if(!(after < result.energy_before)) return result;
  result.energy_after = after;
  result.u.knots = energy->knots(z, 0);
  result.v.knots = energy->knots(z, options.pieces);
  const double width = std::exp(z.back() / 2), height = std::exp(-z.back() / 2), larger = std::max(width, height);
  result.size = {width / larger, height / larger};
  return result;
}

/// Puts chart c on its rectangle: `size` (e.g. from
/// `stretch_optimal_rectangle()`) as it is with `options.pieces` 0, else the
/// aspect and warps `fit_chart_drawing()` finds from it. What the default
/// pipeline does to every chart it maps.
template <class TriangleMesh, class Kernel, class VertexPointMap>
void draw_chart(Uv_atlas<TriangleMesh, Kernel>& atlas, std::size_t c, VertexPointMap vpm, std::array<double, 2> size,
                const Chart_drawing_options& options = Chart_drawing_options())
{
  if(options.pieces == 0) {
    atlas.set_chart_size(c, size[0], size[1]);
    return;
  }
  Chart_drawing drawing = fit_chart_drawing(atlas, c, vpm, size, options);
  atlas.set_chart_size(c, drawing.size[0], drawing.size[1]);
  atlas.set_chart_warp(c, std::move(drawing.u), std::move(drawing.v));
}

} // namespace diffuv

#endif // DIFFUV_PARAMETERIZATION_CHART_RECTANGLE_H
