// Tests of diffuv/render/render_mesh.h: known scenes with analytic pixel
// expectations (fit, shading, z-buffer, isolines, camera handedness), the
// colour ramps, and the PNG writer read back with stb_image.
#include <diffuv/render/render_mesh.h>
#include <diffuv/render/texture_layout.h>

#include "test_data.h"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wsign-compare"
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#include <stb/stb_image.h>
#pragma GCC diagnostic pop

#include <gtest/gtest.h>

#include <unistd.h>

#include <boost/property_map/function_property_map.hpp>

#include <filesystem>
#include <limits>
#include <set>
#include <tuple>

namespace {

using diffuv_test::Mesh;
using diffuv_test::Point_2;
using diffuv_test::Point_3;
using diffuv::Color;

const Color red{255, 0, 0}, blue{0, 0, 255}, white{255, 255, 255};

/// Corner uv = (x, y) of the corner's vertex.
auto xy_uv(const Mesh& m)
{
  return boost::make_function_property_map<Mesh::Halfedge_index>(
      [&m](Mesh::Halfedge_index h) { const Point_3& p = m.point(m.target(h)); return Point_2(p.x(), p.y()); });
}

/// Corner uv = (NaN, NaN) everywhere.
auto nan_uv()
{
  return boost::make_function_property_map<Mesh::Halfedge_index>([](Mesh::Halfedge_index) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    return Point_2(nan, nan);
  });
}

auto uniform(Color c) { return [c](Mesh::Face_index) { return c; }; }

diffuv::Render_options front(int isolines = 0)
{
  diffuv::Render_options o;
  o.view = diffuv::View::front;
  o.isolines = isolines;
  return o;
}

// Adds the square [x0, x0+1] x [y0, y0+1] at height z (two faces, normal +z).
void add_square(Mesh& m, double x0, double y0, double z)
{
  auto a = m.add_vertex(Point_3(x0, y0, z)), b = m.add_vertex(Point_3(x0 + 1, y0, z));
  auto c = m.add_vertex(Point_3(x0 + 1, y0 + 1, z)), d = m.add_vertex(Point_3(x0, y0 + 1, z));
  m.add_face(a, b, c);
  m.add_face(a, c, d);
}

// 800 x 600, margin 5%: the unit square maps to x in [130, 670], y in [30, 570] (scale 540).
TEST(Render, FlatSquareFacingTheCamera)
{
  const Mesh m = diffuv_test::make_grid(1, 1);
  const diffuv::Image img = diffuv::render_mesh(m, m.points(), uniform(red), front());
  ASSERT_EQ(img.width, 800);
  ASSERT_EQ(img.height, 600);
  ASSERT_EQ(img.rgb.size(), 800u * 600u * 3u);
  EXPECT_EQ(img.at(400, 300), red); // facing the headlight: full colour
  EXPECT_EQ(img.at(0, 0), white);
  EXPECT_EQ(img.at(799, 599), white);
  // The fit: inside just within the square's image, background just outside.
  EXPECT_EQ(img.at(131, 300), red);
  EXPECT_EQ(img.at(668, 300), red);
  EXPECT_EQ(img.at(400, 31), red);
  EXPECT_EQ(img.at(400, 568), red);
  EXPECT_EQ(img.at(128, 300), white);
  EXPECT_EQ(img.at(671, 300), white);
  EXPECT_EQ(img.at(400, 28), white);
  EXPECT_EQ(img.at(400, 571), white);
}

TEST(Render, TiltedFaceIsDarkerButTheSameHue)
{
  const Mesh m = diffuv_test::make_grid(1, 1);
  diffuv::Render_options o = front();
  o.use_angles = true;
  o.azimuth = 60; // cos 60 = 0.5: 0.25 + 0.75 * 0.5 = 0.625 of the colour
  o.elevation = 0;
  const diffuv::Image img = diffuv::render_mesh(m, m.points(), uniform(red), o);
  const Color c = img.at(400, 300);
  EXPECT_NEAR(int(c.r), 159, 1);
  EXPECT_EQ(int(c.g), 0);
  EXPECT_EQ(int(c.b), 0);
  // Two-sided: from behind the same shade.
  o.azimuth = 180 + 60;
  EXPECT_EQ(diffuv::render_mesh(m, m.points(), uniform(red), o).at(400, 300), c);
}

