// diffuv: a monotone warp of one axis of a chart's rectangle.
//
// The diffusion map spaces its iso-lines by ratios of distances, so a chart
// drawn on its rectangle is squeezed where the patch narrows and stretched
// where it widens. Drawing u at f(u) and v at g(v), with f and g increasing
// and fixing 0 and 1, keeps every iso-line of the map an iso-line of the
// drawing and the chart's border on the rectangle's border, and gives each
// band of u and of v the share of the rectangle the surface asks for
// (`fit_chart_drawing()` in parameterization/chart_rectangle.h chooses them).
#ifndef DIFFUV_ATLAS_AXIS_WARP_H
#define DIFFUV_ATLAS_AXIS_WARP_H

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace diffuv {

/// An increasing piecewise-linear map of [0,1] onto itself: `knots[j]` is
/// the image of j / (knots.size() - 1), with `knots.front()` 0 and
/// `knots.back()` 1. No knots: the identity.
struct Axis_warp {
  std::vector<double> knots;

  bool is_identity() const { return knots.empty(); }

  /// The image of `t` (values outside [0,1] are clamped to it when the warp
  /// is not the identity; NaN, a corner in no chart, stays NaN).
  double operator()(double t) const
  {
    if(knots.size() < 2 || std::isnan(t)) return t;
    const std::size_t pieces = knots.size() - 1;
    const double x = std::clamp(t, 0., 1.) * static_cast<double>(pieces);
    const std::size_t j = std::min(static_cast<std::size_t>(x), pieces - 1);
    const double s = x - static_cast<double>(j);
    return knots[j] + s * (knots[j + 1] - knots[j]);
  }
};

} // namespace diffuv

#endif // DIFFUV_ATLAS_AXIS_WARP_H
