// Tests of pack_charts() (render/pack_charts.h): the charts of an atlas packed
// into one texture, checked by rasterising the packed triangles.
#include "test_data.h"

#include <diffuv/render/pack_charts.h>
#include <diffuv/layout/disc_patches.h>
#include <diffuv/parameterization/parameterize_patches.h>

#include <CGAL/Polygon_mesh_processing/measure.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <limits>
#include <map>
#include <set>
#include <vector>

namespace {

using namespace diffuv_test;
using Atlas = diffuv::Uv_atlas<Mesh>;
using Point_2 = Atlas::Point_2;

// cow's (or another mesh's) default patches, mapped.
struct Mapped {
  std::unique_ptr<Atlas> atlas;
  std::vector<diffuv::Patch_result<Mesh>> results;
};

Mapped map_default(const Mesh& m)
{
  Mapped out;
  diffuv::Segmentation<Mesh> seg;
  EXPECT_TRUE(diffuv::disc_patches(m, m.points(), {}, seg).ok());
  out.atlas = std::make_unique<Atlas>(m);
  out.results = diffuv::parameterize_patches(m, m.points(), seg, *out.atlas);
  return out;
}

// For each texel centre, how many charts' packed triangles contain it (each
// chart counted once): the texture as a renderer would sample it.
std::vector<int> charts_per_texel(const Atlas& atlas, const diffuv::Chart_packing& packing)
{
  const int r = packing.resolution;
  std::vector<int> count(static_cast<std::size_t>(r) * r, 0);
  std::vector<int> last_chart(count.size(), -1);
  const Mesh& m = atlas.mesh();
  const auto corner = diffuv::packed_corner_map(atlas, packing);
  for(std::size_t c = 0; c < atlas.number_of_charts(); ++c)
    for(auto f : atlas.chart(c).faces) {
      std::array<Point_2, 3> t;
      std::size_t k = 0;
      for(auto h : CGAL::halfedges_around_face(m.halfedge(f), m)) t[k++] = get(corner, h);
      const auto edge = [](const Point_2& a, const Point_2& b, double x, double y) {
        return (b.x() - a.x()) * (y - a.y()) - (b.y() - a.y()) * (x - a.x());
      };
      const double area = edge(t[0], t[1], t[2].x(), t[2].y());
      if(area == 0.) continue;
      const double x0 = std::min({t[0].x(), t[1].x(), t[2].x()}) * r, x1 = std::max({t[0].x(), t[1].x(), t[2].x()}) * r;
      const double y0 = std::min({t[0].y(), t[1].y(), t[2].y()}) * r, y1 = std::max({t[0].y(), t[1].y(), t[2].y()}) * r;
      for(int j = std::max(0, int(std::floor(y0 - 0.5))); j <= std::min(r - 1, int(std::ceil(y1))); ++j)
        for(int i = std::max(0, int(std::floor(x0 - 0.5))); i <= std::min(r - 1, int(std::ceil(x1))); ++i) {
          const double x = (i + 0.5) / r, y = (j + 0.5) / r;
          const double e0 = edge(t[0], t[1], x, y), e1 = edge(t[1], t[2], x, y), e2 = edge(t[2], t[0], x, y);
          const bool inside = area > 0 ? (e0 >= 0 && e1 >= 0 && e2 >= 0) : (e0 <= 0 && e1 <= 0 && e2 <= 0);
          const std::size_t at = static_cast<std::size_t>(j) * r + i;
          if(inside && last_chart[at] != int(c)) {
            ++count[at];
            last_chart[at] = int(c);
          }
        }
    }
  return count;
}

// A face's three corners under two corner maps (e.g. the chart's own
// coordinates and the packed ones).
template <class MapA, class MapB>
std::array<std::array<Point_2, 3>, 2> corners_under(const Mesh& m, boost::graph_traits<Mesh>::face_descriptor f,
                                                    const MapA& first, const MapB& second)
{
  std::array<std::array<Point_2, 3>, 2> t;
  std::size_t k = 0;
  for(auto h : CGAL::halfedges_around_face(m.halfedge(f), m)) {
    t[0][k] = get(first, h);
    t[1][k++] = get(second, h);
  }
  return t;
}

// cow's charts at 512 x 512: every packed point inside its chart's slot and
// inside the texture, no texel sampled by two charts, the covered share as
// counted by rasterising equal to the reported coverage, one texel density.
TEST(PackCharts, CowChartsShareOneTextureWithoutOverlap)
{
  const Mesh& cow = cgal_mesh("cow.off");
  const Mapped mapped = map_default(cow);
  const Atlas& atlas = *mapped.atlas;
  ASSERT_GT(atlas.number_of_charts(), 10u);
  diffuv::Chart_packing_options options;
  options.resolution = 512;
  options.gutter = 2;
  const diffuv::Chart_packing packing = diffuv::pack_charts(atlas, cow.points(), options);
  ASSERT_EQ(packing.charts.size(), atlas.number_of_charts());
  EXPECT_GT(packing.texels_per_unit, 0.);

  // Slots inside the texture, pairwise apart.
  for(std::size_t a = 0; a < packing.charts.size(); ++a) {
    const auto& p = packing.charts[a];
    ASSERT_GT(p.width, options.gutter);
    EXPECT_GE(p.x, 0);
    EXPECT_GE(p.y, 0);
    EXPECT_LE(p.x + p.width, options.resolution);
    EXPECT_LE(p.y + p.height, options.resolution);
    for(std::size_t b = a + 1; b < packing.charts.size(); ++b) {
      const auto& q = packing.charts[b];
      const bool apart = p.x + p.width <= q.x || q.x + q.width <= p.x || p.y + p.height <= q.y || q.y + q.height <= p.y;
      EXPECT_TRUE(apart) << "charts " << a << " and " << b;
    }
  }
  // Each chart's points inside its slot, half a gutter away from the slot's
  // edges (so two charts lie a whole gutter apart).
  const auto corner = diffuv::packed_corner_map(atlas, packing);
  const double r = options.resolution, g = 0.5 * options.gutter;
  for(std::size_t c = 0; c < atlas.number_of_charts(); ++c) {
    const auto& p = packing.charts[c];
    double chart_area = 0.;
    for(auto f : atlas.chart(c).faces) {
      chart_area += CGAL::Polygon_mesh_processing::face_area(f, cow);
      for(auto h : CGAL::halfedges_around_face(cow.halfedge(f), cow)) {
        const Point_2 t = get(corner, h);
        ASSERT_GE(t.x() * r, p.x + g - 1e-9) << "chart " << c;
        ASSERT_LE(t.x() * r, p.x + p.width - g + 1e-9) << "chart " << c;
        ASSERT_GE(t.y() * r, p.y + g - 1e-9) << "chart " << c;
        ASSERT_LE(t.y() * r, p.y + p.height - g + 1e-9) << "chart " << c;
      }
    }
    // One density within the shelves' tolerance: the chart's rectangle in
    // texels has the patch's area times a density within 4.5 % of the atlas's.
    const double density = std::sqrt(p.extent_u * p.extent_v / chart_area);
    EXPECT_NEAR(density, packing.texels_per_unit, options.density_tolerance * packing.texels_per_unit + 1e-9)
        << "chart " << c;
    // Its aspect within 10 % of the patch's, turned or not.
    const auto& size = atlas.chart(c).size;
    const double aspect_change = (p.extent_u / p.extent_v) / (size[0] / size[1]);
    EXPECT_LE(aspect_change, 1. + options.aspect_tolerance + 1e-9) << "chart " << c;
    EXPECT_GE(aspect_change, 1. / (1. + options.aspect_tolerance) - 1e-9) << "chart " << c;
    // Drawn in its slot, which is whole texels: only the half gutters are left.
    EXPECT_LE(p.extent_u + 2 * g, (p.rotated ? p.height : p.width) + 1e-9);
    EXPECT_LE(p.extent_v + 2 * g, (p.rotated ? p.width : p.height) + 1e-9);
  }
  // The gutter lies between two charts, not on each side of each: the
  // charts' drawn rectangles are at least a gutter apart, and the nearest
  // two (neighbours in a row, both filling their slots) exactly a gutter;
  // the charts that start a row lie half a gutter from the texture's edge.
  double nearest_pair = std::numeric_limits<double>::infinity(), nearest_edge = nearest_pair;
  const auto drawn = [&](std::size_t c) {
    const auto& p = packing.charts[c];
    const double w = p.rotated ? p.extent_v : p.extent_u, h = p.rotated ? p.extent_u : p.extent_v;
    return std::array<double, 4>{p.x + g, p.y + g, p.x + g + w, p.y + g + h};
  };
  for(std::size_t a = 0; a < packing.charts.size(); ++a) {
    const auto A = drawn(a);
    nearest_edge = std::min({nearest_edge, A[0], A[1]});
    for(std::size_t b = a + 1; b < packing.charts.size(); ++b) {
      const auto B = drawn(b);
      nearest_pair = std::min(nearest_pair, std::max({B[0] - A[2], A[0] - B[2], B[1] - A[3], A[1] - B[3]}));
    }
  }
  EXPECT_GE(nearest_pair, options.gutter - 1e-9);
  EXPECT_LE(nearest_pair, options.gutter + 1e-6);
  EXPECT_NEAR(nearest_edge, 0.5 * options.gutter, 1e-9);
  // One way of turning for all charts: none, the tall ones or the wide ones.
  std::set<int> turned_kinds;
  for(std::size_t c = 0; c < atlas.number_of_charts(); ++c) {
    const auto& size = atlas.chart(c).size;
    if(size[0] == size[1]) continue;
    if(packing.charts[c].rotated) turned_kinds.insert(size[1] > size[0] ? 1 : 2);
  }
  EXPECT_LE(turned_kinds.size(), 1u);
  const std::vector<int> count = charts_per_texel(atlas, packing);
  EXPECT_EQ(*std::max_element(count.begin(), count.end()), 1) << "a texel sampled by two charts";
  const double covered =
      double(std::count(count.begin(), count.end(), 1)) / double(count.size());
  // The diffusion map covers its rectangle: rasterised and reported agree
  // up to the texels cut by the rectangles' edges.
  EXPECT_NEAR(covered, packing.coverage, 0.05) << "rasterised " << covered << ", reported " << packing.coverage;
  EXPECT_GT(packing.coverage, 0.5);
}

// The skyline packer's coordinates keep each triangle's orientation (a
// turned chart is turned, not mirrored) and its shape up to one scale: the
// same L2 stretch as on the chart's rectangle, one density everywhere.
TEST(PackCharts, TurningKeepsOrientationAndShape)
{
  const Mesh& cow = cgal_mesh("cow.off");
  const Mapped mapped = map_default(cow);
  const Atlas& atlas = *mapped.atlas;
  diffuv::Chart_packing_options skyline;
  skyline.packer = diffuv::Chart_packer::skyline;
  const diffuv::Chart_packing packing = diffuv::pack_charts(atlas, cow.points(), skyline);
  const auto packed = diffuv::packed_corner_map(atlas, packing);
  const auto rectangle = atlas.corner_texture_map();
  std::size_t turned = 0;
  for(std::size_t c = 0; c < atlas.number_of_charts(); ++c) {
    turned += packing.charts[c].rotated;
    const auto& size = atlas.chart(c).size;
    const double scale = packing.charts[c].extent_u / size[0]; // texels per unit of the rectangle
    EXPECT_NEAR(packing.charts[c].extent_v / size[1], scale, 1e-9 * scale);
    for(auto f : atlas.chart(c).faces) {
      const auto [a, b] = corners_under(cow, f, rectangle, packed);
      const double area_a = CGAL::area(a[0], a[1], a[2]);
      const double area_b = CGAL::area(b[0], b[1], b[2]) * packing.resolution * packing.resolution;
      EXPECT_NEAR(area_b, area_a * scale * scale, 1e-6 * std::abs(area_a) * scale * scale + 1e-12) << "chart " << c;
      // Lengths scale by one factor: a similarity.
      for(int e = 0; e < 3; ++e) {
        const double la = std::sqrt(CGAL::squared_distance(a[e], a[(e + 1) % 3]));
        const double lb = std::sqrt(CGAL::squared_distance(b[e], b[(e + 1) % 3])) * packing.resolution;
        EXPECT_NEAR(lb, la * scale, 1e-6 * la * scale + 1e-9);
      }
    }
  }
  (void)turned;
  // One density: the chart's rectangle in texels has the patch's area times density squared.
  for(std::size_t c = 0; c < atlas.number_of_charts(); ++c) {
    double chart_area = 0.;
    for(auto f : atlas.chart(c).faces) chart_area += CGAL::Polygon_mesh_processing::face_area(f, cow);
    const auto& p = packing.charts[c];
    EXPECT_NEAR(p.extent_u * p.extent_v, chart_area * packing.texels_per_unit * packing.texels_per_unit,
                1e-6 * p.extent_u * p.extent_v)
        << "chart " << c;
  }
}

// The shelves never mirror a chart and map it affinely: every packed
// triangle keeps its orientation, and its area over its area as drawn on
// the unit square (warped) is one number per chart (the drawn rectangle's,
// in texels).
TEST(PackCharts, ShelvesKeepOrientationAndOneScalePerChart)
{
  const Mesh& cow = cgal_mesh("cow.off");
  const Mapped mapped = map_default(cow);
  const Atlas& atlas = *mapped.atlas;
  const diffuv::Chart_packing packing = diffuv::pack_charts(atlas, cow.points());
  const auto packed = diffuv::packed_corner_map(atlas, packing);
  const auto square = atlas.corner_drawn_uv_map();
  const double r = packing.resolution;
  std::size_t turned = 0;
  for(std::size_t c = 0; c < atlas.number_of_charts(); ++c) {
    const auto& p = packing.charts[c];
    turned += p.rotated;
    for(auto f : atlas.chart(c).faces) {
      const auto [a, b] = corners_under(cow, f, square, packed);
      const double area_a = CGAL::area(a[0], a[1], a[2]);
      const double area_b = CGAL::area(b[0], b[1], b[2]) * r * r;
      if(std::abs(area_a) < 1e-12) continue;
      EXPECT_GT(area_a * area_b, 0.) << "chart " << c << ": a triangle mirrored";
      EXPECT_NEAR(area_b / area_a, p.extent_u * p.extent_v, 1e-6 * p.extent_u * p.extent_v) << "chart " << c;
    }
  }
  EXPECT_GT(turned, 0u) << "cow's charts all lying one way is unlikely: is turning tried?";
}

// The shelves cover more of the texture than the skyline on the same charts
// (their point: rows closed at the edge, charts filling whole texels), with
// every chart's density within 10 % of every other's and no texel sampled
// by two charts.
TEST(PackCharts, ShelvesCoverMoreThanTheSkyline)
{
  for(const char* name : {"cow.off", "man.off"}) {
    const Mesh& m = cgal_mesh(name);
    const Mapped mapped = map_default(m);
    diffuv::Chart_packing_options skyline;
    skyline.packer = diffuv::Chart_packer::skyline;
    const auto shelves = diffuv::pack_charts(*mapped.atlas, m.points());
    const auto stb = diffuv::pack_charts(*mapped.atlas, m.points(), skyline);
    EXPECT_GT(shelves.coverage, stb.coverage + 0.02) << name;
    const std::vector<int> count = charts_per_texel(*mapped.atlas, shelves);
    EXPECT_EQ(*std::max_element(count.begin(), count.end()), 1) << name;
    const double covered = double(std::count(count.begin(), count.end(), 1)) / double(count.size());
    EXPECT_NEAR(covered, shelves.coverage, 0.03) << name;
    double lowest = 1e300, highest = 0.;
    for(std::size_t c = 0; c < mapped.atlas->number_of_charts(); ++c) {
      double area = 0.;
      for(auto f : mapped.atlas->chart(c).faces) area += CGAL::Polygon_mesh_processing::face_area(f, m);
      const auto& p = shelves.charts[c];
      if(p.width == 0) continue;
      const double density = std::sqrt(p.extent_u * p.extent_v / area);
      lowest = std::min(lowest, density);
      highest = std::max(highest, density);
    }
    EXPECT_LE(highest / lowest, 1.1) << name;
  }
}

// The shelves on sizes no mesh gave them: many equal squares, a spread from
// sub-texel to a quarter of the texture, one chart wider than the texture.
// Slots inside the texture and pairwise apart, each chart drawn inside its
// slot half a gutter from its edges, every chart of at least a texel within its
// density and aspect tolerances.
TEST(PackCharts, ShelvesOnSizesOfEveryKind)
{
  const int R = 256, g = 2;
  const double dt = 0.045, at = 0.10;
  std::vector<std::array<double, 2>> equal(100, {20., 20.}), spread;
  unsigned state = 12345;
  const auto random = [&state] { // a fixed linear congruential sequence in [0,1)
    state = state * 1103515245u + 12345u;
    return double((state >> 8) & 0xffffu) / 65536.;
  };
  for(int k = 0; k < 300; ++k) {
    const double side = 0.3 * std::pow(200., random()); // 0.3 to 60 texels
    spread.push_back({side * (0.5 + random()), side});
  }
  std::vector<std::array<double, 2>> specks(500, {0.2, 0.7}), needles(50, {0.3, 12.});
  for(const auto* sizes : {&equal, &spread, &specks, &needles}) {
    std::vector<diffuv::internal::Shelf_slot> slots;
    // The largest scale at which they fit (sizes grow with it), found by stepping down.
    double scale = 4.;
    std::vector<std::array<double, 2>> scaled;
    bool fitted = false;
    for(; scale > 0.01 && !fitted; scale *= 0.97) {
      scaled = *sizes;
      for(auto& s : scaled) s = {s[0] * scale, s[1] * scale};
      fitted = diffuv::internal::pack_shelves(R, g, dt, at, scaled, slots);
    }
    ASSERT_TRUE(fitted);
    ASSERT_EQ(slots.size(), scaled.size());
    double covered = 0.;
    for(std::size_t a = 0; a < slots.size(); ++a) {
      const auto& p = slots[a];
      EXPECT_GE(p.x, 0);
      EXPECT_GE(p.y, 0);
      EXPECT_LE(p.x + p.width, R);
      EXPECT_LE(p.y + p.height, R);
      EXPECT_LE(p.drawn_width + g, p.width + 1e-9) << a;
      EXPECT_LE(p.drawn_height + g, p.height + 1e-9) << a;
      for(std::size_t b = a + 1; b < slots.size(); ++b) {
        const auto& q = slots[b];
        EXPECT_TRUE(p.x + p.width <= q.x || q.x + q.width <= p.x || p.y + p.height <= q.y || q.y + q.height <= p.y)
            << a << " and " << b;
      }
      const double w = scaled[a][0], h = scaled[a][1];
      covered += p.drawn_width * p.drawn_height;
      const double density = std::sqrt(p.drawn_width * p.drawn_height / (w * h));
      EXPECT_NEAR(density, 1., dt + 1e-9) << a << ": " << w << " x " << h;
      const double aspect = (p.drawn_width / p.drawn_height) / (w / h);
      EXPECT_LE(aspect, 1. + at + 1e-9) << a;
      EXPECT_GE(aspect, 1. / (1. + at) - 1e-9) << a;
    }
    if(sizes == &equal || sizes == &spread) EXPECT_GT(covered, 0.5 * R * R);
  }
  // Equal squares where the tolerances can close a row (ten 20-texel
  // squares drawn 19 high need 20.4 texels each of 224, with their 2-texel
  // gutters; eleven would not fit): every row ends at the texture's edge.
  {
    const int R2 = 224;
    std::vector<diffuv::internal::Shelf_slot> slots;
    std::vector<std::array<double, 2>> squares(100, {20., 20.});
    ASSERT_TRUE(diffuv::internal::pack_shelves(R2, g, dt, at, squares, slots));
    std::map<int, int> row_end;
    for(const auto& p : slots) row_end[p.y] = std::max(row_end[p.y], p.x + p.width);
    ASSERT_GT(row_end.size(), 1u);
    for(const auto& [y, end] : row_end) EXPECT_EQ(end, R2) << "row at " << y;
  }
  // A chart wider than the texture, or rows taller than it: no packing.
  std::vector<diffuv::internal::Shelf_slot> slots;
  EXPECT_FALSE(diffuv::internal::pack_shelves(R, g, dt, at, {{300., 10.}}, slots));
  EXPECT_FALSE(diffuv::internal::pack_shelves(R, g, dt, at, std::vector<std::array<double, 2>>(40, {200., 200.}), slots));
  EXPECT_TRUE(diffuv::internal::pack_shelves(R, g, dt, at, {}, slots));
  EXPECT_TRUE(slots.empty());
}

// Tolerances out of range are refused with a message; the smallest
// textures pack or are refused.
TEST(PackCharts, ShelvesRefuseBadTolerances)
{
  const Mesh& cow = cgal_mesh("cow.off");
  const Mapped mapped = map_default(cow);
  for(double bad : {-0.1, 1., std::numeric_limits<double>::quiet_NaN()}) {
    diffuv::Chart_packing_options o;
    o.density_tolerance = bad;
    EXPECT_THROW(diffuv::pack_charts(*mapped.atlas, cow.points(), o), std::invalid_argument) << bad;
    o = diffuv::Chart_packing_options();
    o.aspect_tolerance = bad < 1. ? bad : 1.5;
    EXPECT_THROW(diffuv::pack_charts(*mapped.atlas, cow.points(), o), std::invalid_argument) << bad;
  }
  diffuv::Chart_packing_options o;
  o.aspect_tolerance = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(diffuv::pack_charts(*mapped.atlas, cow.points(), o), std::invalid_argument);
  // Without gutters, and at a texture too small for cow's 291 charts with
  // them: a packing, or a clear refusal, quickly.
  o = diffuv::Chart_packing_options();
  o.gutter = 0;
  o.resolution = 32;
  const auto tight = diffuv::pack_charts(*mapped.atlas, cow.points(), o);
  EXPECT_GT(tight.coverage, 0.);
  o.gutter = 1;
  o.resolution = 16;
  EXPECT_THROW(diffuv::pack_charts(*mapped.atlas, cow.points(), o), std::invalid_argument);
}

// Turning where it packs better never packs worse than not turning, and is
// still a packing without overlap.
TEST(PackCharts, TurningWhereItPacksBetter)
{
  for(const char* name : {"cow.off", "man.off"})
    for(const auto packer : {diffuv::Chart_packer::shelves, diffuv::Chart_packer::skyline}) {
      const Mesh& m = cgal_mesh(name);
      const Mapped mapped = map_default(m);
      diffuv::Chart_packing_options turning, fixed;
      turning.packer = fixed.packer = packer;
      fixed.rotate = false;
      const auto chosen = diffuv::pack_charts(*mapped.atlas, m.points(), turning);
      const auto unturned = diffuv::pack_charts(*mapped.atlas, m.points(), fixed);
      EXPECT_GE(chosen.coverage, unturned.coverage) << name;
      for(const auto& p : unturned.charts) EXPECT_FALSE(p.rotated);
      const std::vector<int> count = charts_per_texel(*mapped.atlas, chosen);
      EXPECT_EQ(*std::max_element(count.begin(), count.end()), 1) << name;
    }
}

// A larger texture gives a larger density, the same gutters a larger share;
// a resolution the gutters alone fill is refused with a message.
TEST(PackCharts, ResolutionAndGutter)
{
  const Mesh& cow = cgal_mesh("cow.off");
  const Mapped mapped = map_default(cow);
  diffuv::Chart_packing_options small, large, wide_gutter;
  small.resolution = 256;
  large.resolution = 2048;
  wide_gutter.resolution = 256;
  wide_gutter.gutter = 6;
  const auto a = diffuv::pack_charts(*mapped.atlas, cow.points(), small);
  const auto b = diffuv::pack_charts(*mapped.atlas, cow.points(), large);
  const auto c = diffuv::pack_charts(*mapped.atlas, cow.points(), wide_gutter);
  EXPECT_GT(b.texels_per_unit, 6 * a.texels_per_unit);
  EXPECT_GT(b.coverage, a.coverage);
  EXPECT_LT(c.coverage, a.coverage);
  diffuv::Chart_packing_options tiny;
  tiny.resolution = 16;
  EXPECT_THROW(diffuv::pack_charts(*mapped.atlas, cow.points(), tiny), std::invalid_argument);
  tiny.resolution = 0;
  EXPECT_THROW(diffuv::pack_charts(*mapped.atlas, cow.points(), tiny), std::invalid_argument);
}

} // namespace