TEST(Render, EdgeOnSquareDrawsNothing)
{
  const Mesh m = diffuv_test::make_grid(2, 2);
  diffuv::Render_options o = front();
  o.view = diffuv::View::right;
  const diffuv::Image img = diffuv::render_mesh(m, m.points(), uniform(red), o);
  for(int y = 0; y < img.height; y += 7)
    for(int x = 0; x < img.width; x += 7) ASSERT_EQ(img.at(x, y), white) << x << ' ' << y;
}

// Left half red, right half blue; back view mirrors it, top view keeps +x on the right.
TEST(Render, CameraHandedness)
{
  Mesh m;
  add_square(m, 0, 0, 0);  // faces 0, 1: red
  add_square(m, 1, 0, 0);  // faces 2, 3: blue
  auto color = [](Mesh::Face_index f) { return std::size_t(f) < 2 ? red : blue; };
  diffuv::Render_options o = front();
  diffuv::Image img = diffuv::render_mesh(m, m.points(), color, o);
  EXPECT_EQ(img.at(250, 300), red);
  EXPECT_EQ(img.at(550, 300), blue);
  o.view = diffuv::View::back;
  img = diffuv::render_mesh(m, m.points(), color, o);
  EXPECT_EQ(img.at(250, 300), blue);
  EXPECT_EQ(img.at(550, 300), red);
  // Top: the squares are edge-on (flat in z = 0)... so stand them up along z.
  Mesh t;
  auto a = t.add_vertex(Point_3(0, 0, 0)), b = t.add_vertex(Point_3(1, 0, 0));
  auto c = t.add_vertex(Point_3(1, 0, -1)), d = t.add_vertex(Point_3(0, 0, -1));
  t.add_face(a, b, c);
  t.add_face(a, c, d);
  auto e = t.add_vertex(Point_3(2, 0, 0)), f = t.add_vertex(Point_3(2, 0, -1));
  t.add_face(b, e, f);
  t.add_face(b, f, c);
  o.view = diffuv::View::top;
  img = diffuv::render_mesh(t, t.points(), color, o);
  EXPECT_EQ(img.at(250, 300), red);
  EXPECT_EQ(img.at(550, 300), blue);
}

TEST(Render, AMeshWithAnotherUpAxisIsTurnedUpright)
{
  // Rendering a mesh with its up axis z (or x) gives the very picture of the
  // mesh turned so that this axis is y, from every view; the turn is a
  // rotation, so lighting and face orientation agree too.
  const Mesh& man = diffuv_test::cgal_mesh("man.off");
  Mesh turned_z = man, turned_x = man;
  for(auto v : vertices(man)) {
    const Point_3& p = man.point(v);
    turned_z.point(v) = Point_3(p.x(), p.z(), -p.y());
    turned_x.point(v) = Point_3(-p.y(), p.x(), p.z());
  }
  auto color = [](Mesh::Face_index f) { return diffuv::patch_color(std::size_t(f) % 7); };
  for(diffuv::View view : {diffuv::View::front, diffuv::View::iso, diffuv::View::top}) {
    diffuv::Render_options o;
    o.view = view;
    o.width = 200;
    o.height = 150;
    const diffuv::Image upright = diffuv::render_mesh(turned_z, turned_z.points(), color, o);
    o.up = diffuv::Up_axis::z;
    const diffuv::Image z_up = diffuv::render_mesh(man, man.points(), color, o);
    EXPECT_EQ(z_up.rgb, upright.rgb) << "view " << int(view);
    o.up = diffuv::Up_axis::x;
    const diffuv::Image x_up = diffuv::render_mesh(man, man.points(), color, o);
    o.up = diffuv::Up_axis::y;
    EXPECT_EQ(x_up.rgb, diffuv::render_mesh(turned_x, turned_x.points(), color, o).rgb) << "view " << int(view);
  }
  // man is modelled z-up (3.4 times taller along z than deep along y); cow
  // and pig y-up (pig lies long along z: 2.1 times its height).
  EXPECT_EQ(diffuv::guess_up_axis(man, man.points()), diffuv::Up_axis::z);
  const Mesh& pig = diffuv_test::cgal_mesh("pig.off");
  EXPECT_EQ(diffuv::guess_up_axis(pig, pig.points()), diffuv::Up_axis::y);
  const Mesh& cow = diffuv_test::cgal_mesh("cow.off");
  EXPECT_EQ(diffuv::guess_up_axis(cow, cow.points()), diffuv::Up_axis::y);
  EXPECT_EQ(diffuv::guess_up_axis(turned_z, turned_z.points()), diffuv::Up_axis::y);
  // Upright, man's picture from the front is taller than wide; lying on his back, wider.
  auto extent = [](const diffuv::Image& img) {
    int x0 = img.width, x1 = -1, y0 = img.height, y1 = -1;
    for(int y = 0; y < img.height; ++y)
      for(int x = 0; x < img.width; ++x)
        if(!(img.at(x, y) == white)) {
          x0 = std::min(x0, x);
          x1 = std::max(x1, x);
          y0 = std::min(y0, y);
          y1 = std::max(y1, y);
        }
    return std::make_pair(x1 - x0, y1 - y0);
  };
  diffuv::Render_options o = front();
  o.width = o.height = 300;
  const auto lying = extent(diffuv::render_mesh(man, man.points(), color, o));
  o.up = diffuv::Up_axis::z;
  const auto standing = extent(diffuv::render_mesh(man, man.points(), color, o));
  EXPECT_GT(standing.second, 2 * standing.first);
  EXPECT_LT(lying.second, standing.second);
}

