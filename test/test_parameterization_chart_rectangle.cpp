// Tests of the rectangles charts are drawn on (parameterization/chart_rectangle.h):
// the patch's own aspect, the aspect of least stretch, and the warps of u and v.
#include "test_layout_data.h"

TEST(QuadLayout, ChartsAreDrawnOnRectanglesOfTheirAspect)
{
  // A flat 2 x 1 rectangle (a 21 x 11 grid scaled) mapped with its four
  // corners: its chart is drawn on (1, 1/2), where the map is an isometry up
  // to scale (angle distortion 1), and on the unit square is not.
  std::vector<double> xs, ys;
  for(int i = 0; i <= 20; ++i) xs.push_back(0.1 * i);
  for(int j = 0; j <= 10; ++j) ys.push_back(0.1 * j);
  const Mesh rectangle = make_grid_at(xs, ys);
  diffuv::Uv_atlas<Mesh> atlas(rectangle);
  const std::vector<vertex_descriptor> corners = {grid_vertex(20, 0, 0), grid_vertex(20, 20, 0), grid_vertex(20, 20, 10),
                                                  grid_vertex(20, 0, 10)};
  ASSERT_TRUE(diffuv::parameterize_disc(rectangle, rectangle.points(), corners, atlas).ok());
  EXPECT_NEAR(atlas.chart(0).size[0], 1.0, 1e-12);
  EXPECT_NEAR(atlas.chart(0).size[1], 0.5, 1e-12);
  std::vector<face_descriptor> all(faces(rectangle).begin(), faces(rectangle).end());
  const auto drawn = diffuv::measure_distortion(rectangle, rectangle.points(), all, atlas.chart_texture_map(0));
  const auto square = diffuv::measure_distortion(rectangle, rectangle.points(), all, atlas.chart_uv_map(0));
  EXPECT_LT(drawn.angle_mean, 1.02);
  EXPECT_GT(square.angle_mean, 1.9);
  // The corner as seen from its one face (its halfedge() may be the border's).
  Mesh::Halfedge_index into = rectangle.null_halfedge();
  for(auto h : halfedges_around_target(rectangle.halfedge(grid_vertex(20, 20, 10)), rectangle))
    if(!rectangle.is_border(h)) into = h;
  ASSERT_NE(into, rectangle.null_halfedge());
  const auto corner = get(atlas.corner_texture_map(), into);
  EXPECT_NEAR(corner.x(), 1.0, 1e-12);
  EXPECT_NEAR(corner.y(), 0.5, 1e-12);
}


TEST(QuadLayout, ChartRectanglesHaveTheLeastStretchOfAnyAspect)
{
  // On cow's default atlas, each chart's rectangle is checked against the L2
  // stretch that measure_distortion() gives for other aspects: 10 % wider, 10 %
  // narrower, and the mean lengths of its opposite sides (the rule before);
  // none is lower. Over the whole atlas the chosen rectangles lower the L2.
  const Mesh& m = cgal_mesh("cow.off");
  const Seg seg = automatic_layout(m);
  diffuv::Uv_atlas<Mesh> atlas(m);
  diffuv::Patch_parameterization_options unwarped;
  unwarped.drawing.pieces = 0;  // the rectangles alone
  const auto results = diffuv::parameterize_patches(m, m.points(), seg, atlas, unwarped);
  diffuv::Distortion_summary chosen_total, sides_total;
  std::size_t checked = 0, differ = 0;
  for(const auto& r : results) {
    ASSERT_TRUE(r.status.ok());
    const auto& chart = atlas.chart(r.chart);
    const std::array<double, 2> chosen = chart.size;
    EXPECT_DOUBLE_EQ(std::max(chosen[0], chosen[1]), 1.0);
    auto l2_on = [&](double width, double height) {
      const auto uv = atlas.chart_uv_map(r.chart);
      auto scaled = boost::make_function_property_map<vertex_descriptor>([&](vertex_descriptor v) {
        const auto q = get(uv, v);
        return diffuv::Uv_atlas<Mesh>::Point_2(q.x() * width, q.y() * height);
      });
      return diffuv::measure_distortion(m, m.points(), chart.faces, scaled);
    };
    const auto at_chosen = l2_on(chosen[0], chosen[1]);
    EXPECT_NEAR(at_chosen.stretch_l2,
                diffuv::measure_distortion(m, m.points(), chart.faces, atlas.chart_texture_map(r.chart)).stretch_l2, 1e-12);
    EXPECT_LE(at_chosen.stretch_l2, l2_on(chosen[0] * 1.1, chosen[1]).stretch_l2 + 1e-12);
    EXPECT_LE(at_chosen.stretch_l2, l2_on(chosen[0] / 1.1, chosen[1]).stretch_l2 + 1e-12);
    const auto by_sides = diffuv::side_length_rectangle(r.sides, m.points());
    const auto at_sides = l2_on(by_sides[0], by_sides[1]);
    EXPECT_LE(at_chosen.stretch_l2, at_sides.stretch_l2 + 1e-12);
    differ += std::abs(chosen[0] / chosen[1] - by_sides[0] / by_sides[1]) > 0.05 * by_sides[0] / by_sides[1];
    chosen_total = diffuv::combined(chosen_total, at_chosen);
    sides_total = diffuv::combined(sides_total, at_sides);
    ++checked;
  }
  EXPECT_EQ(checked, seg.number_of_patches());
  EXPECT_GT(differ, checked / 10);  // the sides' rule is not what is chosen
  EXPECT_LT(chosen_total.stretch_l2, sides_total.stretch_l2);
}

