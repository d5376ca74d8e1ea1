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
//      none turned: whichever packs densest
//   -> half a gutter of texels on each side of it, so that two charts lie a
//      whole gutter apart, as UVAtlas counts its gutter (bilinear filtering
//      must not mix two charts' texels; baking dilates each chart into its
//      half)
//   -> the largest density at which every chart fits (with shelves, each
//      chart's within a tolerance of it), with one of two packers:
//      - shelves (the default): rows of charts of one height, tallest first,
//        each row filled to the texture's edge by letting every chart's
//        density and aspect give a little (within 4.5 % and 10 %); most
//        charts then fill their slots to the gutters in whole texels;
//      - skyline: stb_rect_pack's packer (Debian's libstb-dev), every chart
//        at exactly one density and its own aspect, in a slot rounded up to
//        whole texels (the chart is not stretched to the rounded size).
//
// stb's packer places fixed rectangles; the shelves use the freedom the
// issue allows (density within 10 %), which a fixed-size packer cannot:
// with ~300 charts the skyline leaves about 10 % of the texture between
// slots, the shelves 1-3 % (doc/design.md, "Packed atlas").
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

/// How `pack_charts()` places the charts' slots.
enum class Chart_packer {
  /// Rows ("shelves") of charts of one height, each row filled to the
  /// texture's width: a chart's texel density may differ from the atlas's by
  /// `density_tolerance` and its rectangle's aspect from its patch's by
  /// `aspect_tolerance`, so that rows close without gaps.
  shelves,
  /// stb_rect_pack's skyline packer: every chart at exactly one density and
  /// its patch's aspect, in slots rounded up to whole texels.
  skyline
};

/// Options of `pack_charts()`.
struct Chart_packing_options {
  int resolution = 1024; ///< the texture's width and height in texels
  /// Texels kept free between two charts (the least distance between them,
  /// as UVAtlas's gutter): each chart has half of it on each side, so half
  /// of it also lies between a chart and the texture's edge.
  int gutter = 2;
  /// Try the charts turned by 90 degrees to lie all wide and all tall as
  /// well as unturned, and keep whichever packs densest.
  bool rotate = true;
  Chart_packer packer = Chart_packer::shelves;
  /// Shelves: a chart's density lies within this share of the atlas's
  /// (0.045: any two charts' densities within 10 % of each other).
  double density_tolerance = 0.045;
  /// Shelves: a chart's rectangle may be up to this share wider or
  /// narrower, for its height, than its patch's aspect (the aspect was
  /// chosen for least stretch: 10 % costs cow, man, bull, bunny00 and
  /// camel 0.1 % of their L2 and 0.2-0.7 % of their angle distortion).
  double aspect_tolerance = 0.10;
};

/// One chart's place in the texture. Texels are counted from the lower left
/// corner (texture coordinates (0,0)), as OBJ and OpenGL count them.
struct Packed_chart {
  int x = 0, y = 0;          ///< lower left texel of the chart's slot (its half gutters included)
  int width = 0, height = 0; ///< the slot, in texels, half a gutter on each side included (0 for a chart of no area)
  bool rotated = false;      ///< drawn turned by 90 degrees counter-clockwise
  double extent_u = 0.;      ///< texels the chart is drawn across along u (before turning)
  double extent_v = 0.;      ///< texels the chart is drawn across along v
};

/// Where `pack_charts()` put the charts.
struct Chart_packing {
  int resolution = 0;
  int gutter = 0;
  /// Texels per unit of length on the surface: every chart's with the
  /// skyline packer; with shelves, each chart's lies within
  /// `density_tolerance` of it (sqrt(extent_u extent_v / its 3D area)).
  double texels_per_unit = 0.;
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
    const double r = resolution, half = 0.5 * gutter;
    if(p.rotated)
      return Point_2((p.x + half + (1. - v) * p.extent_v) / r, (p.y + half + u * p.extent_u) / r);
    return Point_2((p.x + half + u * p.extent_u) / r, (p.y + half + v * p.extent_v) / r);
  }
};

