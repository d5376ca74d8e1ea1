// Tests of the rectangles charts are drawn on (parameterization/chart_rectangle.h):
// the patch's own aspect, and the aspect of least stretch.
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
  const auto results = diffuv::parameterize_patches(m, m.points(), seg, atlas);
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
