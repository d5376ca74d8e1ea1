// diffuv: how an atlas uses its texture, whoever made it: the share of the
// texels that some chart covers, texels claimed by two charts, and how even
// the texel density is over the charts (issue #22's measures, taken the same
// way on diffuv's packed OBJ and on Blender's Smart UV Project).
#ifndef DIFFUV_METRICS_TEXTURE_USE_H
#define DIFFUV_METRICS_TEXTURE_USE_H

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

namespace diffuv {

/// One textured triangle: its texture coordinates (in [0,1]^2 for the
/// texture's square; v up), its 3D area and its chart.
struct Uv_triangle_in_chart {
  std::array<std::array<double, 2>, 3> uv;
  double area_3d = 0.;
  std::size_t chart = 0;
};

/// What `measure_texture_use()` found.
struct Texture_use {
  int resolution = 0;
  double covered = 0.;  ///< texels whose centre lies in some triangle, over all texels
  double shared = 0.;   ///< texels whose centre lies in triangles of two charts or more, over all texels
  /// The median over the 3D area of the charts' texel densities (texels per
  /// unit of length: sqrt of a chart's texels over its 3D area).
  double density_median = 0.;
  double within_10_percent = 0.;  ///< share of the 3D area in charts whose density is within 10 % of the median
  double lowest = 0., highest = 0.;  ///< the charts' smallest and largest density over the median (charts of positive area)
};

/// Rasterises `triangles` at `resolution` x `resolution` texels (a texel
/// counts where its centre lies inside or on a triangle; parts outside the
/// unit square are ignored) and measures the charts' texel densities from
/// their uv and 3D areas.
/// \throws std::invalid_argument if `resolution` is not in [1, 65536]
inline Texture_use measure_texture_use(const std::vector<Uv_triangle_in_chart>& triangles, int resolution)
{
  if(resolution < 1 || resolution > 65536)
    throw std::invalid_argument("measure_texture_use: the resolution must be in [1, 65536]");
  Texture_use use;
  use.resolution = resolution;
  const std::size_t R = static_cast<std::size_t>(resolution);
  constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max(), several = none - 1;
  std::vector<std::uint32_t> owner(R * R, none);
  std::size_t charts = 0;
  for(const auto& t : triangles) charts = (std::max)(charts, t.chart + 1);
  std::vector<double> uv_area(charts, 0.), area_3d(charts, 0.);
  for(const auto& t : triangles) {
    const auto& a = t.uv[0];
    const auto& b = t.uv[1];
    const auto& c = t.uv[2];
    const double twice = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    if(!std::isfinite(twice)) continue;
    uv_area[t.chart] += std::abs(twice) / 2;
    area_3d[t.chart] += t.area_3d;
    if(twice == 0.) continue;
    const double sign = twice > 0 ? 1. : -1.;
    // Texel (i, j) has its centre at ((i + 0.5) / R, (j + 0.5) / R).
    const double r = static_cast<double>(R);
    const double x0 = (std::min)({a[0], b[0], c[0]}) * r - 0.5, x1 = (std::max)({a[0], b[0], c[0]}) * r - 0.5;
    const double y0 = (std::min)({a[1], b[1], c[1]}) * r - 0.5, y1 = (std::max)({a[1], b[1], c[1]}) * r - 0.5;
    const long i0 = (std::max)(0L, static_cast<long>(std::ceil(x0))), i1 = (std::min)(static_cast<long>(R) - 1, static_cast<long>(std::floor(x1)));
    const long j0 = (std::max)(0L, static_cast<long>(std::ceil(y0))), j1 = (std::min)(static_cast<long>(R) - 1, static_cast<long>(std::floor(y1)));
    auto edge = [&](const std::array<double, 2>& p, const std::array<double, 2>& q, double x, double y) {
      return sign * ((q[0] - p[0]) * (y - p[1]) - (q[1] - p[1]) * (x - p[0]));
    };
    for(long j = j0; j <= j1; ++j)
      for(long i = i0; i <= i1; ++i) {
        const double x = (static_cast<double>(i) + 0.5) / r, y = (static_cast<double>(j) + 0.5) / r;
        if(edge(a, b, x, y) < 0 || edge(b, c, x, y) < 0 || edge(c, a, x, y) < 0) continue;
        std::uint32_t& o = owner[static_cast<std::size_t>(j) * R + static_cast<std::size_t>(i)];
        const auto chart = static_cast<std::uint32_t>((std::min)(t.chart, static_cast<std::size_t>(several - 1)));
        if(o == none) o = chart;
        else if(o != chart) o = several;
      }
  }
  std::size_t covered = 0, shared = 0;
  for(std::uint32_t o : owner) {
    covered += o != none;
    shared += o == several;
  }
  use.covered = static_cast<double>(covered) / static_cast<double>(R * R);
  use.shared = static_cast<double>(shared) / static_cast<double>(R * R);

  // Densities, and their median over the 3D area.
  std::vector<std::pair<double, double>> density;  // (texels per unit of length, 3D area)
  double total = 0.;
  for(std::size_t c = 0; c < charts; ++c)
    if(uv_area[c] > 0 && area_3d[c] > 0) {
      density.emplace_back(std::sqrt(uv_area[c] / area_3d[c]) * static_cast<double>(R), area_3d[c]);
      total += area_3d[c];
    }
  if(density.empty()) return use;
  std::sort(density.begin(), density.end());
  double below = 0.;
  for(const auto& [d, area] : density) {
    below += area;
    if(below >= total / 2) {
      use.density_median = d;
      break;
    }
  }
  double within = 0.;
  for(const auto& [d, area] : density)
    if(std::abs(d - use.density_median) <= 0.1 * use.density_median) within += area;
  use.within_10_percent = within / total;
  use.lowest = density.front().first / use.density_median;
  use.highest = density.back().first / use.density_median;
  return use;
}

} // namespace diffuv

#endif // DIFFUV_METRICS_TEXTURE_USE_H