namespace internal {

/// Packs rectangles of `sizes` (width, height in texels, half gutters included)
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

/// A chart's place in a shelf packing: its slot (half a gutter on each side
/// included) and the size it is drawn at inside it, in texels.
struct Shelf_slot {
  int x = 0, y = 0, width = 0, height = 0;
  double drawn_width = 0., drawn_height = 0.;
};

/// Packs charts of `sizes` (width, height in texels at the atlas's density,
/// as they will lie) into rows, bottom up, each as wide as the texture: the
/// tallest charts first; a row's height is the least its first chart may be
/// drawn at, and every later chart of the row is drawn at that height (its
/// density within `density_tolerance` and its aspect within
/// `aspect_tolerance`) or, if it cannot reach it, at the most its density
/// allows, at the row's foot. A row takes charts while they fit at their
/// least widths; then the widths are grown or shrunk within the same
/// tolerances so that the row ends at the texture's edge, and rounded to
/// whole texels. False if the rows do not fit.
/// `order`: the charts as the rows take them, `shelf_order(sizes)` (the same
/// at every density, so a caller that tries many densities sorts once).
inline bool pack_shelves(int resolution, int gutter, double density_tolerance, double aspect_tolerance,
                         const std::vector<std::array<double, 2>>& sizes, const std::vector<std::size_t>& order,
                         std::vector<Shelf_slot>& slots)
{
  const std::size_t n = sizes.size();
  slots.assign(n, Shelf_slot());
  const double R = resolution, g = gutter; // a slot holds its chart and half a gutter on each side
  const double low_density = 1. - density_tolerance, high_density = 1. + density_tolerance;
  const double wider = 1. + aspect_tolerance;
  // A chart of (w, h) drawn at height H: the widths its tolerances allow.
  const auto widths = [&](double w, double h, double H) {
    const double area = w * h, aspect = w / h;
    return std::array<double, 2>{(std::max)(low_density * low_density * area / H, H * aspect / wider),
                                 (std::min)(high_density * high_density * area / H, H * aspect * wider)};
  };
  const double shortest = low_density / std::sqrt(wider), tallest = high_density * std::sqrt(wider);
  int y = 0;
  std::size_t next = 0;
  std::vector<std::size_t> row;
  std::vector<double> least, most, width, drawn_height;
  while(next < n) {
    const double w0 = sizes[order[next]][0], h0 = sizes[order[next]][1];
    // The row's height: the least its first chart may be drawn at; a chart
    // too small for a whole texel within its tolerances is drawn at its own
    // size in a slot rounded up, as the skyline packer draws every chart.
    int H = (std::max)(1, static_cast<int>(std::ceil(shortest * h0 - 1e-9)));
    const bool first_fits = H <= tallest * h0 + 1e-9;
    if(!first_fits) H = (std::max)(1, static_cast<int>(std::ceil(h0 - 1e-9)));
    row.clear();
    least.clear();
    most.clear();
    width.clear();
    drawn_height.clear();
    double sum_least = 0.;
    for(std::size_t j = next; j < n; ++j) {
      const double w = sizes[order[j]][0], h = sizes[order[j]][1];
      std::array<double, 2> range;
      double preferred, tall = sizes[order[j]][1];
      if(j == next && !first_fits) {
        range = {(std::max)(1., std::ceil(w - 1e-9)), (std::max)(1., std::ceil(w - 1e-9))};
        preferred = range[0];
      } else {
        if(H < shortest * h - 1e-9) break; // cannot be drawn this low
        // A chart that cannot reach the row's height is drawn at the height
        // its density allows, at the row's foot (next-fit by decreasing
        // height: the row is still filled to the edge).
        tall = H > tallest * h + 1e-9 ? high_density * h : static_cast<double>(H);
        range = widths(w, h, tall);
        range[1] = (std::max)(range[1], range[0]); // equal up to rounding
        preferred = (std::min)((std::max)(tall * w / h, range[0]), range[1]); // its own aspect where it can
      }
      // The row holds it if every chart fits at its least whole width (a
      // slot is at least a texel wide; a narrower chart is drawn narrower).
      const double fewest_texels = (std::max)(1., std::ceil(range[0] - 1e-9));
      if(sum_least + fewest_texels + g * static_cast<double>(row.size() + 1) > R) break;
      row.push_back(order[j]);
      least.push_back(range[0]);
      most.push_back(range[1]);
      width.push_back(preferred);
      drawn_height.push_back(tall);
      sum_least += fewest_texels;
    }
    if(row.empty()) return false; // the first chart is wider than the texture
    // Widths within their tolerances that end the row at the texture's edge
    // (or as near as the tolerances let them).
    const double room = R - g * static_cast<double>(row.size());
    double sum = 0., slack = 0.;
    for(double w : width) sum += w;
    if(sum < room) {
      for(std::size_t k = 0; k < row.size(); ++k) slack += most[k] - width[k];
      const double t = slack > 0. ? (std::min)(1., (room - sum) / slack) : 0.;
      for(std::size_t k = 0; k < row.size(); ++k) width[k] += t * (most[k] - width[k]);
    } else if(sum > room) {
      for(std::size_t k = 0; k < row.size(); ++k) slack += width[k] - least[k];
      const double t = slack > 0. ? (std::min)(1., (sum - room) / slack) : 0.;
      for(std::size_t k = 0; k < row.size(); ++k) width[k] -= t * (width[k] - least[k]);
    }
    // Whole texels: each width rounded down (not below its tolerance),
    // then texels taken from or handed to the widths by their remainders
    // so that the row ends at the edge; a chart is drawn no wider than its
    // tolerance allows, even in a slot a fraction of a texel wider.
    sum = 0.;
    std::vector<int> whole(row.size()), fewest(row.size());
    int whole_sum = 0;
    for(std::size_t k = 0; k < row.size(); ++k) {
      sum += width[k];
      fewest[k] = (std::max)(1, static_cast<int>(std::ceil(least[k] - 1e-9)));
      whole[k] = (std::max)(fewest[k], static_cast<int>(std::floor(width[k] + 1e-9)));
      whole_sum += whole[k];
    }
    const int room_whole = resolution - gutter * static_cast<int>(row.size());
    const int wanted = (std::min)(room_whole, static_cast<int>(std::floor(sum + 0.5)));
    std::vector<std::size_t> by_remainder(row.size());
    for(std::size_t k = 0; k < row.size(); ++k) by_remainder[k] = k;
    std::stable_sort(by_remainder.begin(), by_remainder.end(), [&](std::size_t a, std::size_t b) {
      return width[a] - whole[a] > width[b] - whole[b];
    });
    for(std::size_t k = 0; whole_sum < wanted && k < by_remainder.size(); ++k)
      if(whole[by_remainder[k]] < most[by_remainder[k]] - 1e-9) { // drawn no wider than its most
        ++whole[by_remainder[k]];
        ++whole_sum;
      }
    for(std::size_t k = by_remainder.size(); whole_sum > room_whole && k-- > 0;)
      if(whole[by_remainder[k]] > fewest[by_remainder[k]]) {
        --whole[by_remainder[k]];
        --whole_sum;
      }
    if(y + H + gutter > resolution) return false;
    int x = 0;
    for(std::size_t k = 0; k < row.size(); ++k) {
      Shelf_slot& slot = slots[row[k]];
      slot.x = x;
      slot.y = y;
      slot.width = whole[k] + gutter;
      slot.height = H + gutter;
      const bool own_size = k == 0 && !first_fits;
      // Rounding may not take a chart out of its tolerances: it is drawn
      // within them, inside a slot of whole texels.
      slot.drawn_width = own_size ? sizes[row[k]][0] : (std::min)(double(whole[k]), most[k]);
      slot.drawn_height = drawn_height[k];
      x += slot.width;
    }
    if(x > resolution) return false;
    y += H + gutter;
    next += row.size();
  }
  return true;
}

/// The order in which `pack_shelves()` takes charts: the tallest first, then
/// the widest, then by number.
inline std::vector<std::size_t> shelf_order(const std::vector<std::array<double, 2>>& sizes)
{
  std::vector<std::size_t> order(sizes.size());
  for(std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if(sizes[a][1] != sizes[b][1]) return sizes[a][1] > sizes[b][1];
    return sizes[a][0] > sizes[b][0];
  });
  return order;
}

