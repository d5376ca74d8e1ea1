// diffuv: a triangle in the (u,v) plane: its signed area, when it counts as
// degenerate, and the singular values of a map's 2x2 Jacobian. The distortion
// measures (metrics/) and the fold repair (parameterization/) share them, so
// that both judge a triangle alike.
#ifndef DIFFUV_INTERNAL_UV_TRIANGLE_H
#define DIFFUV_INTERNAL_UV_TRIANGLE_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <array>
#include <cmath>
#include <utility>

namespace diffuv {
namespace internal {

/// A triangle's area counts as zero below this fraction of the chart's total:
/// well above the rounding noise of a cross product, well below any real face.
constexpr double degenerate_area_fraction = 1e-14;

using Uv_point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_2;
using Uv_triangle = std::array<Uv_point, 3>;

inline double signed_area(const Uv_triangle& t)
{
  return 0.5 * ((t[1].x() - t[0].x()) * (t[2].y() - t[0].y()) - (t[2].x() - t[0].x()) * (t[1].y() - t[0].y()));
}

/// Whether a triangle with (possibly non-finite) area `a` is too thin to measure;
/// written as a negation so that NaN counts as degenerate.
inline bool is_degenerate_area(double a, double total)
{
  return !(std::isfinite(a) && std::abs(a) > degenerate_area_fraction * total);
}

/// Singular values {max, min} of [[a, b], [c, d]] in closed form.
///
/// The matrix is a similarity [[e, -h], [h, e]] plus an anti-similarity
/// [[f, g], [g, -f]]; its singular values are |(e,h)| + |(f,g)| and the
/// difference of the two. The smaller one is taken as |det| / sigma_max,
/// which does not cancel for nearly singular matrices.
inline std::pair<double, double> singular_values_2x2(double a, double b, double c, double d)
{
  const double e = (a + d) / 2, f = (a - d) / 2, g = (c + b) / 2, h = (c - b) / 2;
  const double s_max = std::hypot(e, h) + std::hypot(f, g);
  const double s_min = s_max > 0 ? std::abs(a * d - b * c) / s_max : 0.0;
  return {s_max, s_min};
}

} // namespace internal
} // namespace diffuv

#endif // DIFFUV_INTERNAL_UV_TRIANGLE_H