namespace {

// A flat W x H rectangle as a grid whose chart is given by hand: u = sqrt(x / W)
// (the iso-lines of u crowd towards x = W), v = y / H. The warp f(u) = u^2
// would draw it without distortion.
struct Uneven_chart {
  std::unique_ptr<Mesh> mesh;  // on the heap: the atlas keeps a reference to it
  std::unique_ptr<diffuv::Uv_atlas<Mesh>> atlas;
};

Uneven_chart uneven_chart(double width, double height)
{
  Uneven_chart out;
  std::vector<double> xs, ys;
  for(int i = 0; i <= 24; ++i) xs.push_back(width * i / 24.);
  for(int j = 0; j <= 8; ++j) ys.push_back(height * j / 8.);
  out.mesh = std::make_unique<Mesh>(make_grid_at(xs, ys));
  const Mesh& m = *out.mesh;
  out.atlas = std::make_unique<diffuv::Uv_atlas<Mesh>>(m);
  std::vector<vertex_descriptor> vs(vertices(m).begin(), vertices(m).end());
  std::vector<diffuv::Uv_atlas<Mesh>::Point_2> uv;
  for(auto v : vs) uv.emplace_back(std::sqrt(m.point(v).x() / width), m.point(v).y() / height);
  std::vector<face_descriptor> fs(faces(m).begin(), faces(m).end());
  out.atlas->add_chart(fs, vs, uv);
  return out;
}

} // namespace

TEST(ChartDrawing, EnergyGradientMatchesFiniteDifferences)
{
  // The symmetric Dirichlet energy's gradient (knots' log widths of u and of
  // v, log aspect) against central differences at a point away from the
  // identity, on a chart that is not a product of its axes (cow's patches).
  const Uneven_chart flat = uneven_chart(2., 1.);
  const Mesh& m = cgal_mesh("cow.off");
  const Seg seg = automatic_layout(m);
  diffuv::Uv_atlas<Mesh> atlas(m);
  diffuv::Patch_parameterization_options unwarped;
  unwarped.drawing.pieces = 0;
  const auto results = diffuv::parameterize_patches(m, m.points(), seg, atlas, unwarped);
  std::size_t checked = 0;
  auto check = [&](const auto& a, std::size_t c, const auto& points) {
    const auto energy = diffuv::internal::chart_drawing_energy(a, c, points, 5);
    if(!energy) return;
    std::vector<double> z(energy->variables()), g, ignored;
    for(std::size_t i = 0; i < z.size(); ++i) z[i] = 0.15 * std::sin(1.7 * double(i) + 0.3);
    const double e = (*energy)(z, g);
    ASSERT_TRUE(std::isfinite(e));
    for(std::size_t i = 0; i < z.size(); ++i) {
      const double h = 1e-6;
      auto plus = z, minus = z;
      plus[i] += h;
      minus[i] -= h;
      const double numeric = ((*energy)(plus, ignored) - (*energy)(minus, ignored)) / (2 * h);
      EXPECT_NEAR(g[i], numeric, 1e-5 * std::max(1., std::abs(numeric))) << "chart " << c << ", variable " << i;
    }
    ++checked;
  };
  check(*flat.atlas, 0, flat.mesh->points());
  for(std::size_t p = 0; p < results.size() && checked < 6; p += 37)
    if(results[p].status) check(atlas, results[p].chart, m.points());
  EXPECT_GE(checked, 5u);
}