inline bool pack_shelves(int resolution, int gutter, double density_tolerance, double aspect_tolerance,
                         const std::vector<std::array<double, 2>>& sizes, std::vector<Shelf_slot>& slots)
{
  return pack_shelves(resolution, gutter, density_tolerance, aspect_tolerance, sizes, shelf_order(sizes), slots);
}

} // namespace internal

/// Packs the charts of `atlas` into one square texture (see the top of this
/// file): one texel density for every chart (with shelves, each chart's
/// within `density_tolerance` of it), as large as lets them all fit.
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
  if(!(options.density_tolerance >= 0. && options.density_tolerance < 1. && options.aspect_tolerance >= 0. &&
       options.aspect_tolerance <= 1.))
    throw std::invalid_argument("pack_charts: the density tolerance must lie in [0,1) and the aspect tolerance "
                                "in [0,1]");
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
      const int w = static_cast<int>(std::ceil(s * extent[c][0])) + g;
      const int h = static_cast<int>(std::ceil(s * extent[c][1])) + g;
      sizes.push_back(turned[c] ? std::array<int, 2>{h, w} : std::array<int, 2>{w, h});
    }
    return sizes;
  };
  const bool shelves = options.packer == Chart_packer::shelves;
  std::vector<std::array<int, 2>> at;
  std::vector<internal::Shelf_slot> shelf_slots;
  // The charts' sizes at density s, as they lie; for shelves, the order in
  // which rows take them, the same at every density (set for each way of
  // turning below): sorting it at each of the densities tried was half of
  // the packing's time.
  std::vector<std::array<double, 2>> shelf_sizes;
  std::vector<std::size_t> row_order;
  const auto sizes_at = [&](double s) {
    shelf_sizes.clear();
    for(std::size_t c : placed)
      shelf_sizes.push_back(turned[c] ? std::array<double, 2>{s * extent[c][1], s * extent[c][0]}
                                      : std::array<double, 2>{s * extent[c][0], s * extent[c][1]});
  };
  const auto fits = [&](double s) {
    if(shelves) {
      sizes_at(s);
      return internal::pack_shelves(options.resolution, g, options.density_tolerance, options.aspect_tolerance,
                                    shelf_sizes, row_order, shelf_slots);
    }
    const auto sizes = slot_sizes(s);
    for(const auto& size : sizes)
      if(size[0] > options.resolution || size[1] > options.resolution) return false;
    return internal::pack_rectangles(options.resolution, sizes, at);
  };
  // No density packs more area than the texture holds, nor a chart wider
  // than it (shelves may draw a chart a little smaller than the density says).
  const double r = options.resolution;
  const double area_share = shelves ? 1. - options.density_tolerance : 1.;
  const double length_share =
      shelves ? (1. - options.density_tolerance) / std::sqrt(1. + options.aspect_tolerance) : 1.;
  const double bound =
      (std::min)(r / (std::sqrt(total_area) * area_share), r / (longest * length_share)) * (1. + 1e-9);
  // Each way of turning, its largest density that fits (by bisection) and
  // the slots found at it; kept: the way that covers the most texels.
  struct Found {
    double density = 0., covered = -1.;
    std::vector<char> turned;
    std::vector<std::array<int, 2>> at;
    std::vector<internal::Shelf_slot> shelf_slots;
  };
  Found best;
  const auto covered_by = [](const std::vector<internal::Shelf_slot>& slots) {
    double c = 0.;
    for(const auto& slot : slots) c += slot.drawn_width * slot.drawn_height;
    return c;
  };
  for(int policy = 0; policy < (options.rotate ? 3 : 1); ++policy) {
    turn(policy);
    if(shelves) {
      sizes_at(1.);
      row_order = internal::shelf_order(shelf_sizes);
    }
    double lo = 0., hi = bound;
    Found here;
    const auto keep = [&](double s) {
      here.density = s;
      here.covered = 0.;
      here.at = at;
      here.shelf_slots = shelf_slots;
    };
    if(fits(hi)) {
      keep(hi);
    } else if(shelves) {
      // Whether rows fit is not monotone in the density (a row more or less
      // moves every later row), so bisection could stop far below the best:
      // step down from the bound by 0.3 % until the rows fit, then bisect
      // within that step, keeping the packing that covers the most.
      // At the floor every chart is under a texel (at the bound the
      // longest spans at most r / length_share texels): if the rows do not
      // fit there, the gutters alone do not, and stepping down is vain.
      const double floor = hi / (2. * r);
      if(fits(floor)) {
        double s = hi;
        while(s > floor && !fits(s)) {
          hi = s;
          s *= 0.997;
        }
        if(s <= floor) {
          s = floor;
          fits(s);
        }
        lo = s;
        keep(s);
        double kept = covered_by(shelf_slots);
        for(int step = 0; step < 12; ++step) {
          const double mid = 0.5 * (lo + hi);
          if(fits(mid)) {
            lo = mid;
            const double c = covered_by(shelf_slots);
            if(c > kept) {
              kept = c;
              keep(mid);
            }
          } else {
            hi = mid;
          }
        }
      }
    } else {
      for(int step = 0; step < 40 && hi - lo > 1e-4 * hi; ++step) {
        const double mid = 0.5 * (lo + hi);
        if(fits(mid)) {
          lo = mid;
          keep(mid);
        } else {
          hi = mid;
        }
      }
    }
    if(here.covered < 0.) continue; // not even the smallest density fits
    if(shelves) {
      here.covered = covered_by(here.shelf_slots);
    } else {
      for(std::size_t c : placed) here.covered += here.density * here.density * extent[c][0] * extent[c][1];
    }
    here.turned = turned;
    if(here.covered > best.covered) best = std::move(here);
  }
  if(best.covered < 0.) // the gutters alone do not fit
    throw std::invalid_argument("pack_charts: the charts do not fit in the texture with their gutters: raise the "
                                "resolution or narrow the gutter");
  turned = best.turned;
  const double s = best.density;
  packing.texels_per_unit = s;
  const auto sizes = shelves ? std::vector<std::array<int, 2>>() : slot_sizes(s);
  for(std::size_t k = 0; k < placed.size(); ++k) {
    Packed_chart& p = packing.charts[placed[k]];
    p.rotated = turned[placed[k]] != 0;
    if(shelves) {
      const internal::Shelf_slot& slot = best.shelf_slots[k];
      p.x = slot.x;
      p.y = slot.y;
      p.width = slot.width;
      p.height = slot.height;
      // A turned chart lies with its v along the texture's width.
      p.extent_u = p.rotated ? slot.drawn_height : slot.drawn_width;
      p.extent_v = p.rotated ? slot.drawn_width : slot.drawn_height;
    } else {
      p.x = best.at[k][0];
      p.y = best.at[k][1];
      p.width = sizes[k][0];
      p.height = sizes[k][1];
      p.extent_u = s * extent[placed[k]][0];
      p.extent_v = s * extent[placed[k]][1];
    }
  }
  packing.coverage = best.covered / (r * r);
  return packing;
}

/// A halfedge property map: the packed texture coordinates of `target(h)` in
/// the chart of `face(h)` (per corner, as `Uv_atlas::corner_uv_map()`, drawn
/// with the chart's warps as `Uv_atlas::corner_drawn_uv_map()`); NaN
/// for border halfedges and faces in no chart. `atlas` and `packing` must
/// outlive the map.
template <class TriangleMesh, class Kernel>
auto packed_corner_map(const Uv_atlas<TriangleMesh, Kernel>& atlas, const Chart_packing& packing)
{
  using halfedge_descriptor = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;
  using Atlas = Uv_atlas<TriangleMesh, Kernel>;
  using Point_2 = typename Atlas::Point_2;
  const auto uv = atlas.corner_drawn_uv_map();
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
