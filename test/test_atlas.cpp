// Tests of the atlas stage: (patch, vertex) -> uv, kd-tree look-ups, point location.
#include "test_data.h"

#include <diffuv/atlas/Uv_atlas.h>
#include <diffuv/parameterization/parameterize_disc.h>

#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/Surface_mesh_parameterization/Mean_value_coordinates_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>

#include <random>

namespace {

using namespace diffuv_test;
using vertex_descriptor = Mesh::Vertex_index;
using Atlas = diffuv::Uv_atlas<Mesh>;
namespace PMP = CGAL::Polygon_mesh_processing;
namespace SMP = CGAL::Surface_mesh_parameterization;

// An injective chart from CGAL's mean value parameterizer (convex border), so
// point location has one right answer to compare with.
void add_mean_value_chart(Mesh& mesh, Atlas& atlas, Mesh::Property_map<vertex_descriptor, Point_2>& uvmap)
{
  auto bhd = PMP::longest_border(mesh).first;
  ASSERT_EQ(SMP::parameterize(mesh, SMP::Mean_value_coordinates_parameterizer_3<Mesh>(), bhd, uvmap), SMP::OK);
  std::vector<vertex_descriptor> vs(vertices(mesh).begin(), vertices(mesh).end());
  std::vector<Point_2> uv;
  for(auto v : vs) uv.push_back(uvmap[v]);
  atlas.add_chart(std::vector<Mesh::Face_index>(faces(mesh).begin(), faces(mesh).end()), vs, uv);
}

TEST(Atlas, VertexToUvToVertexRoundTrip)
{
  for(const char* name : {"nefertiti.off", "mushroom.off", "three_peaks.off"}) {
    const Mesh& mesh = cgal_mesh(name);
    Atlas atlas(mesh);
    ASSERT_TRUE(diffuv::parameterize_disc(mesh, mesh.points(), {}, atlas).ok());
    const auto& chart = atlas.chart(0);
    std::size_t same_vertex = 0;
    for(std::uint32_t i = 0; i < chart.vertices.size(); ++i) {
      const auto found = atlas.nearest_vertex(0, atlas.uv(0, i));
      // Graph distances can give two vertices the same (u,v); then either is right.
      EXPECT_EQ(atlas.uv(0, found), atlas.uv(0, i)) << name << " vertex " << i;
      if(found == i) ++same_vertex;
    }
    EXPECT_GT(same_vertex, 0.95 * chart.vertices.size()) << name;
  }
}

TEST(Atlas, LocatingAVertexUvGivesThatVertexPoint)
{
  Mesh mesh = cgal_mesh("mushroom.off"); // a copy: CGAL's parameterize() takes a mutable mesh
  Atlas atlas(mesh);
  auto uvmap = mesh.add_property_map<vertex_descriptor, Point_2>("v:test_uv").first;
  add_mean_value_chart(mesh, atlas, uvmap);
  for(auto v : vertices(mesh)) {
    const auto loc = atlas.locate(0, uvmap[v]);
    ASSERT_TRUE(loc.inside);
    const Point_3 p = atlas.point(loc);
    EXPECT_LT(std::sqrt(CGAL::squared_distance(p, mesh.point(v))), 1e-9) << v;
  }
}

TEST(Atlas, PointLocationAgreesWithCgalAabbLocate)
{
  Mesh mesh = cgal_mesh("nefertiti.off");
  Atlas atlas(mesh);
  auto uvmap = mesh.add_property_map<vertex_descriptor, Point_2>("v:test_uv").first;
  add_mean_value_chart(mesh, atlas, uvmap);

  // CGAL's reference: an AABB tree over the faces in the uv plane (a 2D point
  // map, lifted to z = 0), queried with locate_with_AABB_tree().
  using Uv_map = decltype(uvmap);
  using Lifted = PMP::internal::Point_to_Point_3_VPM<Mesh, Uv_map>;
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, CGAL::AABB_face_graph_triangle_primitive<Mesh, Lifted>>>;
  Tree tree;
  PMP::build_AABB_tree(mesh, tree, CGAL::parameters::vertex_point_map(uvmap));

  std::mt19937 rng(3);
  std::uniform_real_distribution<double> coord(0., 1.);
  std::size_t inside = 0;
  for(int k = 0; k < 300; ++k) {
    const Point_2 q(coord(rng), coord(rng));
    const auto ours = atlas.locate(0, q);
    const auto theirs = PMP::locate_with_AABB_tree(q, tree, mesh, CGAL::parameters::vertex_point_map(uvmap));
    // Same surface point (faces may differ when q is on a shared edge).
    const Point_3 a = atlas.point(ours), b = PMP::construct_point(theirs, mesh);
    EXPECT_LT(std::sqrt(CGAL::squared_distance(a, b)), 1e-9) << "q = " << q;
    // The barycentric coordinates interpolate back to q in uv.
    const auto h = mesh.halfedge(ours.location.first);
    const Point_2 u0 = uvmap[mesh.source(h)], u1 = uvmap[mesh.target(h)], u2 = uvmap[mesh.target(mesh.next(h))];
    const auto& w = ours.location.second;
    const Point_2 back(w[0] * u0.x() + w[1] * u1.x() + w[2] * u2.x(), w[0] * u0.y() + w[1] * u1.y() + w[2] * u2.y());
    // CGAL's answer lands on q exactly when q is inside the chart (a disc here).
    const auto th = mesh.halfedge(theirs.first);
    const auto& tw = theirs.second;
    const Point_2 t0 = uvmap[mesh.source(th)], t1 = uvmap[mesh.target(th)], t2 = uvmap[mesh.target(mesh.next(th))];
    const Point_2 theirs_uv(tw[0] * t0.x() + tw[1] * t1.x() + tw[2] * t2.x(), tw[0] * t0.y() + tw[1] * t1.y() + tw[2] * t2.y());
    const bool cgal_inside = std::sqrt(CGAL::squared_distance(theirs_uv, q)) < 1e-12;
    EXPECT_EQ(ours.inside, cgal_inside) << "q = " << q;
    if(ours.inside) {
      ++inside;
      EXPECT_LT(std::sqrt(CGAL::squared_distance(back, q)), 1e-12);
      EXPECT_GE((std::min)({w[0], w[1], w[2]}), 0.);
    }
  }
  EXPECT_GT(inside, 200u); // mean value maps onto a disc: most of the unit square
}

TEST(Atlas, OutsideQueriesGiveTheNearestPointOfTheChart)
{
  const std::size_t n = 6;
  const Mesh grid = make_grid(n, n);
  Atlas atlas(grid);
  ASSERT_TRUE(diffuv::parameterize_disc(grid, grid.points(), {grid_vertex(n, 0, 0), grid_vertex(n, n, 0), grid_vertex(n, n, n),
                                               grid_vertex(n, 0, n)}, atlas).ok());
  const auto loc = atlas.locate(0, Point_2(2., 2.));
  EXPECT_FALSE(loc.inside);
  EXPECT_NEAR(loc.uv_distance, std::sqrt(2.), 1e-12);
  const Point_3 p = atlas.point(loc);
  EXPECT_NEAR(p.x(), 1., 1e-12);
  EXPECT_NEAR(p.y(), 1., 1e-12);
  const auto below = atlas.locate(0, Point_2(0.5, -0.25));
  EXPECT_FALSE(below.inside);
  EXPECT_NEAR(below.uv_distance, 0.25, 1e-12);
  EXPECT_NEAR(atlas.point(below).x(), 0.5, 1e-12);
  EXPECT_NEAR(atlas.point(below).y(), 0., 1e-12);
}

TEST(Atlas, BorderVerticesHaveOneEntryPerChartAndCornersKeepSeams)
{
  // Two charts: the left and right halves of a grid, each with its own uv.
  const std::size_t n = 4;
  const Mesh grid = make_grid(n, n);
  std::vector<Mesh::Face_index> left, right;
  std::vector<vertex_descriptor> lv, rv;
  std::vector<Point_2> luv, ruv;
  for(auto f : faces(grid)) {
    double cx = 0;
    for(auto v : vertices_around_face(grid.halfedge(f), grid)) cx += grid.point(v).x() / 3;
    (cx < 0.5 ? left : right).push_back(f);
  }
  for(auto v : vertices(grid)) {
    const auto& p = grid.point(v);
    if(p.x() <= 0.5) { lv.push_back(v); luv.emplace_back(2 * p.x(), p.y()); }
    if(p.x() >= 0.5) { rv.push_back(v); ruv.emplace_back(2 * p.x() - 1, p.y()); }
  }
  Atlas atlas(grid);
  EXPECT_EQ(atlas.add_chart(left, lv, luv), 0u);
  EXPECT_EQ(atlas.add_chart(right, rv, ruv), 1u);
  EXPECT_THROW(atlas.add_chart(left, lv, luv), std::invalid_argument); // faces already used

  const vertex_descriptor seam = grid_vertex(n, n / 2, 1);
  auto e = atlas.entries(seam);
  ASSERT_EQ(e.second - e.first, 2);
  EXPECT_EQ(atlas.uv(e.first[0].chart, e.first[0].local).x() + atlas.uv(e.first[1].chart, e.first[1].local).x(), 1.);
  EXPECT_EQ(std::distance(atlas.entries(grid_vertex(n, 0, 0)).first, atlas.entries(grid_vertex(n, 0, 0)).second), 1);

  // Corner uv: the seam vertex seen from a left face is at u = 1, from a right face at u = 0.
  auto corner_uv = atlas.corner_uv_map();
  std::size_t left_seen = 0, right_seen = 0;
  for(auto h : halfedges_around_target(grid.halfedge(seam), grid)) {
    if(grid.is_border(h)) continue;
    const double u = get(corner_uv, h).x();
    if(atlas.chart_of(grid.face(h)) == 0) { EXPECT_EQ(u, 1.); ++left_seen; }
    else { EXPECT_EQ(u, 0.); ++right_seen; }
  }
  EXPECT_GT(left_seen, 0u);
  EXPECT_GT(right_seen, 0u);
  auto chart_of = atlas.vertex_chart_map();
  EXPECT_EQ(get(chart_of, grid_vertex(n, n, n)), 1u);
}

// A uv triangle flat on one side (its three vertices on one line) contains
// the points of its segment many times over; a proper triangle as near wins,
// whichever is met first, so the answer does not depend on the numbering.
TEST(Atlas, PointLocationPrefersAProperTriangleToAFlatOne)
{
  for(bool flat_first : {true, false}) {
    Mesh m;
    const auto a = m.add_vertex(Point_3(0, 0, 0)), b = m.add_vertex(Point_3(1, -0.5, 0)),
               c = m.add_vertex(Point_3(2, 0, 0)), d = m.add_vertex(Point_3(1, 1, 0));
    Mesh::Face_index flat, proper;
    if(flat_first) {
      flat = m.add_face(a, b, c);
      proper = m.add_face(a, c, d);
    } else {
      proper = m.add_face(a, c, d);
      flat = m.add_face(a, b, c);
    }
    ASSERT_TRUE(flat.is_valid() && proper.is_valid());
    Atlas atlas(m);
    atlas.add_chart({flat, proper}, {a, b, c, d}, {Point_2(0, 0), Point_2(0.5, 0), Point_2(1, 0), Point_2(0.5, 1)});
    // (0.2, 0): the nearest vertex is a, whose star holds both triangles.
    const auto loc = atlas.locate(0, Point_2(0.2, 0));
    EXPECT_EQ(loc.location.first, proper) << (flat_first ? "flat triangle added first" : "proper face added first");
    EXPECT_TRUE(loc.inside);
    const auto p = atlas.point(loc);
    EXPECT_NEAR(p.x(), 0.4, 1e-12);
    EXPECT_NEAR(p.y(), 0., 1e-12);
    // (0.5, 0) is b's (u,v): b itself, although it also lies inside the flat
    // triangle's edge ac and on the proper triangle's edge.
    const auto at_b = atlas.point(atlas.locate(0, Point_2(0.5, 0)));
    EXPECT_EQ(at_b, m.point(b)) << (flat_first ? "flat triangle added first" : "proper face added first");
  }
}

} // namespace
