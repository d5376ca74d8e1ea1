// Tests of bake_texture() (render/bake_texture.h): per-vertex colours, normals
// and another mesh's colours baked into cow's packed texture, read back the
// way a renderer reads a texture (bilinear filtering).
#include "test_data.h"

#include <diffuv/layout/disc_patches.h>
#include <diffuv/parameterization/parameterize_patches.h>
#include <diffuv/render/bake_texture.h>
#include <diffuv/render/pack_charts.h>

#include <CGAL/Polygon_mesh_processing/compute_normal.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <vector>

namespace {

using namespace diffuv_test;
using Bake_atlas = diffuv::Uv_atlas<Mesh>;

// A mesh's default patches, mapped and packed into `size`^2 texels.
struct Packed_mesh {
  std::unique_ptr<Bake_atlas> atlas;
  diffuv::Chart_packing packing;
};

Packed_mesh pack_default(const Mesh& m, int size)
{
  Packed_mesh out;
  diffuv::Segmentation<Mesh> seg;
  EXPECT_TRUE(diffuv::disc_patches(m, m.points(), {}, seg).ok());
  out.atlas = std::make_unique<Bake_atlas>(m);
  diffuv::parameterize_patches(m, m.points(), seg, *out.atlas);
  out.packing = diffuv::pack_charts(*out.atlas, m.points(), diffuv::Chart_packing_options{size, 2});
  return out;
}

// A smooth colour field: each channel a linear function of the position
// across the mesh's bounding box (what `diffuv correspond` paints an unpainted B with).
std::vector<diffuv::Rgb> position_rgb(const Mesh& m)
{
  CGAL::Bbox_3 box;
  for(auto v : m.vertices()) box += m.point(v).bbox();
  std::vector<diffuv::Rgb> colors(m.number_of_vertices());
  for(auto v : m.vertices()) {
    const auto& p = m.point(v);
    // Whole bytes, so that a colour read back can equal the vertex's exactly.
    auto channel = [](double t) { return std::round(255. * t) / 255.; };
    colors[v.idx()] = {channel((p.x() - box.xmin()) / (box.xmax() - box.xmin())),
                       channel((p.y() - box.ymin()) / (box.ymax() - box.ymin())),
                       channel((p.z() - box.zmin()) / (box.zmax() - box.zmin()))};
  }
  return colors;
}

double channel_error(const diffuv::Rgb& a, const diffuv::Rgb& b)
{
  return std::max({std::abs(a[0] - b[0]), std::abs(a[1] - b[1]), std::abs(a[2] - b[2])});
}

// How many vertices read back their colour within 1/255 at each of their
// texture points (one per chart they are in), over all vertices and over
// those the texture resolves: no other vertex's texture point within 2
// texels (Chebyshev) of theirs, so that no texel lies in both their bilinear
// footprints. Crowded vertices are where a chart is squeezed (#18's area
// distortion): no texel can hold two vertices' colours.
struct Read_back {
  double all = 0., resolved = 0.;
  std::size_t crowded = 0;
};

template <class CornerMap>
Read_back vertices_read_back(const Mesh& m, CornerMap corner, const diffuv::Image& image,
                             const std::vector<diffuv::Rgb>& colors)
{
  const double S = image.width;
  std::vector<char> used(m.number_of_vertices(), 0), wrong(m.number_of_vertices(), 0), crowded(m.number_of_vertices(), 0);
  std::vector<std::pair<std::array<double, 2>, std::size_t>> points;  // texel position, vertex
  for(auto f : m.faces())
    for(auto h : CGAL::halfedges_around_face(m.halfedge(f), m)) {
      const auto t = get(corner, h);
      if(!std::isfinite(t.x())) continue;
      const std::size_t v = m.target(h).idx();
      used[v] = 1;
      points.push_back({{t.x() * S, t.y() * S}, v});
      if(channel_error(diffuv::sample_bilinear(image, t.x(), t.y()), colors[v]) > 1. / 255 + 1e-9) wrong[v] = 1;
    }
  // Crowded: sorted by x, each point against those less than 2 texels to its right.
  std::sort(points.begin(), points.end());
  for(std::size_t i = 0; i < points.size(); ++i)
    for(std::size_t j = i + 1; j < points.size() && points[j].first[0] - points[i].first[0] < 2.; ++j)
      if(points[j].second != points[i].second && std::abs(points[j].first[1] - points[i].first[1]) < 2.)
        crowded[points[i].second] = crowded[points[j].second] = 1;
  std::size_t n = 0, good = 0, resolved = 0, resolved_good = 0;
  Read_back out;
  for(std::size_t v = 0; v < used.size(); ++v) {
    if(!used[v]) continue;
    ++n;
    good += wrong[v] ? 0 : 1;
    if(crowded[v]) {
      ++out.crowded;
      continue;
    }
    ++resolved;
    resolved_good += wrong[v] ? 0 : 1;
  }
  out.all = n ? double(good) / double(n) : 0.;
  out.resolved = resolved ? double(resolved_good) / double(resolved) : 0.;
  return out;
}

// Issue #22's target: baked vertex colours read back at each vertex's
// texture point within 1/255. Every vertex the texture resolves does, thanks
// to the four texels around each vertex (without them, those texels hold the
// colour of points up to 0.7 texels away, across faces of different slopes).
TEST(BakeTexture, VertexColoursReadBackAtTheVertices)
{
  const Mesh& cow = cgal_mesh("cow.off");
  const Packed_mesh packed = pack_default(cow, 1024);
  const std::vector<diffuv::Rgb> colors = position_rgb(cow);
  const auto corner = diffuv::packed_corner_map(*packed.atlas, packed.packing);
  const auto sampler = diffuv::vertex_value_sampler(
      cow, boost::make_iterator_property_map(colors.begin(), get(boost::vertex_index, cow)));
  const diffuv::Baked_texture baked = diffuv::bake_texture(cow, corner, sampler);
  ASSERT_EQ(baked.image.width, 1024);
  ASSERT_EQ(baked.source.size(), 1024u * 1024u);
  EXPECT_GT(baked.face_texels, 1024u * 1024u / 2);
  EXPECT_GT(baked.vertex_texels, cow.number_of_vertices());
  const Read_back with_pins = vertices_read_back(cow, corner, baked.image, colors);
  // Every vertex the texture resolves reads back; 89 % of all, 22 % crowded (measured 2026-12-06).
  EXPECT_EQ(with_pins.resolved, 1.);
  EXPECT_GT(with_pins.all, 0.85);
  EXPECT_LT(with_pins.crowded, cow.number_of_vertices() / 4);

  diffuv::Bake_options plain;
  plain.pin_vertices = false;
  const diffuv::Baked_texture unpinned = diffuv::bake_texture(cow, corner, sampler, plain);
  EXPECT_EQ(unpinned.vertex_texels, 0u);
  const Read_back without_pins = vertices_read_back(cow, corner, unpinned.image, colors);
  EXPECT_LT(without_pins.resolved, 0.99);
  std::cout << "cow at 1024: vertices read back within 1/255: " << 100. * with_pins.all << " % of all, "
            << 100. * with_pins.resolved << " % of the " << cow.number_of_vertices() - with_pins.crowded
            << " the texture resolves (without the vertex texels: " << 100. * without_pins.all << " %, "
            << 100. * without_pins.resolved << " %)\n";

  // Inside the faces, a texel holds the colour of its centre's point.
  const diffuv::Image& image = baked.image;
  std::size_t checked = 0;
  for(auto f : cow.faces()) {
    auto h = cow.halfedge(f);
    std::array<Bake_atlas::Point_2, 3> t{get(corner, h), get(corner, cow.next(h)), get(corner, cow.next(cow.next(h)))};
    if(!std::isfinite(t[0].x())) continue;
    // The centroid's texel, when its centre is well inside the face (a texel from it).
    const double cx = (t[0].x() + t[1].x() + t[2].x()) / 3 * 1024, cy = (1. - (t[0].y() + t[1].y() + t[2].y()) / 3) * 1024;
    const int px = int(cx), py = int(cy);
    if(baked.source[std::size_t(py) * 1024 + px] != diffuv::Texel_source::face) continue;
    const double qx = (px + 0.5) / 1024, qy = 1. - (py + 0.5) / 1024;
    const double area = (t[1].x() - t[0].x()) * (t[2].y() - t[0].y()) - (t[2].x() - t[0].x()) * (t[1].y() - t[0].y());
    const double w0 = ((t[1].x() - qx) * (t[2].y() - qy) - (t[2].x() - qx) * (t[1].y() - qy)) / area;
    const double w1 = ((t[2].x() - qx) * (t[0].y() - qy) - (t[0].x() - qx) * (t[2].y() - qy)) / area;
    if(w0 < 0. || w1 < 0. || w0 + w1 > 1.) continue;  // the texel's centre is in a neighbour
    const diffuv::Rgb expected = sampler(f, {w0, w1, 1. - w0 - w1});
    const diffuv::Color got = image.at(px, py);
    EXPECT_LE(channel_error(diffuv::to_rgb(got), expected), 0.5 / 255 + 1e-9) << "face " << f.idx();
    ++checked;
  }
  EXPECT_GT(checked, cow.number_of_faces() / 2);
}

// The gutters: after d passes, every texel within d texels (8-neighbour
// steps) of a baked one is filled and none farther; reading the texture at
// the middle of each chart's border edges gives the edge's colour, where the
// background would bleed in without dilation.
TEST(BakeTexture, DilationFillsTheGuttersSoBordersDoNotBleed)
{
  const Mesh& cow = cgal_mesh("cow.off");
  const Packed_mesh packed = pack_default(cow, 512);
  const std::vector<diffuv::Rgb> colors = position_rgb(cow);
  const auto corner = diffuv::packed_corner_map(*packed.atlas, packed.packing);
  const auto sampler = diffuv::vertex_value_sampler(
      cow, boost::make_iterator_property_map(colors.begin(), get(boost::vertex_index, cow)));
  diffuv::Bake_options options;
  options.size = 512;
  options.dilation = 2;
  const diffuv::Baked_texture baked = diffuv::bake_texture(cow, corner, sampler, options);
  options.dilation = 0;
  const diffuv::Baked_texture bare = diffuv::bake_texture(cow, corner, sampler, options);
  EXPECT_EQ(bare.gutter_texels, 0u);
  EXPECT_GT(baked.gutter_texels, 0u);
  // Chebyshev distance to the nearest texel baked from the mesh, by two sweeps.
  const int S = 512;
  std::vector<int> distance(std::size_t(S) * S, 1 << 20);
  for(std::size_t i = 0; i < distance.size(); ++i)
    if(bare.source[i] != diffuv::Texel_source::background) distance[i] = 0;
  for(int pass = 0; pass < 2; ++pass)
    for(int step = 0; step < S * S; ++step) {
      const int i = pass == 0 ? step : S * S - 1 - step;
      const int x = i % S, y = i / S;
      for(int dy = -1; dy <= 1; ++dy)
        for(int dx = -1; dx <= 1; ++dx) {
          const int nx = x + dx, ny = y + dy;
          if(nx < 0 || ny < 0 || nx >= S || ny >= S) continue;
          distance[std::size_t(i)] = std::min(distance[std::size_t(i)], distance[std::size_t(ny) * S + nx] + 1);
        }
    }
  for(std::size_t i = 0; i < distance.size(); ++i) {
    ASSERT_EQ(baked.source[i] == diffuv::Texel_source::gutter, distance[i] == 1 || distance[i] == 2) << "texel " << i;
    if(distance[i] > 2) ASSERT_EQ(baked.image.at(int(i) % S, int(i) / S), (diffuv::Color{0, 0, 0}));
  }

  // Border edges of the charts: their two faces are in different charts (or
  // one is the mesh's border). A triangle thinner than a texel across its
  // border edge holds no texel centre near it, whatever the dilation (a
  // warped chart squeezes triangles with little 3D area that thin): only
  // edges of triangles at least a texel thick are read.
  double worst_dilated = 0., worst_bare = 0.;
  std::size_t edges = 0, thin = 0;
  for(std::size_t c = 0; c < packed.atlas->number_of_charts(); ++c)
    for(auto f : packed.atlas->chart(c).faces)
      for(auto h : CGAL::halfedges_around_face(cow.halfedge(f), cow)) {
        const auto g = cow.opposite(h);
        if(!cow.is_border(g) && packed.atlas->chart_of(cow.face(g)) == packed.atlas->chart_of(f)) continue;
        const auto a = get(corner, h), b = get(corner, cow.prev(h)), o = get(corner, cow.next(h));
        const double length = std::hypot(a.x() - b.x(), a.y() - b.y()) * S;
        const double twice_area = std::abs((b.x() - a.x()) * (o.y() - a.y()) - (o.x() - a.x()) * (b.y() - a.y())) * S * S;
        if(!(twice_area >= length)) { // thinner than a texel across the edge
          ++thin;
          continue;
        }
        const double s = 0.5 * (a.x() + b.x()), t = 0.5 * (a.y() + b.y());
        diffuv::Rgb expected;
        for(int k = 0; k < 3; ++k)
          expected[std::size_t(k)] = 0.5 * (colors[cow.target(h).idx()][std::size_t(k)] + colors[cow.source(h).idx()][std::size_t(k)]);
        worst_dilated = std::max(worst_dilated, channel_error(diffuv::sample_bilinear(baked.image, s, t), expected));
        worst_bare = std::max(worst_bare, channel_error(diffuv::sample_bilinear(bare.image, s, t), expected));
        ++edges;
      }
  EXPECT_GT(edges, 100u);
  EXPECT_LT(thin, edges / 20);
  EXPECT_LT(worst_dilated, 0.06) << "a chart's border reads the background";
  EXPECT_GT(worst_bare, 0.2);
}

// Charts packed a gutter (2 texels) apart share the texels between them:
// with one flat colour per chart, every gutter texel holds exactly the
// colour of a chart baked within the dilation's reach, never a blend of two.
TEST(BakeTexture, GutterTexelsTakeTheNearestChartsColourOnly)
{
  const Mesh& cow = cgal_mesh("cow.off");
  const Packed_mesh packed = pack_default(cow, 512);
  const auto corner = diffuv::packed_corner_map(*packed.atlas, packed.packing);
  const std::size_t charts = packed.atlas->number_of_charts();
  ASSERT_LT(charts, 200u * 200u);
  // A colour per chart, all different, whole bytes.
  const auto colour_of = [](std::size_t c) {
    return diffuv::Color{static_cast<unsigned char>(28 + c % 200), static_cast<unsigned char>(28 + c / 200), 90};
  };
  const auto sampler = [&](Mesh::Face_index f, const std::array<double, 3>&) {
    const diffuv::Color k = colour_of(packed.atlas->chart_of(f));
    return diffuv::Rgb{k.r / 255., k.g / 255., k.b / 255.};
  };
  diffuv::Bake_options options;
  options.size = 512;
  options.dilation = 2;
  const diffuv::Baked_texture baked = diffuv::bake_texture(cow, corner, sampler, options);
  ASSERT_GT(baked.gutter_texels, 1000u);
  const int S = 512;
  std::size_t checked = 0;
  for(int y = 0; y < S; ++y)
    for(int x = 0; x < S; ++x) {
      if(baked.source[std::size_t(y) * S + x] != diffuv::Texel_source::gutter) continue;
      const diffuv::Color got = baked.image.at(x, y);
      bool near = false;  // a texel of the chart of that colour within two texels
      for(int dy = -2; dy <= 2 && !near; ++dy)
        for(int dx = -2; dx <= 2 && !near; ++dx) {
          const int nx = x + dx, ny = y + dy;
          if(nx < 0 || ny < 0 || nx >= S || ny >= S) continue;
          const auto s = baked.source[std::size_t(ny) * S + nx];
          near = (s == diffuv::Texel_source::face || s == diffuv::Texel_source::vertex) && baked.image.at(nx, ny) == got;
        }
      ASSERT_TRUE(near) << "gutter texel (" << x << ", " << y << ") holds " << int(got.r) << " " << int(got.g) << " "
                        << int(got.b) << ", no chart's colour";
      ++checked;
    }
  EXPECT_EQ(checked, baked.gutter_texels);
}

// The dilation's two helpers. The max-norm distance to a triangle against a
// brute force over a fine grid of the triangle's points (never below it, and
// within the grid's step of it); the texture's islands of cow's packed atlas
// are its charts, face for face.
TEST(BakeTexture, NearestChartHelpers)
{
  unsigned state = 2024;
  const auto random = [&state] { // a fixed linear congruential sequence in [0,1)
    state = state * 1103515245u + 12345u;
    return double((state >> 8) & 0xffffu) / 65536.;
  };
  for(int trial = 0; trial < 300; ++trial) {
    std::array<double, 6> t;
    for(double& c : t) c = 10. * random();
    const double x = 14. * random() - 2., y = 14. * random() - 2.;
    const double d = diffuv::internal::max_norm_distance_to_triangle(x, y, t);
    double brute = std::numeric_limits<double>::infinity();
    const int steps = 400;
    for(int i = 0; i <= steps; ++i)
      for(int j = 0; i + j <= steps; ++j) {
        const double a = double(i) / steps, b = double(j) / steps, c = 1. - a - b;
        const double px = a * t[0] + b * t[2] + c * t[4], py = a * t[1] + b * t[3] + c * t[5];
        brute = std::min(brute, std::max(std::abs(px - x), std::abs(py - y)));
      }
    EXPECT_LE(d, brute + 1e-9) << trial;
    EXPECT_GE(d, brute - 0.05) << trial;
  }

  const Mesh& cow = cgal_mesh("cow.off");
  const Packed_mesh packed = pack_default(cow, 512);
  const auto corner = diffuv::packed_corner_map(*packed.atlas, packed.packing);
  std::vector<Mesh::Face_index> faces(cow.faces().begin(), cow.faces().end());
  const std::vector<std::int32_t> island = diffuv::internal::texture_islands(cow, corner, faces);
  std::map<std::int32_t, std::size_t> chart_of_island;
  for(std::size_t k = 0; k < faces.size(); ++k) {
    const std::size_t chart = packed.atlas->chart_of(faces[k]);
    const auto [it, inserted] = chart_of_island.emplace(island[k], chart);
    EXPECT_EQ(it->second, chart) << "face " << k << " joins two charts";
  }
  EXPECT_EQ(chart_of_island.size(), packed.atlas->number_of_charts());
}

// From another mesh by closest point: cow's colours taken from cow itself are
// those of the direct bake; normals of a flat grid are (0,0,1) everywhere.
TEST(BakeTexture, ClosestPointOnAnotherMeshAndNormals)
{
  const Mesh& cow = cgal_mesh("cow.off");
  const Packed_mesh packed = pack_default(cow, 256);
  const std::vector<diffuv::Rgb> colors = position_rgb(cow);
  const auto corner = diffuv::packed_corner_map(*packed.atlas, packed.packing);
  const auto colour_map = boost::make_iterator_property_map(colors.begin(), get(boost::vertex_index, cow));
  diffuv::Bake_options options;
  options.size = 256;
  const diffuv::Baked_texture direct = diffuv::bake_texture(cow, corner, diffuv::vertex_value_sampler(cow, colour_map), options);
  // The source: cow's faces listed backwards, so that face numbers differ.
  Mesh source;
  {
    std::vector<Mesh::Vertex_index> vs;
    for(auto v : cow.vertices()) vs.push_back(source.add_vertex(cow.point(v)));
    std::vector<Mesh::Face_index> fs(cow.faces().begin(), cow.faces().end());
    for(auto it = fs.rbegin(); it != fs.rend(); ++it) {
      std::vector<Mesh::Vertex_index> face;
      for(auto v : CGAL::vertices_around_face(cow.halfedge(*it), cow)) face.push_back(vs[v.idx()]);
      ASSERT_TRUE(source.add_face(face) != Mesh::null_face());
    }
  }
  const auto from = diffuv::closest_point_sampler(cow, cow.points(), source,
                                                  diffuv::vertex_value_sampler(source, colour_map));
  const diffuv::Baked_texture taken = diffuv::bake_texture(cow, corner, from, options);
  ASSERT_EQ(taken.source, direct.source);
  std::size_t differ = 0;
  for(std::size_t i = 0; i < direct.image.rgb.size(); ++i)
    differ += std::abs(int(direct.image.rgb[i]) - int(taken.image.rgb[i])) > 1 ? 1 : 0;
  EXPECT_EQ(differ, 0u);

  Mesh grid = make_grid(8, 8);
  auto normals = grid.add_property_map<Mesh::Vertex_index, Kernel::Vector_3>("v:n").first;
  CGAL::Polygon_mesh_processing::compute_vertex_normals(grid, normals);
  const Packed_mesh flat = pack_default(grid, 64);
  diffuv::Bake_options small;
  small.size = 64;
  const diffuv::Baked_texture normal_map = diffuv::bake_texture(
      grid, diffuv::packed_corner_map(*flat.atlas, flat.packing), diffuv::vertex_normal_sampler(grid, normals), small);
  ASSERT_GT(normal_map.face_texels, 64u * 64u / 2);
  const double z = 0.5 * (normals[*grid.vertices().begin()].z() + 1.);
  for(std::size_t i = 0; i < normal_map.source.size(); ++i)
    if(normal_map.source[i] != diffuv::Texel_source::background)
      ASSERT_EQ(normal_map.image.at(int(i) % 64, int(i) / 64), (diffuv::Color{128, 128, static_cast<unsigned char>(z > 0.5 ? 255 : 0)}));
}

} // namespace