TEST(ChartDrawing, WarpUndoesUnevenSpacing)
{
  // u = sqrt(x / W) spreads the strip near x = 0 over much of the square and
  // squeezes the rest; the warp evens it out: L2 stretch and area distortion
  // fall to near 1, the aspect to W / H, and the warps increase from 0 to 1.
  const Uneven_chart flat = uneven_chart(2., 1.);
  const Mesh& mesh = *flat.mesh;
  const diffuv::Uv_atlas<Mesh>& atlas = *flat.atlas;
  std::vector<face_descriptor> all(faces(mesh).begin(), faces(mesh).end());
  const auto before = diffuv::measure_distortion(mesh, mesh.points(), all, atlas.chart_uv_map(0));
  const diffuv::Chart_drawing drawing = diffuv::fit_chart_drawing(atlas, 0, mesh.points(), {1., 1.});
  EXPECT_LT(drawing.energy_after, drawing.energy_before);
  EXPECT_GE(drawing.energy_after, 4. - 1e-9);  // 4: an isometry
  ASSERT_EQ(drawing.u.knots.size(), 7u);
  ASSERT_EQ(drawing.v.knots.size(), 7u);
  for(const auto* w : {&drawing.u, &drawing.v}) {
    EXPECT_EQ(w->knots.front(), 0.);
    EXPECT_EQ(w->knots.back(), 1.);
    for(std::size_t j = 0; j + 1 < w->knots.size(); ++j) EXPECT_LT(w->knots[j], w->knots[j + 1]);
  }
  EXPECT_TRUE(std::isnan(drawing.u(std::numeric_limits<double>::quiet_NaN())));
  EXPECT_EQ(drawing.u(-0.5), 0.);
  EXPECT_EQ(drawing.u(1.5), 1.);
  // f(u) near u^2 (a piecewise-linear fit of it), g near the identity.
  for(double t : {0.25, 0.5, 0.75}) {
    EXPECT_NEAR(drawing.u(t), t * t, 0.03) << t;
    EXPECT_NEAR(drawing.v(t), t, 0.01) << t;
  }
  EXPECT_NEAR(drawing.size[0], 1., 1e-12);
  EXPECT_NEAR(drawing.size[1], 0.5, 0.02);

  diffuv::Uv_atlas<Mesh>& writable = *flat.atlas;
  writable.set_chart_size(0, drawing.size[0], drawing.size[1]);
  writable.set_chart_warp(0, drawing.u, drawing.v);
  const auto after = diffuv::measure_distortion(mesh, mesh.points(), all, atlas.chart_texture_map(0));
  EXPECT_GT(before.stretch_l2, 1.3);
  EXPECT_LT(after.stretch_l2, 1.03);
  EXPECT_LT(after.area_mean, 1.06);
  EXPECT_EQ(after.flipped, 0u);
  EXPECT_EQ(after.degenerate, 0u);
  // The texture map is the warp then the rectangle, corner by corner.
  const auto corner = atlas.corner_texture_map();
  for(auto h : halfedges(mesh)) {
    if(mesh.is_border(h)) continue;
    const auto q = get(atlas.corner_uv_map(), h), t = get(corner, h);
    EXPECT_DOUBLE_EQ(t.x(), drawing.u(q.x()) * drawing.size[0]);
    EXPECT_DOUBLE_EQ(t.y(), drawing.v(q.y()) * drawing.size[1]);
  }
}

