// diffuv: the charts of an atlas packed into one square texture (in the
// optional diffuv::render target, as it packs with stb).
//
// Each chart of a `Uv_atlas` maps its patch onto the unit square, drawn on a
// rectangle of the patch's own aspect (`Chart::size`). Packing gives every
// chart a place of its own in one texture, so that a user can paint or bake
// one image for the whole mesh:
//
//   rectangle of the patch's aspect, scaled so that its area is the patch's
//     3D area (one texel density on every chart)
//   -> turned by 90 degrees so that all lie wide, or all stand tall, or
//      none turned: whichever packs densest (stb's skyline fills its rows
//      differently with each)
//   -> a gutter of texels around it (bilinear filtering and mipmaps must not
//      mix two charts' texels)
//   -> the largest density at which every chart fits, by bisection over
//      stb_rect_pack's skyline packer (Debian's libstb-dev).
//
// A chart drawn at density s covers (s w) x (s h) texels of its slot, the
// slot being that rounded up plus the gutters: the chart is not stretched to
// the rounded size, so the density stays exactly s everywhere.
#ifndef DIFFUV_RENDER_PACK_CHARTS_H
#define DIFFUV_RENDER_PACK_CHARTS_H

#include <diffuv/atlas/Uv_atlas.h>

#include <CGAL/Polygon_mesh_processing/measure.h>

#ifndef DIFFUV_STB_RECT_PACK_INCLUDED
#define DIFFUV_STB_RECT_PACK_INCLUDED
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#define STBRP_STATIC
#define STB_RECT_PACK_IMPLEMENTATION
#include <stb/stb_rect_pack.h>
// stb's implementation section has no guard of its own: a later plain include
// (by the user) must not compile it a second time.
#undef STB_RECT_PACK_IMPLEMENTATION
#undef STBRP_STATIC
#pragma GCC diagnostic pop
#endif

#include <boost/property_map/function_property_map.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <cstddef>
#include <stdexcept>
#include <vector>

namespace diffuv {

/// Options of `pack_charts()`.
struct Chart_packing_options {
  int resolution = 1024; ///< the texture's width and height in texels
  int gutter = 2;        ///< texels kept free on each side of a chart
  /// Try the charts turned by 90 degrees to lie all wide and all tall as
  /// well as unturned, and keep whichever packs densest.
  bool rotate = true;
};

/// One chart's place in the texture. Texels are counted from the lower left
/// corner (texture coordinates (0,0)), as OBJ and OpenGL count them.
struct Packed_chart {
  int x = 0, y = 0;          ///< lower left texel of the chart's slot (gutters included)
  int width = 0, height = 0; ///< the slot, in texels, gutters included (0 for a chart of no area)
  bool rotated = false;      ///< drawn turned by 90 degrees counter-clockwise
  double extent_u = 0.;      ///< texels the chart spans along u (before turning)
  double extent_v = 0.;      ///< texels the chart spans along v
};

/// Where `pack_charts()` put the charts.
struct Chart_packing {
  int resolution = 0;
  int gutter = 0;
  double texels_per_unit = 0.;      ///< texels per unit of length on the surface, the same on every chart
  std::vector<Packed_chart> charts; ///< one per chart of the atlas, in its order
  /// Texels inside the charts' rectangles over all texels: the share of
  /// the texture the charts cover, as a map onto its whole rectangle (the
  /// diffusion map's) covers it.
  double coverage = 0.;

