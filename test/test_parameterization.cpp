// Tests of the patch and parameterization stages: disc check, four sides,
// diffusion coordinates, a whole disc mesh.
#include "test_data.h"

#include <diffuv/metrics/distortion.h>
#include <diffuv/parameterization/parameterize_disc.h>

#include <CGAL/boost/graph/copy_face_graph.h>

#include <boost/graph/adjacency_list.hpp>

#include <algorithm>
#include <fstream>
#include <numeric>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>

namespace {

using namespace diffuv_test;
using vertex_descriptor = Mesh::Vertex_index;
using Atlas = diffuv::Uv_atlas<Mesh>;
using Sides = diffuv::Four_sides<vertex_descriptor>;

std::vector<vertex_descriptor> grid_corners(std::size_t nx, std::size_t ny)
{
  return {grid_vertex(nx, 0, 0), grid_vertex(nx, nx, 0), grid_vertex(nx, nx, ny), grid_vertex(nx, 0, ny)};
}

// ---- diffusion_ratio: the edge cases of equation (2) ----------------------------

TEST(DiffusionRatio, DefinedEdgeCases)
{
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(diffuv::diffusion_ratio(1., 3.), 0.25);
  EXPECT_EQ(diffuv::diffusion_ratio(0., 3.), 0.);
  EXPECT_EQ(diffuv::diffusion_ratio(3., 0.), 1.);
  EXPECT_EQ(diffuv::diffusion_ratio(0., 0.), 0.5);   // on two opposite sides
  EXPECT_EQ(diffuv::diffusion_ratio(inf, 2.), 1.);   // unreached from side 1
  EXPECT_EQ(diffuv::diffusion_ratio(2., inf), 0.);   // unreached from side 2
  EXPECT_TRUE(std::isnan(diffuv::diffusion_ratio(inf, inf)));
}

// ---- disc check -------------------------------------------------------------------

TEST(DiscCheck, AcceptsDiscMeshes)
{
  for(const char* name : {"nefertiti.off", "mushroom.off", "three_peaks.off", "lion-head.off"})
    EXPECT_TRUE(diffuv::check_disc(cgal_mesh(name)).ok()) << name << ": " << diffuv::check_disc(cgal_mesh(name)).what();
  EXPECT_TRUE(diffuv::check_disc(make_grid(3, 2)).ok());
}

TEST(DiscCheck, RejectsClosedMeshes)
{
  EXPECT_EQ(diffuv::check_disc(cgal_mesh("cow.off")).code, diffuv::Status_code::no_border);
}

TEST(DiscCheck, RejectsSeveralBordersAndHandles)
{
  // A grid with an interior hole: two boundary loops (an annulus).
  Mesh annulus = make_grid(4, 4);
  std::vector<Mesh::Face_index> centre;
  for(auto f : faces(annulus)) {
    auto c = CGAL::centroid(annulus.point(annulus.source(annulus.halfedge(f))), annulus.point(annulus.target(annulus.halfedge(f))),
                            annulus.point(annulus.target(annulus.next(annulus.halfedge(f)))));
    if(std::abs(c.x() - 0.5) < 0.25 && std::abs(c.y() - 0.5) < 0.25) centre.push_back(f);
  }
  ASSERT_EQ(centre.size(), 8u);
  for(auto f : centre) CGAL::Euler::remove_face(annulus.halfedge(f), annulus);
  annulus.collect_garbage();
  const diffuv::Status s = diffuv::check_disc(annulus);
  EXPECT_EQ(s.code, diffuv::Status_code::several_borders);
  EXPECT_EQ(s.what(), "the mesh has several boundary loops, not a topological disc (2 boundary loops)");

  // Two disjoint grids.
  Mesh two = make_grid(2, 2);
  Mesh other = make_grid(2, 2);
  CGAL::copy_face_graph(other, two);
  EXPECT_EQ(diffuv::check_disc(two).code, diffuv::Status_code::disconnected_mesh);

  // A torus-like strip: a grid whose left and right columns are glued has
  // two boundary loops; gluing into a closed torus leaves none; a torus with
  // one face removed has one loop but Euler characteristic -1.
  Mesh torus;
  const std::size_t n = 6;
  std::vector<Mesh::Vertex_index> v;
  for(std::size_t j = 0; j < n; ++j)
    for(std::size_t i = 0; i < n; ++i) {
      const double a = 2 * CGAL_PI * i / n, b = 2 * CGAL_PI * j / n;
      v.push_back(torus.add_vertex(Point_3((2 + std::cos(b)) * std::cos(a), (2 + std::cos(b)) * std::sin(a), std::sin(b))));
    }
  auto at = [&](std::size_t i, std::size_t j) { return v[(j % n) * n + (i % n)]; };
  for(std::size_t j = 0; j < n; ++j)
    for(std::size_t i = 0; i < n; ++i) {
      if(i == 0 && j == 0) continue; // the hole
      torus.add_face(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      torus.add_face(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  const diffuv::Status t = diffuv::check_disc(torus);
  EXPECT_EQ(t.code, diffuv::Status_code::not_a_disc) << t.what();
  EXPECT_EQ(t.detail, "Euler characteristic -1, genus 1");
}

// ---- four sides ---------------------------------------------------------------------

TEST(FourSides, CornersGivenInAnyOrderFollowTheBoundaryCounterClockwise)
{
  const Mesh grid = make_grid(4, 3);
  const auto loop = diffuv::counterclockwise_boundary(grid, diffuv::boundary_loops(grid).front());
  ASSERT_EQ(loop.size(), 14u);
  const auto c = grid_corners(4, 3);
  Sides sides;
  // Listed out of order; corners[0] stays first.
  ASSERT_TRUE(diffuv::sides_from_corners(loop, {c[0], c[2], c[3], c[1]}, sides).ok());
  EXPECT_EQ(sides.corners[0], c[0]);
  EXPECT_EQ(sides.corners[1], c[1]); // counter-clockwise seen from +z: bottom-right next
  EXPECT_EQ(sides.corners[2], c[2]);
  EXPECT_EQ(sides.corners[3], c[3]);
  EXPECT_EQ(sides.v1.size(), 5u);
  EXPECT_EQ(sides.u2.size(), 4u);
  EXPECT_EQ(sides.v2.size(), 5u);
  EXPECT_EQ(sides.u1.size(), 4u);
  EXPECT_EQ(sides.v1.front(), c[0]);
  EXPECT_EQ(sides.v1.back(), c[1]);
  EXPECT_EQ(sides.u1.front(), c[3]);
  EXPECT_EQ(sides.u1.back(), c[0]);
}

TEST(FourSides, BadCornersAreReported)
{
  const Mesh grid = make_grid(4, 3);
  const auto loop = diffuv::counterclockwise_boundary(grid, diffuv::boundary_loops(grid).front());
  const auto c = grid_corners(4, 3);
  Sides sides;
  EXPECT_EQ(diffuv::sides_from_corners(loop, {c[0], c[1], c[2]}, sides).code, diffuv::Status_code::corner_count);
  EXPECT_EQ(diffuv::sides_from_corners(loop, {c[0], c[1], c[2], c[3], c[0]}, sides).code, diffuv::Status_code::corner_count);
  EXPECT_EQ(diffuv::sides_from_corners(loop, {c[0], c[1], c[1], c[3]}, sides).code, diffuv::Status_code::corner_duplicated);
  const diffuv::Status inner = diffuv::sides_from_corners(loop, {c[0], c[1], grid_vertex(4, 2, 1), c[3]}, sides);
  EXPECT_EQ(inner.code, diffuv::Status_code::corner_not_on_border);
  EXPECT_EQ(inner.detail, "corner #3 listed");
}

TEST(FourSides, EqualArcCornersCutTheLoopIntoQuarters)
{
  const Mesh grid = make_grid(8, 8);
  const auto loop = diffuv::counterclockwise_boundary(grid, diffuv::boundary_loops(grid).front());
  const auto corners = diffuv::equal_arc_corners(grid, get(CGAL::vertex_point, grid), loop);
  // The sharpest boundary vertices of a square grid are its corners (90 degrees);
  // quarter arcs then land on the other three corners.
  std::vector<vertex_descriptor> expected = grid_corners(8, 8);
  ASSERT_EQ(corners.size(), 4u);
  EXPECT_NE(std::find(expected.begin(), expected.end(), corners[0]), expected.end());
  Sides sides;
  ASSERT_TRUE(diffuv::sides_from_corners(loop, corners, sides).ok());
  EXPECT_EQ(sides.v1.size(), 9u);
  EXPECT_EQ(sides.u2.size(), 9u);
  EXPECT_EQ(sides.v2.size(), 9u);
  EXPECT_EQ(sides.u1.size(), 9u);
}

// ---- diffusion coordinates --------------------------------------------------------------

TEST(DiffusionCoordinates, FlatGridGivesTheGridCoordinates)
{
  // On a regular grid, the edge-path distance from the left side to column i is
  // i * h along horizontal edges, so u = i / nx and v = j / ny exactly.
  const std::size_t nx = 12, ny = 7;
  const Mesh grid = make_grid(nx, ny);
  Atlas atlas(grid);
  Sides sides;
  diffuv::Disc_parameterization_report<Mesh> disc_report;
  ASSERT_TRUE(diffuv::parameterize_disc(grid, grid.points(), grid_corners(nx, ny), atlas, {}, &disc_report).ok());
  sides = disc_report.sides;
  auto uv = atlas.vertex_uv_map();
  for(std::size_t j = 0; j <= ny; ++j)
    for(std::size_t i = 0; i <= nx; ++i) {
      const Point_2 p = get(uv, grid_vertex(nx, i, j));
      EXPECT_NEAR(p.x(), double(i) / nx, 1e-12) << i << "," << j;
      EXPECT_NEAR(p.y(), double(j) / ny, 1e-12) << i << "," << j;
    }
}

TEST(DiffusionCoordinates, ChartsAreNotMirrored)
{
  const std::size_t n = 10;
  const Mesh grid = make_grid(n, n);
  Atlas atlas(grid);
  ASSERT_TRUE(diffuv::parameterize_disc(grid, grid.points(), grid_corners(n, n), atlas).ok());
  auto uv = atlas.vertex_uv_map();
  for(auto f : faces(grid))
    EXPECT_GT(signed_uv_area(grid, f, [&](vertex_descriptor v) { return get(uv, v); }), 0.);
}

TEST(DiffusionCoordinates, SwappingOppositeSidesMirrorsTheCoordinate)
{
  const Mesh& mesh = cgal_mesh("mushroom.off");
  const auto loop = diffuv::counterclockwise_boundary(mesh, diffuv::boundary_loops(mesh).front());
  Sides sides;
  ASSERT_TRUE(diffuv::sides_from_corners(loop, diffuv::equal_arc_corners(mesh, mesh.points(), loop), sides).ok());
  Sides swapped = sides;
  std::swap(swapped.u1, swapped.u2);
  std::swap(swapped.v1, swapped.v2);
  std::vector<Point_2> a(num_vertices(mesh)), b(num_vertices(mesh));
  auto index = get(boost::vertex_index, mesh);
  auto lengths = diffuv::edge_length_map(mesh);
  ASSERT_TRUE(diffuv::diffusion_coordinates(mesh, sides, lengths, boost::make_iterator_property_map(a.begin(), index)).ok());
  ASSERT_TRUE(diffuv::diffusion_coordinates(mesh, swapped, lengths, boost::make_iterator_property_map(b.begin(), index)).ok());
  for(std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_NEAR(b[i].x(), 1. - a[i].x(), 1e-12);
    EXPECT_NEAR(b[i].y(), 1. - a[i].y(), 1e-12);
  }
}

TEST(DiffusionCoordinates, EveryDistanceBackendGivesTheGridCoordinatesOnAFlatGrid)
{
  const std::size_t nx = 10, ny = 6;
  const Mesh grid = make_grid(nx, ny);
  Atlas fmm(grid), exact(grid);
  ASSERT_TRUE(diffuv::parameterize_disc<diffuv::Fmm_distance_tag>(grid, grid.points(), grid_corners(nx, ny), fmm).ok());
  ASSERT_TRUE(diffuv::parameterize_disc<diffuv::Exact_distance_tag>(grid, grid.points(), grid_corners(nx, ny), exact).ok());
  for(std::size_t j = 0; j <= ny; ++j)
    for(std::size_t i = 0; i <= nx; ++i) {
      for(const Atlas* a : {&fmm, &exact}) {
        const Point_2 p = get(a->vertex_uv_map(), grid_vertex(nx, i, j));
        EXPECT_NEAR(p.x(), double(i) / nx, 1e-9) << i << "," << j;
        EXPECT_NEAR(p.y(), double(j) / ny, 1e-9) << i << "," << j;
      }
    }
}

TEST(DiffusionCoordinates, FastMarchingRemovesTheCollapsedTrianglesOfEdgePaths)
{
  // Measured on mushroom: edge-path distances collapse a few triangles (angle
  // distortion up to 1e5); distances through triangles do not.
  const Mesh& mesh = cgal_mesh("mushroom.off");
  Atlas graph(mesh), fmm(mesh);
  ASSERT_TRUE(diffuv::parameterize_disc<diffuv::Graph_distance_tag>(mesh, mesh.points(), {}, graph).ok());
  ASSERT_TRUE(diffuv::parameterize_disc<diffuv::Fmm_distance_tag>(mesh, mesh.points(), {}, fmm).ok());
  const auto dg = diffuv::measure_distortion(mesh, mesh.points(), faces(mesh), graph.chart_uv_map(0));
  const auto df = diffuv::measure_distortion(mesh, mesh.points(), faces(mesh), fmm.chart_uv_map(0));
  EXPECT_GT(dg.angle_max, 100.);
  EXPECT_LT(df.angle_max, 10.);
  EXPECT_LT(df.angle_mean, dg.angle_mean);
  EXPECT_TRUE(df.injective());
}

TEST(DiffusionCoordinates, AllHeapsGiveTheSameCoordinates)
{
  const Mesh& mesh = cgal_mesh("nefertiti.off");
  Atlas fib(mesh), pairing(mesh);
  ASSERT_TRUE(diffuv::parameterize_disc(mesh, mesh.points(), {}, fib).ok());
  ASSERT_TRUE((diffuv::parameterize_disc<diffuv::Default_distance_tag, diffuv::Quaternary_heap_tag>(mesh, mesh.points(), {}, pairing).ok()));
  EXPECT_EQ(fib.chart(0).uv, pairing.chart(0).uv);
}

TEST(DiffusionCoordinates, EmptySideUnreachableAndOppositeSides)
{
  using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, boost::no_property,
                                      boost::property<boost::edge_weight_t, double>>;
  // Path 0-1-2-3-4 plus an isolated vertex 5.
  Graph g(6);
  for(std::size_t i = 0; i < 4; ++i) boost::add_edge(i, i + 1, 1.0, g);
  diffuv::Four_sides<std::size_t> sides;
  sides.u1 = {0};
  sides.u2 = {4};
  sides.v1 = {0, 2}; // vertex 2 is on both v sides: 0/0
  sides.v2 = {2, 4};
  std::vector<Point_2> uv(6);
  auto map = boost::make_iterator_property_map(uv.begin(), get(boost::vertex_index, g));
  diffuv::Diffusion_coordinates<Graph, diffuv::Graph_distance_tag> coordinates(g);
  const diffuv::Status s = coordinates.compute(sides, get(boost::edge_weight, g), map);
  EXPECT_EQ(s.code, diffuv::Status_code::unreachable_vertices);
  EXPECT_EQ(s.detail, "1 vertex");
  EXPECT_DOUBLE_EQ(uv[1].x(), 0.25);
  EXPECT_DOUBLE_EQ(uv[2].x(), 0.5);
  EXPECT_DOUBLE_EQ(uv[2].y(), 0.5); // on v1 and v2: halfway
  EXPECT_TRUE(std::isnan(uv[5].x()));
  EXPECT_EQ(coordinates.vertices_on_opposite_sides(), 1u);
  EXPECT_EQ(coordinates.distances(diffuv::Side::u2)[1], 3.);

  sides.v2.clear();
  const diffuv::Status e = coordinates.compute(sides, get(boost::edge_weight, g), map);
  EXPECT_EQ(e.code, diffuv::Status_code::empty_side);
  EXPECT_EQ(e.detail, "side v2");
}

TEST(DiffusionCoordinates, ASideVertexThatIsNotOfTheGraphIsRefused)
{
  // A side naming a vertex past the graph's: refused before a distance run
  // indexes its arrays by it, for every distance backend.
  const std::size_t n = 5;
  const Mesh grid = make_grid(n, n);
  Atlas atlas(grid);
  diffuv::Disc_parameterization_report<Mesh> report;
  ASSERT_TRUE(diffuv::parameterize_disc(grid, grid.points(), grid_corners(n, n), atlas, {}, &report).ok());
  Sides sides = report.sides;
  const std::size_t far = num_vertices(grid) + 1000000;
  sides.u2.push_back(vertex_descriptor(Mesh::size_type(far)));
  std::vector<Point_2> uv(num_vertices(grid), Point_2(-7, -7));
  auto map = boost::make_iterator_property_map(uv.begin(), get(boost::vertex_index, grid));
  const std::string expected = "Diffusion_coordinates::compute: a vertex of side u2 (index " + std::to_string(far) +
                               ") is not a vertex of the graph (" + std::to_string(num_vertices(grid)) + " vertices)";
  auto refused = [&](auto tag) {
    try {
      diffuv::Diffusion_coordinates<Mesh, decltype(tag)> coordinates(grid);
      coordinates.compute(sides, diffuv::edge_length_map(grid), map);
    } catch(const std::out_of_range& e) {
      return std::string(e.what());
    }
    return std::string("no exception");
  };
  EXPECT_EQ(refused(diffuv::Graph_distance_tag()), expected);
  EXPECT_EQ(refused(diffuv::Fmm_distance_tag()), expected);
  for(const Point_2& p : uv) EXPECT_EQ(p, Point_2(-7, -7));
}

// ---- whole disc meshes -------------------------------------------------------------------

TEST(ParameterizeDisc, NefertitiWithCgalSquareCorners)
{
  const Mesh& mesh = cgal_mesh("nefertiti.off");
  const auto corners = selection_corners("square_corners.selection.txt");
  ASSERT_EQ(corners.size(), 4u);
  Atlas atlas(mesh);
  Sides sides;
  diffuv::Disc_parameterization_report<Mesh> disc_report;
  ASSERT_TRUE(diffuv::parameterize_disc(mesh, mesh.points(), corners, atlas, {}, &disc_report).ok());
  sides = disc_report.sides;
  EXPECT_EQ(sides.corners[0], corners[0]);
  auto uv = atlas.vertex_uv_map();
  const Point_2 square[4] = {Point_2(0, 0), Point_2(1, 0), Point_2(1, 1), Point_2(0, 1)};
  for(int c = 0; c < 4; ++c) EXPECT_EQ(get(uv, sides.corners[c]), square[c]) << "corner " << c;
  for(auto v : vertices(mesh)) {
    const Point_2 p = get(uv, v);
    EXPECT_GE(p.x(), 0.);
    EXPECT_LE(p.x(), 1.);
    EXPECT_GE(p.y(), 0.);
    EXPECT_LE(p.y(), 1.);
  }
  // Sides are where they must be: u1 at u = 0, v2 at v = 1, ...
  for(auto v : sides.u1) EXPECT_EQ(get(uv, v).x(), 0.);
  for(auto v : sides.u2) EXPECT_EQ(get(uv, v).x(), 1.);
  for(auto v : sides.v1) EXPECT_EQ(get(uv, v).y(), 0.);
  for(auto v : sides.v2) EXPECT_EQ(get(uv, v).y(), 1.);
}

TEST(ParameterizeDisc, RealMeshesAreMostlyCounterClockwise)
{
  for(const char* name : {"nefertiti.off", "mushroom.off", "three_peaks.off"}) {
    const Mesh& mesh = cgal_mesh(name);
    Atlas atlas(mesh);
    ASSERT_TRUE(diffuv::parameterize_disc(mesh, mesh.points(), {}, atlas).ok()) << name;
    auto uv = atlas.vertex_uv_map();
    std::size_t positive = 0;
    for(auto f : faces(mesh))
      if(signed_uv_area(mesh, f, [&](vertex_descriptor v) { return get(uv, v); }) > 0) ++positive;
    EXPECT_GT(positive, 0.95 * num_faces(mesh)) << name;
  }
}

TEST(ParameterizeDisc, ShufflingTheVertexOrderChangesNothing)
{
  // Same surface, vertices stored in another order: automatic corners and
  // every vertex's (u,v) must be the same.
  const Mesh& mesh = cgal_mesh("nefertiti.off");
  std::vector<std::size_t> perm(num_vertices(mesh));
  std::iota(perm.begin(), perm.end(), 0);
  std::shuffle(perm.begin(), perm.end(), std::mt19937(7));
  Mesh shuffled; // vertex perm[i] of the copy is vertex i of the original
  std::vector<std::size_t> inverse(perm.size());
  for(std::size_t i = 0; i < perm.size(); ++i) inverse[perm[i]] = i;
  for(std::size_t k = 0; k < perm.size(); ++k) shuffled.add_vertex(mesh.point(vertex_descriptor(Mesh::size_type(inverse[k]))));
  for(auto f : faces(mesh)) {
    std::vector<vertex_descriptor> fv;
    for(auto v : vertices_around_face(mesh.halfedge(f), mesh)) fv.push_back(vertex_descriptor(Mesh::size_type(perm[v.idx()])));
    shuffled.add_face(fv);
  }
  Atlas a(mesh), b(shuffled);
  ASSERT_TRUE(diffuv::parameterize_disc(mesh, mesh.points(), {}, a).ok());
  ASSERT_TRUE(diffuv::parameterize_disc(shuffled, shuffled.points(), {}, b).ok());
  auto uva = a.vertex_uv_map();
  auto uvb = b.vertex_uv_map();
  for(auto v : vertices(mesh)) {
    const Point_2 p = get(uva, v), q = get(uvb, vertex_descriptor(Mesh::size_type(perm[v.idx()])));
    EXPECT_EQ(p, q) << "vertex " << v.idx();
  }
}

TEST(ParameterizeDisc, FailuresLeaveTheAtlasEmpty)
{
  Atlas atlas(cgal_mesh("cow.off"));
  EXPECT_EQ(diffuv::parameterize_disc(cgal_mesh("cow.off"), get(CGAL::vertex_point, cgal_mesh("cow.off")), {}, atlas).code, diffuv::Status_code::no_border);
  EXPECT_EQ(atlas.number_of_charts(), 0u);
  const Mesh& mesh = cgal_mesh("nefertiti.off");
  Atlas other(mesh);
  EXPECT_EQ(diffuv::parameterize_disc(mesh, mesh.points(), {vertex_descriptor(133), vertex_descriptor(8)}, other).code,
            diffuv::Status_code::corner_count);
  EXPECT_EQ(other.number_of_charts(), 0u);
}

TEST(ParameterizeDisc, AnAtlasOfAnotherMeshIsRefused)
{
  // The atlas holds the mesh it maps; charts of nefertiti's faces in an atlas
  // of mushroom (larger, so nothing would even be written past its arrays)
  // would describe faces mushroom does not have.
  const Mesh& mesh = cgal_mesh("nefertiti.off");
  const Mesh& other = cgal_mesh("mushroom.off");
  ASSERT_GT(num_faces(other), num_faces(mesh));
  Atlas atlas(other);
  try {
    diffuv::parameterize_disc(mesh, mesh.points(), {}, atlas);
    ADD_FAILURE() << "no exception";
  } catch(const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "parameterize_disc: the atlas maps another mesh");
  }
  EXPECT_EQ(atlas.number_of_charts(), 0u);
}

} // namespace