TEST(Render, TextureLayoutDrawsEachChartWhereItsTextureCoordinatesPutIt)
{
  // The unit square, its uv = (x, y), placed in the texture at [0.25, 0.75]
  // x [0.5, 0.75] (half as tall as wide): at 64 x 64 texels it covers columns
  // 16..47 and rows 16..31 (the image's rows go down from v = 1).
  Mesh m;
  add_square(m, 0, 0, 0);
  const auto texture = boost::make_function_property_map<Mesh::Halfedge_index>([&m](Mesh::Halfedge_index h) {
    const Point_3& p = m.point(m.target(h));
    return Point_2(0.25 + 0.5 * p.x(), 0.5 + 0.25 * p.y());
  });
  diffuv::Texture_layout_options o;
  o.size = 64;
  o.isolines = 0;
  const diffuv::Image plain = diffuv::render_texture_layout(m, texture, uniform(red), xy_uv(m), o);
  for(int y = 0; y < 64; ++y)
    for(int x = 0; x < 64; ++x) {
      const bool inside = x >= 16 && x < 48 && y >= 16 && y < 32;
      EXPECT_EQ(plain.at(x, y), inside ? red : o.background) << x << ", " << y;
    }
  // Isolines every 1/2 of the chart's own (u,v): u = 1/2 falls between columns 31 and 32.
  o.isolines = 2;
  const diffuv::Image lined = diffuv::render_texture_layout(m, texture, uniform(red), xy_uv(m), o);
  EXPECT_EQ(lined.at(31, 20), o.u_line_color);
  EXPECT_EQ(lined.at(20, 24), o.v_line_color);  // v = 1/2: texture v = 0.625, row 24
  EXPECT_EQ(lined.at(20, 20), red);
  EXPECT_EQ(lined.at(5, 5), o.background);
  // No uv: the chart without lines; no texture point: nothing.
  EXPECT_EQ(diffuv::render_texture_layout(m, texture, uniform(red), nan_uv(), o).at(31, 20), red);
  EXPECT_EQ(diffuv::render_texture_layout(m, nan_uv(), uniform(red), xy_uv(m), o).at(31, 20), o.background);
  o.size = 0;
  EXPECT_THROW(diffuv::render_texture_layout(m, texture, uniform(red), xy_uv(m), o), std::invalid_argument);
}