  /// The texture coordinates, in [0,1]^2, of the point (u,v) of chart `c`.
  template <class Point_2>
  Point_2 texture_point(std::size_t c, const Point_2& uv) const
  {
    const Packed_chart& p = charts.at(c);
    const double u = CGAL::to_double(uv.x()), v = CGAL::to_double(uv.y());
    const double r = resolution;
    if(p.rotated)
      return Point_2((p.x + gutter + (1. - v) * p.extent_v) / r, (p.y + gutter + u * p.extent_u) / r);
    return Point_2((p.x + gutter + u * p.extent_u) / r, (p.y + gutter + v * p.extent_v) / r);
  }
};

namespace internal {

/// Packs rectangles of `sizes` (width, height in texels, gutters included)
/// into a square of `resolution`; false if one does not fit.
inline bool pack_rectangles(int resolution, const std::vector<std::array<int, 2>>& sizes,
                            std::vector<std::array<int, 2>>& at)
{
  std::vector<stbrp_rect> rects(sizes.size());
  for(std::size_t k = 0; k < sizes.size(); ++k) {
    rects[k] = stbrp_rect();
    rects[k].id = static_cast<int>(k);
    rects[k].w = sizes[k][0];
    rects[k].h = sizes[k][1];
  }
  std::vector<stbrp_node> nodes(static_cast<std::size_t>(resolution));
  stbrp_context context;
  stbrp_init_target(&context, resolution, resolution, nodes.data(), resolution);
  if(!stbrp_pack_rects(&context, rects.data(), static_cast<int>(rects.size()))) return false;
  at.assign(sizes.size(), {0, 0});
  for(const stbrp_rect& r : rects) at[static_cast<std::size_t>(r.id)] = {r.x, r.y};
  return true;
}

} // namespace internal

/// Packs the charts of `atlas` into one square texture (see the top of this
/// file): one texel density for every chart, as large as lets them all fit.
///
/// \tparam VertexPointMap a readable property map from the mesh's vertices to 3D points
/// \param vpm the points, for the patches' areas
/// \returns the charts' places; a chart of no area (or no face) gets an empty slot
/// \throws std::invalid_argument if the resolution is below 1 or the gutter
///         negative, or if the charts cannot fit even at one texel each
template <class TriangleMesh, class Kernel, class VertexPointMap>
Chart_packing pack_charts(const Uv_atlas<TriangleMesh, Kernel>& atlas, VertexPointMap vpm,
                          const Chart_packing_options& options = {})
{
  if(options.resolution < 1 || options.gutter < 0)
    throw std::invalid_argument("pack_charts: the resolution must be positive and the gutter not negative");
  const std::size_t n = atlas.number_of_charts();
  Chart_packing packing;
  packing.resolution = options.resolution;
  packing.gutter = options.gutter;
  packing.charts.assign(n, Packed_chart());

  // Each chart's rectangle in units of length: its aspect, its patch's area.
  std::vector<std::array<double, 2>> extent(n, {0., 0.});
  std::vector<std::size_t> placed;
  double total_area = 0., longest = 0.;
  for(std::size_t c = 0; c < n; ++c) {
    const auto& chart = atlas.chart(c);
    double area = 0.;
    for(auto f : chart.faces)
      area += CGAL::to_double(CGAL::Polygon_mesh_processing::face_area(
          f, atlas.mesh(), CGAL::parameters::vertex_point_map(vpm)));
    const double aspect_area = chart.size[0] * chart.size[1];
    if(!(area > 0.) || !(aspect_area > 0.) || !std::isfinite(area)) continue;
    const double k = std::sqrt(area / aspect_area);
    extent[c] = {chart.size[0] * k, chart.size[1] * k};
    total_area += area;
    longest = (std::max)(longest, (std::max)(extent[c][0], extent[c][1]));
    placed.push_back(c);
  }
  if(placed.empty()) return packing;

  const int g = options.gutter;
  // Which charts are turned: none, the tall ones (all lie wide) or the wide
  // ones (all stand tall). Sorted by height, stb's skyline fills its rows
  // differently with each; which packs best depends on the charts.
  std::vector<char> turned(n, 0);
  const auto turn = [&](int policy) {
    for(std::size_t c : placed)
      turned[c] = policy == 1 ? extent[c][1] > extent[c][0] : policy == 2 ? extent[c][0] > extent[c][1] : false;
  };
  const auto slot_sizes = [&](double s) {
    std::vector<std::array<int, 2>> sizes;
    sizes.reserve(placed.size());
    for(std::size_t c : placed) {
      const int w = static_cast<int>(std::ceil(s * extent[c][0])) + 2 * g;
      const int h = static_cast<int>(std::ceil(s * extent[c][1])) + 2 * g;
      sizes.push_back(turned[c] ? std::array<int, 2>{h, w} : std::array<int, 2>{w, h});
    }
    return sizes;
  };
  std::vector<std::array<int, 2>> at;
  const auto fits = [&](double s) {
    const auto sizes = slot_sizes(s);
    for(const auto& size : sizes)
      if(size[0] > options.resolution || size[1] > options.resolution) return false;
    return internal::pack_rectangles(options.resolution, sizes, at);
  };
  // No density packs more area than the texture holds, nor a chart wider than it.
  const double r = options.resolution;
  const double bound = (std::min)(r / std::sqrt(total_area), r / longest) * (1. + 1e-9);
  double low = 0.;
  std::vector<std::array<int, 2>> best_at;
  std::vector<char> best_turned;
  for(int policy = 0; policy < (options.rotate ? 3 : 1); ++policy) {
    turn(policy);
    double lo = 0., hi = bound;
    std::vector<std::array<int, 2>> found;
    if(fits(hi)) {
      lo = hi;
      found = at;
    } else {
      for(int step = 0; step < 40 && hi - lo > 1e-4 * hi; ++step) {
        const double mid = 0.5 * (lo + hi);
        if(fits(mid)) {
          lo = mid;
          found = at;
        } else {
          hi = mid;
        }
      }
    }
    if(!found.empty() && (best_at.empty() || lo > low)) {
      low = lo;
      best_at = std::move(found);
      best_turned = turned;
    }
  }
  if(best_at.empty()) // the gutters alone do not fit
    throw std::invalid_argument("pack_charts: the charts do not fit in the texture with their gutters: raise the "
                                "resolution or narrow the gutter");
  turned = best_turned;
  const double s = low;
  packing.texels_per_unit = s;
  const auto sizes = slot_sizes(s);
  double covered = 0.;
  for(std::size_t k = 0; k < placed.size(); ++k) {
    Packed_chart& p = packing.charts[placed[k]];
    p.rotated = turned[placed[k]] != 0;
    p.x = best_at[k][0];
    p.y = best_at[k][1];
    p.width = sizes[k][0];
    p.height = sizes[k][1];
    p.extent_u = s * extent[placed[k]][0];
    p.extent_v = s * extent[placed[k]][1];
    covered += p.extent_u * p.extent_v;
  }
  packing.coverage = covered / (r * r);
  return packing;
}

/// A halfedge property map: the packed texture coordinates of `target(h)` in
/// the chart of `face(h)` (per corner, as `Uv_atlas::corner_uv_map()`); NaN
/// for border halfedges and faces in no chart. `atlas` and `packing` must
/// outlive the map.
template <class TriangleMesh, class Kernel>
auto packed_corner_map(const Uv_atlas<TriangleMesh, Kernel>& atlas, const Chart_packing& packing)
{
  using halfedge_descriptor = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;
  using Atlas = Uv_atlas<TriangleMesh, Kernel>;
  using Point_2 = typename Atlas::Point_2;
  const auto uv = atlas.corner_uv_map();
  return boost::make_function_property_map<halfedge_descriptor>([&atlas, &packing, uv](halfedge_descriptor h) {
    const Point_2 q = get(uv, h);
    if(is_border(h, atlas.mesh())) return q;
    const std::size_t c = atlas.chart_of(face(h, atlas.mesh()));
    if(c == Atlas::no_chart || packing.charts.at(c).width == 0) {
      const double nan = std::numeric_limits<double>::quiet_NaN();
      return Point_2(nan, nan);
    }
    return packing.texture_point(c, q);
  });
}

} // namespace diffuv

#endif // DIFFUV_RENDER_PACK_CHARTS_H