TEST(ChartDrawing, CowsChartsStayOneToOneOnTheirRectanglesAndStretchLess)
{
  // Cow's default atlas, drawn with and without the warps: every chart stays
  // one-to-one, its border stays on its rectangle's border (a vertex at u = 0
  // drawn at 0, at u = 1 drawn at the width), and the L2 stretch and the area
  // distortion over the atlas both fall.
  const Mesh& m = cgal_mesh("cow.off");
  const Seg seg = automatic_layout(m);
  diffuv::Uv_atlas<Mesh> plain(m), warped(m);
  diffuv::Patch_parameterization_options unwarped;
  unwarped.drawing.pieces = 0;
  const auto plain_results = diffuv::parameterize_patches(m, m.points(), seg, plain, unwarped);
  const auto results = diffuv::parameterize_patches(m, m.points(), seg, warped);
  diffuv::Distortion_summary plain_total, warped_total;
  std::size_t charts_warped = 0;
  for(std::size_t p = 0; p < results.size(); ++p) {
    ASSERT_TRUE(results[p].status.ok());
    const auto& chart = warped.chart(results[p].chart);
    const auto d = diffuv::measure_distortion(m, m.points(), chart.faces, warped.chart_texture_map(results[p].chart));
    EXPECT_TRUE(d.injective()) << "patch " << p;
    warped_total = diffuv::combined(warped_total, d);
    plain_total = diffuv::combined(plain_total, diffuv::measure_distortion(m, m.points(), plain.chart(plain_results[p].chart).faces,
                                                                         plain.chart_texture_map(plain_results[p].chart)));
    charts_warped += !chart.warp[0].is_identity();
    const auto drawn = warped.chart_texture_map(results[p].chart);
    for(std::size_t i = 0; i < chart.vertices.size(); ++i) {
      const auto q = chart.uv[i];
      const auto t = get(drawn, chart.vertices[i]);
      if(q.x() == 0.) EXPECT_EQ(t.x(), 0.);
      if(q.x() == 1.) EXPECT_DOUBLE_EQ(t.x(), chart.size[0]);
      if(q.y() == 0.) EXPECT_EQ(t.y(), 0.);
      if(q.y() == 1.) EXPECT_DOUBLE_EQ(t.y(), chart.size[1]);
    }
  }
  EXPECT_GT(charts_warped, results.size() / 2);
  EXPECT_LT(warped_total.stretch_l2, 0.95 * plain_total.stretch_l2);
  EXPECT_LT(warped_total.area_mean, 0.95 * plain_total.area_mean);
}

TEST(ChartDrawing, SameDrawingsOnOneThreadAndOnMany)
{
  // The fits run in parallel over the charts: every chart's rectangle and
  // warps must not depend on the number of threads (nor race on the atlas's
  // look-ups, which the fits read).
  const Mesh& m = cgal_mesh("cow.off");
  const Seg seg = automatic_layout(m);
  diffuv::Uv_atlas<Mesh> one(m), many(m);
  diffuv::Patch_parameterization_options serial, parallel;
  serial.threads = 1;
  parallel.threads = 4;
  const auto a = diffuv::parameterize_patches(m, m.points(), seg, one, serial);
  const auto b = diffuv::parameterize_patches(m, m.points(), seg, many, parallel);
  ASSERT_EQ(a.size(), b.size());
  std::size_t warped = 0;
  for(std::size_t p = 0; p < a.size(); ++p) {
    ASSERT_TRUE(a[p].status.ok() && b[p].status.ok());
    const auto& x = one.chart(a[p].chart);
    const auto& y = many.chart(b[p].chart);
    EXPECT_EQ(x.size, y.size) << "patch " << p;
    EXPECT_EQ(x.warp[0].knots, y.warp[0].knots) << "patch " << p;
    EXPECT_EQ(x.warp[1].knots, y.warp[1].knots) << "patch " << p;
    warped += !x.warp[0].is_identity();
  }
  EXPECT_GT(warped, a.size() / 2);
}