TEST(Render, ZBufferKeepsTheNearestFaceWhateverTheOrder)
{
  for(bool red_first : {true, false}) {
    Mesh m;
    // Red at z = 0 and blue at z = 0.5, overlapping on [0.5, 1] x [0, 1].
    if(red_first) { add_square(m, 0, 0, 0); add_square(m, 0.5, 0, 0.5); }
    else { add_square(m, 0.5, 0, 0.5); add_square(m, 0, 0, 0); }
    auto color = [red_first](Mesh::Face_index f) { return (std::size_t(f) < 2) == red_first ? red : blue; };
    // x in [0, 1.5]: scale 480 (width bound 720 / 1.5), centre 0.75 at pixel 400.
    diffuv::Image img = diffuv::render_mesh(m, m.points(), color, front());
    EXPECT_EQ(img.at(400 - 240, 300), red) << red_first;   // x = 0.25: red only
    EXPECT_EQ(img.at(400, 300), blue) << red_first;        // x = 0.75: both, blue nearer
    EXPECT_EQ(img.at(400 + 240, 300), blue) << red_first;  // x = 1.25: blue only
    diffuv::Render_options o = front();
    o.view = diffuv::View::back; // now red is nearer; x = 0.75 is still the centre
    img = diffuv::render_mesh(m, m.points(), color, o);
    EXPECT_EQ(img.at(400, 300), red) << red_first;
  }
}

int count_in_row(const diffuv::Image& img, int y, int x0, int x1, Color c)
{
  int n = 0;
  for(int x = x0; x <= x1; ++x) n += img.at(x, y) == c;
  return n;
}

TEST(Render, IsolinesOnTheUnitSquare)
{
  const Mesh m = diffuv_test::make_grid(4, 4);
  const diffuv::Render_options o = front(2);
  const diffuv::Image img = diffuv::render_mesh(m, m.points(), uniform(red), xy_uv(m), o);
  // u = 0.5 at pixel x = 400, u = 0.25 at x = 265; v = 0.5 at y = 300, v = 0.25 at y = 435.
  for(int y : {100, 200, 350, 435, 500}) {
    EXPECT_GE(count_in_row(img, y, 398, 402, o.u_line_color), 1) << y;
    EXPECT_EQ(count_in_row(img, y, 255, 275, o.u_line_color), 0) << y;
    EXPECT_EQ(img.at(265, y), red) << y;
  }
  for(int x : {200, 265, 500, 600}) {
    int n = 0;
    for(int y = 298; y <= 302; ++y) n += img.at(x, y) == o.v_line_color;
    EXPECT_GE(n, 1) << x;
    EXPECT_EQ(img.at(x, 435), red) << x;
  }
  // u = 0 and u = 1 lie on the border of the square.
  EXPECT_GE(count_in_row(img, 200, 129, 131, o.u_line_color), 1);
  EXPECT_GE(count_in_row(img, 200, 669, 671, o.u_line_color), 1);
  // No isolines without isolines.
  const diffuv::Image none = diffuv::render_mesh(m, m.points(), uniform(red), xy_uv(m), front(0));
  EXPECT_EQ(count_in_row(none, 200, 130, 670, o.u_line_color), 0);
  // Lines 270 pixels apart (the square is 540 wide, lines every 1/2): drawn
  // with a minimum spacing of 200 pixels, left out with 300.
  diffuv::Render_options spaced = o;
  spaced.min_line_spacing = 200;
  const diffuv::Image kept = diffuv::render_mesh(m, m.points(), uniform(red), xy_uv(m), spaced);
  EXPECT_GE(count_in_row(kept, 200, 398, 402, o.u_line_color), 1);
  spaced.min_line_spacing = 300;
  const diffuv::Image dropped = diffuv::render_mesh(m, m.points(), uniform(red), xy_uv(m), spaced);
  EXPECT_EQ(count_in_row(dropped, 200, 130, 670, o.u_line_color), 0);
  EXPECT_EQ(count_in_row(dropped, 300, 130, 670, o.v_line_color), 0);
  EXPECT_EQ(dropped.at(400, 200), red);
}

// With a texture, a face takes the texture's colour at its (u,v), filtered
// bilinearly: a 2 x 2 texture (red, blue over green, white) on the unit
// square seen from the front, (u,v) = (x,y); no isolines drawn over it.
TEST(Render, TextureIsReadAtTheCornersUv)
{
  const Mesh m = diffuv_test::make_grid(4, 4);
  diffuv::Image texture(2, 2);
  texture.set(0, 0, red);   // top left: v = 1
  texture.set(1, 0, blue);
  texture.set(0, 1, Color{0, 255, 0});
  texture.set(1, 1, white);
  diffuv::Render_options o = front(4);
  o.texture = &texture;
  const diffuv::Image img = diffuv::render_mesh(m, m.points(), uniform(Color{9, 9, 9}), xy_uv(m), o);
  // The square spans x in [130, 670] and y in [30, 570]; texel centres are at
  // u, v = 1/4 and 3/4, and outside them the edge texels are clamped (u, v = 0.15 and 0.85 here).
  EXPECT_EQ(img.at(211, 111), red);
  EXPECT_EQ(img.at(589, 111), blue);
  EXPECT_EQ(img.at(211, 489), (Color{0, 255, 0}));
  EXPECT_EQ(img.at(589, 489), white);
  // Halfway between red and blue, at the top: their mean.
  const Color middle = img.at(400, 111);
  EXPECT_NEAR(middle.r, 128, 2);
  EXPECT_EQ(middle.g, 0);
  EXPECT_NEAR(middle.b, 128, 2);
  // Without (u,v) the face colour stays.
  const diffuv::Image plain = diffuv::render_mesh(m, m.points(), uniform(Color{9, 9, 9}), nan_uv(), o);
  EXPECT_EQ(plain.at(211, 111), (Color{9, 9, 9}));
}

TEST(Render, IsolineWidthIsInScreenPixels)
{
  const Mesh m = diffuv_test::make_grid(3, 3);
  for(double width : {1.0, 3.0, 6.0})
    for(int size : {300, 800}) {
      diffuv::Render_options o = front(2);
      o.line_width = width;
      o.width = size;
      o.height = size * 3 / 4;
      const diffuv::Image img = diffuv::render_mesh(m, m.points(), uniform(red), xy_uv(m), o);
      // Row a quarter of the way down (v = 0.75, away from v lines), columns around u = 0.5.
      const int y = o.height / 4 + 3, cx = size / 2;
      const int n = count_in_row(img, y, cx - 20, cx + 20, o.u_line_color);
      EXPECT_GE(n, int(width) - 1) << width << ' ' << size;
      EXPECT_LE(n, int(width) + 1) << width << ' ' << size;
      EXPECT_GE(n, 1) << width << ' ' << size;
    }
}

TEST(Render, NoIsolinesWhereUvIsNaN)
{
  const Mesh m = diffuv_test::make_grid(4, 4);
  const diffuv::Render_options o = front(2);
  const diffuv::Image img = diffuv::render_mesh(m, m.points(), uniform(red), nan_uv(), o);
  int lines = 0, reds = 0;
  for(int y = 0; y < img.height; y += 2)
    for(int x = 0; x < img.width; ++x) {
      const Color c = img.at(x, y);
      lines += c == o.u_line_color || c == o.v_line_color;
      reds += c == red;
    }
  EXPECT_EQ(lines, 0);
  EXPECT_GT(reds, 1000);
  // Same without a uv map at all (the 4-argument overload).
  const diffuv::Image plain = diffuv::render_mesh(m, m.points(), uniform(red), o);
  EXPECT_EQ(plain.rgb, img.rgb);
}

TEST(Render, InvalidOptionsThrow)
{
  const Mesh m = diffuv_test::make_grid(1, 1);
  diffuv::Render_options o;
  o.width = 0;
  EXPECT_THROW(diffuv::render_mesh(m, m.points(), uniform(red), o), std::invalid_argument);
  o = {};
  o.isolines = -1;
  EXPECT_THROW(diffuv::render_mesh(m, m.points(), uniform(red), xy_uv(m), o), std::invalid_argument);
  diffuv::Image img(4, 3);
  EXPECT_THROW(img.at(4, 0), std::out_of_range);
  EXPECT_THROW(img.set(0, -1, red), std::out_of_range);
}

TEST(Render, HeatColorRamp)
{
  EXPECT_NE(diffuv::heat_color(0), diffuv::heat_color(1));
  int previous = -1;
  for(int i = 0; i <= 40; ++i) {
    const Color c = diffuv::heat_color(i / 40.);
    EXPECT_GT(int(c.g), previous) << i; // green strictly increases along the ramp
    previous = c.g;
  }
  EXPECT_EQ(diffuv::heat_color(-3), diffuv::heat_color(0));
  EXPECT_EQ(diffuv::heat_color(7), diffuv::heat_color(1));
  EXPECT_EQ(diffuv::heat_color(0), (Color{68, 1, 84}));
  EXPECT_EQ(diffuv::heat_color(1), (Color{253, 231, 37}));
}

TEST(Render, PatchColorsAreDistinctAndDeterministic)
{
  std::set<std::tuple<int, int, int>> seen;
  for(std::size_t i = 0; i < 64; ++i) {
    const Color c = diffuv::patch_color(i);
    EXPECT_TRUE(seen.emplace(c.r, c.g, c.b).second) << "patch " << i << " repeats " << c;
    EXPECT_EQ(diffuv::patch_color(i), c);
  }
}

TEST(Render, ColorBarAtTheRightEdge)
{
  diffuv::Image img(400, 300);
  diffuv::draw_color_bar(img, 0.0, 2.5, "distortion");
  // Bar: columns [386, 396), rows [45, 255): top = max colour, bottom = min colour.
  EXPECT_EQ(img.at(390, 45), diffuv::heat_color(1));
  EXPECT_EQ(img.at(390, 254), diffuv::heat_color(0));
  EXPECT_EQ(img.at(390, 150), diffuv::heat_color(104. / 209.));
  EXPECT_EQ(img.at(385, 150), (Color{0, 0, 0})); // frame
  EXPECT_EQ(img.at(100, 150), white);            // the rest untouched
  EXPECT_EQ(img.at(390, 10), white);
  int dark = 0; // some text left of the bar (the values)
  for(int y = 40; y < 60; ++y)
    for(int x = 330; x < 384; ++x) dark += img.at(x, y) == Color{0, 0, 0};
  EXPECT_GT(dark, 5);
  // A tiny image is clipped, not overrun.
  diffuv::Image tiny(5, 5);
  EXPECT_NO_THROW(diffuv::draw_color_bar(tiny, 0, 1, "a long label that does not fit"));
}

std::string temp_dir()
{
  const auto dir = std::filesystem::temp_directory_path() / ("diffuv_render_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  return dir.string();
}

TEST(Render, WritePngReadsBackTheSamePixels)
{
  const Mesh m = diffuv_test::make_grid(4, 4);
  diffuv::Render_options o = front(4);
  o.width = 97; // odd sizes: no hidden padding assumption
  o.height = 61;
  diffuv::Image img = diffuv::render_mesh(m, m.points(), [](Mesh::Face_index f) { return diffuv::patch_color(f); },
                                          xy_uv(m), o);
  diffuv::draw_color_bar(img, 0, 1);
  const std::string path = temp_dir() + "/square.png";
  diffuv::write_png(path, img);
  int w = 0, h = 0, n = 0;
  unsigned char* data = stbi_load(path.c_str(), &w, &h, &n, 3);
  ASSERT_NE(data, nullptr);
  EXPECT_EQ(w, 97);
  EXPECT_EQ(h, 61);
  const std::vector<unsigned char> back(data, data + std::size_t(w) * h * 3);
  stbi_image_free(data);
  EXPECT_EQ(back, img.rgb);
  // No temporary file left next to it.
  int files = 0;
  for(const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(path).parent_path()))
    files += entry.path().filename() != "square.png";
  EXPECT_EQ(files, 0);
  std::filesystem::remove_all(std::filesystem::path(path).parent_path());
}

TEST(Render, WritePngFailuresThrowOutputError)
{
  diffuv::Image img(8, 8);
  const std::string missing = temp_dir() + "/no/such/folder/x.png";
  EXPECT_THROW(diffuv::write_png(missing, img), diffuv::Output_error);
  EXPECT_FALSE(std::filesystem::exists(missing));
  EXPECT_THROW(diffuv::write_png(temp_dir() + "/empty.png", diffuv::Image()), diffuv::Output_error);
  std::filesystem::remove_all(temp_dir());
}

} // namespace
