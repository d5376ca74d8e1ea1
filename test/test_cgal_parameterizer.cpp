// Tests of Diffusion_parameterizer_3, the model of CGAL's Parameterizer_3
// concept: through CGAL::Surface_mesh_parameterization::parameterize() on a
// Surface_mesh, a Polyhedron_3 and a Seam_mesh, and its error codes.
#include "test_data.h"

#include <diffuv/cgal/Diffusion_parameterizer_3.h>
#include <diffuv/parameterization/parameterize_disc.h>

#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>
#include <CGAL/Unique_hash_map.h>
#include <CGAL/boost/graph/Seam_mesh.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>
#include <unordered_map>

namespace {

using namespace diffuv_test;
namespace SMP = CGAL::Surface_mesh_parameterization;
namespace PMP = CGAL::Polygon_mesh_processing;

using vertex_descriptor = Mesh::Vertex_index;
using halfedge_descriptor = Mesh::Halfedge_index;
using Parameterizer = diffuv::Diffusion_parameterizer_3<Mesh>;

// The Polyhedron of CGAL's square_border_parameterizer and seam_Polyhedron_3
// examples: Simple_cartesian<double>, no vertex ids.
using SC_kernel = CGAL::Simple_cartesian<double>;
using Poly = CGAL::Polyhedron_3<SC_kernel>;
using Poly_vertex = boost::graph_traits<Poly>::vertex_descriptor;
using Poly_halfedge = boost::graph_traits<Poly>::halfedge_descriptor;

Poly read_polyhedron(const std::string& name)
{
  Poly poly;
  std::ifstream in(data_path("meshes/" + name));
  in >> poly; // keeps the file's vertex order
  EXPECT_TRUE(in || in.eof()) << name;
  return poly;
}

template <class Graph>
std::vector<typename boost::graph_traits<Graph>::vertex_descriptor> vertices_by_position(const Graph& g)
{
  return {vertices(g).begin(), vertices(g).end()};
}

// The (u,v) of diffuv's native API on the same mesh and corners.
std::vector<Point_2> native_uv(const Mesh& mesh, const std::vector<vertex_descriptor>& corners)
{
  diffuv::Uv_atlas<Mesh> atlas(mesh);
  const diffuv::Status status = diffuv::parameterize_disc(mesh, mesh.points(), corners, atlas);
  EXPECT_TRUE(status.ok()) << status.what();
  std::vector<Point_2> uv;
  for(vertex_descriptor v : vertices(mesh)) uv.push_back(get(atlas.vertex_uv_map(), v));
  return uv;
}

template <class P>
bool is_square_corner(const P& p)
{
  return (p.x() == 0. || p.x() == 1.) && (p.y() == 0. || p.y() == 1.);
}

// ---- Surface_mesh and Polyhedron_3 through CGAL's parameterize() -----------------------

TEST(CgalParameterizer, SurfaceMeshGivesTheNativeUv)
{
  Mesh mesh = cgal_mesh("nefertiti.off");
  const std::vector<vertex_descriptor> corners = selection_corners("square_corners.selection.txt");
  ASSERT_EQ(corners.size(), 4u);
  auto uv = mesh.add_property_map<vertex_descriptor, Point_2>("v:uv").first;
  const halfedge_descriptor bhd = PMP::longest_border(mesh).first;

  Parameterizer parameterizer(corners[0], corners[1], corners[2], corners[3]);
  ASSERT_EQ(SMP::parameterize(mesh, parameterizer, bhd, uv), SMP::OK) << parameterizer.status().what();

  // The copy keeps the vertex and face order: the same (u,v), bit-identical
  // today; 1e-12 leaves room for round-off in the fold repair's solves.
  const std::vector<Point_2> expected = native_uv(mesh, corners);
  for(vertex_descriptor v : vertices(mesh)) {
    EXPECT_NEAR(uv[v].x(), expected[v].x(), 1e-12) << "vertex " << v;
    EXPECT_NEAR(uv[v].y(), expected[v].y(), 1e-12) << "vertex " << v;
  }
  // The copies made by parameterize() share the status and the corners.
  EXPECT_TRUE(parameterizer.status().ok());
  ASSERT_EQ(parameterizer.corners().size(), 4u);
  EXPECT_EQ(parameterizer.corners()[0], corners[0]);
  const Point_2 square[4] = {Point_2(0, 0), Point_2(1, 0), Point_2(1, 1), Point_2(0, 1)};
  for(std::size_t c = 0; c < 4; ++c) EXPECT_EQ(uv[parameterizer.corners()[c]], square[c]) << "corner " << c;
  for(vertex_descriptor c : corners) EXPECT_TRUE(is_square_corner(uv[c]));
}

TEST(CgalParameterizer, PolyhedronGivesTheNativeUv)
{
  // As CGAL's square_border_parameterizer example: a Polyhedron_3 and a
  // Unique_hash_map as the uv map.
  Poly poly = read_polyhedron("nefertiti.off");
  const std::vector<Poly_vertex> by_position = vertices_by_position(poly);
  const Mesh& mesh = cgal_mesh("nefertiti.off");
  ASSERT_EQ(by_position.size(), num_vertices(mesh));
  std::vector<Poly_vertex> corners;
  for(std::size_t i : selection_indices("square_corners.selection.txt")) corners.push_back(by_position[i]);

  CGAL::Unique_hash_map<Poly_vertex, SC_kernel::Point_2> uv_uhm;
  boost::associative_property_map<CGAL::Unique_hash_map<Poly_vertex, SC_kernel::Point_2>> uv(uv_uhm);
  const Poly_halfedge bhd = PMP::longest_border(poly).first;
  diffuv::Diffusion_parameterizer_3<Poly> parameterizer(corners[0], corners[1], corners[2], corners[3]);
  ASSERT_EQ(SMP::parameterize(poly, parameterizer, bhd, uv), SMP::OK) << parameterizer.status().what();

  const std::vector<Point_2> expected = native_uv(mesh, selection_corners("square_corners.selection.txt"));
  for(std::size_t i = 0; i < by_position.size(); ++i) {
    EXPECT_NEAR(get(uv, by_position[i]).x(), expected[i].x(), 1e-12) << "vertex " << i;
    EXPECT_NEAR(get(uv, by_position[i]).y(), expected[i].y(), 1e-12) << "vertex " << i;
  }
  EXPECT_EQ(get(uv, corners[0]), SC_kernel::Point_2(0, 0));
  ASSERT_EQ(parameterizer.corners().size(), 4u);
  EXPECT_EQ(get(uv, parameterizer.corners()[1]), SC_kernel::Point_2(1, 0));
  EXPECT_EQ(get(uv, parameterizer.corners()[2]), SC_kernel::Point_2(1, 1));
  EXPECT_EQ(get(uv, parameterizer.corners()[3]), SC_kernel::Point_2(0, 1));
}

template <class Parameterizer_type>
void expect_grid_coordinates(std::size_t nx, std::size_t ny)
{
  Mesh grid = make_grid(nx, ny);
  auto uv = grid.add_property_map<vertex_descriptor, Point_2>("v:uv").first;
  Parameterizer_type parameterizer(grid_vertex(nx, 0, 0), grid_vertex(nx, nx, 0), grid_vertex(nx, nx, ny),
                                   grid_vertex(nx, 0, ny));
  ASSERT_EQ(SMP::parameterize(grid, parameterizer, PMP::longest_border(grid).first, uv), SMP::OK);
  for(vertex_descriptor v : vertices(grid)) {
    EXPECT_NEAR(uv[v].x(), grid.point(v).x(), 1e-12) << v;
    EXPECT_NEAR(uv[v].y(), grid.point(v).y(), 1e-12) << v;
  }
}

TEST(CgalParameterizer, FlatGridGetsItsOwnCoordinates)
{
  // A flat 8 x 5 grid of the unit square, corners at its corners: the diffusion
  // coordinates are the grid coordinates (the distance to a straight side is
  // linear: along rows or columns of edges, or through the flat triangles).
  expect_grid_coordinates<Parameterizer>(8, 5);
  expect_grid_coordinates<diffuv::Diffusion_parameterizer_3<Mesh, diffuv::Graph_distance_tag>>(8, 5);
  expect_grid_coordinates<diffuv::Diffusion_parameterizer_3<Mesh, diffuv::Fmm_distance_tag>>(8, 5);
}

TEST(CgalParameterizer, AutomaticCornersOnTheSquaresCorners)
{
  // Flat square grid: the four sharpest boundary vertices are its corners, so
  // the map is the grid itself, up to a rotation of the square.
  const std::size_t n = 6;
  Mesh grid = make_grid(n, n);
  auto uv = grid.add_property_map<vertex_descriptor, Point_2>("v:uv").first;
  Parameterizer automatic;
  EXPECT_FALSE(automatic.corners_given());
  ASSERT_EQ(SMP::parameterize(grid, automatic, PMP::longest_border(grid).first, uv), SMP::OK);
  ASSERT_EQ(automatic.corners().size(), 4u);
  const std::set<vertex_descriptor> grid_corners = {grid_vertex(n, 0, 0), grid_vertex(n, n, 0), grid_vertex(n, n, n),
                                                    grid_vertex(n, 0, n)};
  EXPECT_EQ(std::set<vertex_descriptor>(automatic.corners().begin(), automatic.corners().end()), grid_corners);
  // The rotation about (0.5, 0.5) taking corners()[0] to (0,0).
  auto rotate = [](const Point_2& p) { return Point_2(1. - p.y(), p.x()); }; // +90 degrees, exact here
  const Point_3 first = grid.point(automatic.corners()[0]);
  int turns = 0;
  for(Point_2 q(first.x(), first.y()); turns < 4 && q != Point_2(0, 0); ++turns) q = rotate(q);
  ASSERT_LT(turns, 4);
  for(vertex_descriptor v : vertices(grid)) {
    Point_2 expected(grid.point(v).x(), grid.point(v).y());
    for(int t = 0; t < turns; ++t) expected = rotate(expected);
    EXPECT_NEAR(uv[v].x(), expected.x(), 1e-12) << v;
    EXPECT_NEAR(uv[v].y(), expected.y(), 1e-12) << v;
  }

  // A curved disc: four distinct corners, exactly on the square's corners, the
  // ones parameterize_disc() chooses; the other border vertices on its sides.
  Mesh mesh = cgal_mesh("nefertiti.off");
  auto muv = mesh.add_property_map<vertex_descriptor, Point_2>("v:uv").first;
  Parameterizer parameterizer;
  const halfedge_descriptor bhd = PMP::longest_border(mesh).first;
  ASSERT_EQ(SMP::parameterize(mesh, parameterizer, bhd, muv), SMP::OK);
  const std::vector<vertex_descriptor> chosen = parameterizer.corners();
  ASSERT_EQ(chosen.size(), 4u);
  EXPECT_EQ(std::set<vertex_descriptor>(chosen.begin(), chosen.end()).size(), 4u);
  const std::vector<vertex_descriptor> loop = diffuv::counterclockwise_boundary(mesh, bhd);
  diffuv::Uv_atlas<Mesh> atlas(mesh);
  diffuv::Four_sides<vertex_descriptor> sides;
  diffuv::Disc_parameterization_report<Mesh> disc_report;
  ASSERT_TRUE(diffuv::parameterize_disc(mesh, mesh.points(), {}, atlas, {}, &disc_report).ok());
  sides = disc_report.sides;
  EXPECT_EQ(chosen, std::vector<vertex_descriptor>(sides.corners.begin(), sides.corners.end())); // the native choice
  const Point_2 square[4] = {Point_2(0, 0), Point_2(1, 0), Point_2(1, 1), Point_2(0, 1)};
  for(std::size_t c = 0; c < 4; ++c) EXPECT_EQ(muv[chosen[c]], square[c]);
  std::size_t on_a_corner = 0;
  for(vertex_descriptor v : loop) {
    const Point_2 p = muv[v];
    EXPECT_TRUE(p.x() == 0. || p.x() == 1. || p.y() == 0. || p.y() == 1.) << v << ": " << p;
    on_a_corner += is_square_corner(p);
  }
  EXPECT_EQ(on_a_corner, 4u);
  const std::vector<Point_2> expected = native_uv(mesh, {});
  for(vertex_descriptor v : vertices(mesh)) {
    EXPECT_NEAR(muv[v].x(), expected[v].x(), 1e-12) << v;
    EXPECT_NEAR(muv[v].y(), expected[v].y(), 1e-12) << v;
  }
}

TEST(CgalParameterizer, OnlyTheComponentOfTheBorderHalfedge)
{
  // Nefertiti and, beside it, a flat grid: parameterizing from the grid's border
  // maps the grid and leaves nefertiti's vertices alone, as CGAL does.
  const std::size_t n = 4;
  Mesh mesh = cgal_mesh("nefertiti.off");
  const std::size_t first_grid_vertex = num_vertices(mesh);
  const Mesh grid = make_grid(n, n);
  std::vector<vertex_descriptor> added;
  for(vertex_descriptor v : vertices(grid))
    added.push_back(mesh.add_vertex(Point_3(grid.point(v).x() + 1000., grid.point(v).y(), 0.)));
  for(auto f : faces(grid)) {
    std::vector<vertex_descriptor> face_vertices;
    for(vertex_descriptor v : CGAL::vertices_around_face(grid.halfedge(f), grid)) face_vertices.push_back(added[v]);
    ASSERT_NE(mesh.add_face(face_vertices), Mesh::null_face());
  }
  halfedge_descriptor bhd = Mesh::null_halfedge();
  for(halfedge_descriptor h : halfedges(mesh))
    if(is_border(h, mesh) && std::size_t(target(h, mesh)) >= first_grid_vertex) bhd = h;
  ASSERT_NE(bhd, Mesh::null_halfedge());

  auto uv = mesh.add_property_map<vertex_descriptor, Point_2>("v:uv", Point_2(-7, -7)).first;
  auto parameterized = mesh.add_property_map<vertex_descriptor, bool>("v:parameterized", false).first;
  auto index = mesh.add_property_map<vertex_descriptor, int>("v:index", -1).first; // not used
  Parameterizer parameterizer(added[grid_vertex(n, 0, 0)], added[grid_vertex(n, n, 0)], added[grid_vertex(n, n, n)],
                              added[grid_vertex(n, 0, n)]);
  ASSERT_EQ(parameterizer.parameterize(mesh, bhd, uv, index, parameterized), SMP::OK) << parameterizer.status().what();
  for(vertex_descriptor v : vertices(mesh)) {
    if(std::size_t(v) < first_grid_vertex) {
      EXPECT_FALSE(parameterized[v]) << v;
      EXPECT_EQ(uv[v], Point_2(-7, -7)) << v;
    } else {
      EXPECT_TRUE(parameterized[v]) << v;
      EXPECT_NEAR(uv[v].x(), mesh.point(v).x() - 1000., 1e-12) << v;
      EXPECT_NEAR(uv[v].y(), mesh.point(v).y(), 1e-12) << v;
    }
  }
  // From nefertiti's border instead: all of nefertiti, none of the grid.
  std::fill(parameterized.begin(), parameterized.end(), false);
  Parameterizer automatic;
  halfedge_descriptor nefertiti_border = Mesh::null_halfedge();
  for(halfedge_descriptor h : halfedges(mesh))
    if(is_border(h, mesh) && std::size_t(target(h, mesh)) < first_grid_vertex) nefertiti_border = h;
  ASSERT_EQ(automatic.parameterize(mesh, nefertiti_border, uv, index, parameterized), SMP::OK);
  for(vertex_descriptor v : vertices(mesh)) EXPECT_EQ(parameterized[v], std::size_t(v) < first_grid_vertex) << v;
}

TEST(CgalParameterizer, DistanceAndHeapTagsArePassedOn)
{
  Mesh mesh = cgal_mesh("nefertiti.off");
  const std::vector<vertex_descriptor> corners = selection_corners("square_corners.selection.txt");
  const halfedge_descriptor bhd = PMP::longest_border(mesh).first;
  auto native = [&](auto heap, auto distance) {
    diffuv::Uv_atlas<Mesh> atlas(mesh);
    EXPECT_TRUE((diffuv::parameterize_disc<decltype(distance), decltype(heap)>(mesh, mesh.points(), corners, atlas).ok()));
    std::vector<Point_2> uv;
    for(vertex_descriptor v : vertices(mesh)) uv.push_back(get(atlas.vertex_uv_map(), v));
    return uv;
  };
  auto expect_near = [&](const std::vector<Point_2>& a, const std::vector<Point_2>& b) {
    for(vertex_descriptor v : vertices(mesh)) {
      EXPECT_NEAR(a[v].x(), b[v].x(), 1e-12) << v;
      EXPECT_NEAR(a[v].y(), b[v].y(), 1e-12) << v;
    }
  };
  auto through_cgal = [&](auto parameterizer) {
    auto uv = mesh.add_property_map<vertex_descriptor, Point_2>("v:uv").first;
    EXPECT_EQ(SMP::parameterize(mesh, parameterizer, bhd, uv), SMP::OK) << parameterizer.status().what();
    std::vector<Point_2> result(uv.begin(), uv.end());
    mesh.remove_property_map(uv);
    return result;
  };
  const std::vector<Point_2> fmm =
      through_cgal(diffuv::Diffusion_parameterizer_3<Mesh, diffuv::Fmm_distance_tag>(corners[0], corners[1], corners[2], corners[3]));
  expect_near(fmm, native(diffuv::Fibonacci_heap_tag(), diffuv::Fmm_distance_tag()));
  const std::vector<Point_2> graph = through_cgal(diffuv::Diffusion_parameterizer_3<Mesh, diffuv::Graph_distance_tag, diffuv::Pairing_heap_tag>(
      corners[0], corners[1], corners[2], corners[3]));
  expect_near(graph, native(diffuv::Pairing_heap_tag(), diffuv::Graph_distance_tag()));
  // A heap alone: the library's default distance.
  auto default_uv = [&] {
    diffuv::Uv_atlas<Mesh> atlas(mesh);
    EXPECT_TRUE(diffuv::parameterize_disc(mesh, mesh.points(), corners, atlas).ok());
    std::vector<Point_2> uv;
    for(vertex_descriptor v : vertices(mesh)) uv.push_back(get(atlas.vertex_uv_map(), v));
    return uv;
  };
  expect_near(through_cgal(diffuv::Diffusion_parameterizer_3<Mesh, CGAL::Default, diffuv::Binomial_heap_tag>(
                  corners[0], corners[1], corners[2], corners[3])),
              default_uv());
  std::size_t differ = 0; // the tag matters: edge paths and fast marching differ
  for(vertex_descriptor v : vertices(mesh)) differ += CGAL::squared_distance(fmm[v], graph[v]) > 1e-12;
  EXPECT_GT(differ, num_vertices(mesh) / 2);
}

// ---- Seam_mesh -------------------------------------------------------------------------

// An open tube: n vertices around, m + 1 rings; vertex (i, j) = j * n + i at
// angle 2 pi i / n, height j / m; cells cut like make_grid's, faces outwards.
Mesh make_tube(std::size_t n, std::size_t m)
{
  Mesh tube;
  const double pi = std::acos(-1.);
  for(std::size_t j = 0; j <= m; ++j)
    for(std::size_t i = 0; i < n; ++i)
      tube.add_vertex(Point_3(std::cos(2 * pi * double(i) / double(n)), std::sin(2 * pi * double(i) / double(n)),
                              double(j) / double(m)));
  auto at = [&](std::size_t i, std::size_t j) { return vertex_descriptor(Mesh::size_type(j * n + i % n)); };
  for(std::size_t j = 0; j < m; ++j)
    for(std::size_t i = 0; i < n; ++i) {
      tube.add_face(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      tube.add_face(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  return tube;
}

using Seam_edge_pmap = Mesh::Property_map<Mesh::Edge_index, bool>;
using Seam_vertex_pmap = Mesh::Property_map<vertex_descriptor, bool>;
using Tube_seam_mesh = CGAL::Seam_mesh<Mesh, Seam_edge_pmap, Seam_vertex_pmap>;
using Seam_vertex = boost::graph_traits<Tube_seam_mesh>::vertex_descriptor;
using Seam_halfedge = boost::graph_traits<Tube_seam_mesh>::halfedge_descriptor;

TEST(CgalParameterizer, SeamMeshTubeCutAlongALine)
{
  // The tube cut along the vertical line i = 0 is a disc; with its corners at
  // the ends of the two copies of the cut, u = i / n (1 on the second copy)
  // and v = j / m: shortest edge paths to the cut are the rings, to a rim the
  // vertical edges.
  const std::size_t n = 12, m = 4;
  Mesh tube = make_tube(n, m);
  auto at = [&](std::size_t i, std::size_t j) { return vertex_descriptor(Mesh::size_type(j * n + i % n)); };
  Seam_edge_pmap seam_edges = tube.add_property_map<Mesh::Edge_index, bool>("e:seam", false).first;
  Seam_vertex_pmap seam_vertices = tube.add_property_map<vertex_descriptor, bool>("v:seam", false).first;
  Tube_seam_mesh seam_mesh(tube, seam_edges, seam_vertices);

  // Without the cut, a tube (an annulus) is not a disc.
  std::unordered_map<Seam_vertex, Point_2> uv_of;
  boost::associative_property_map<std::unordered_map<Seam_vertex, Point_2>> uv(uv_of);
  diffuv::Diffusion_parameterizer_3<Tube_seam_mesh> uncut;
  EXPECT_EQ(SMP::parameterize(seam_mesh, uncut, PMP::longest_border(seam_mesh).first, uv), SMP::ERROR_NO_TOPOLOGICAL_DISC);
  EXPECT_EQ(uncut.status().code, diffuv::Status_code::several_borders);
  EXPECT_TRUE(uv_of.empty());

  for(std::size_t j = 0; j < m; ++j) ASSERT_TRUE(seam_mesh.add_seam(at(0, j), at(0, j + 1)));
  EXPECT_EQ(num_vertices(seam_mesh), num_vertices(tube) + m + 1);

  // A seam vertex is the target of a halfedge of a face: the copy on the side
  // of the cells i = 0 (u = 0) and the copy on the side of the cells i = n - 1 (u = 1).
  auto seam_vertex = [&](vertex_descriptor from, vertex_descriptor to) {
    return target(Seam_halfedge(tube.halfedge(from, to)), seam_mesh);
  };
  const Seam_vertex c00 = seam_vertex(at(1, 1), at(0, 0));          // (0,0), cell (0,0)
  const Seam_vertex c10 = seam_vertex(at(n - 1, 0), at(0, 0));      // (1,0), cell (n-1,0)
  const Seam_vertex c11 = seam_vertex(at(n - 1, m - 1), at(0, m));  // (1,1), cell (n-1,m-1)
  const Seam_vertex c01 = seam_vertex(at(1, m), at(0, m));          // (0,1), cell (0,m-1)
  ASSERT_NE(c00, c10);
  ASSERT_NE(c01, c11);

  diffuv::Diffusion_parameterizer_3<Tube_seam_mesh> parameterizer(c00, c10, c11, c01);
  const Seam_halfedge bhd = PMP::longest_border(seam_mesh).first;
  ASSERT_EQ(SMP::parameterize(seam_mesh, parameterizer, bhd, uv), SMP::OK) << parameterizer.status().what();
  EXPECT_EQ(uv_of.size(), num_vertices(seam_mesh));
  EXPECT_EQ(get(uv, c00), Point_2(0, 0));
  EXPECT_EQ(get(uv, c10), Point_2(1, 0));
  EXPECT_EQ(get(uv, c11), Point_2(1, 1));
  EXPECT_EQ(get(uv, c01), Point_2(0, 1));

  // Face by face: each corner gets the (u,v) of its cell's side of the cut.
  for(auto f : faces(tube)) {
    const std::size_t cell = std::size_t(f) / 2 % n;
    for(Seam_halfedge h : CGAL::halfedges_around_face(halfedge(f, seam_mesh), seam_mesh)) {
      const std::size_t k = std::size_t(tube.target(target(h, seam_mesh).hd.tmhd));
      const std::size_t i = k % n, j = k / n;
      const double u = (i == 0 && cell == n - 1) ? 1. : double(i) / double(n);
      const Point_2 p = get(uv, target(h, seam_mesh));
      EXPECT_NEAR(p.x(), u, 1e-12) << "face " << f << " vertex " << k;
      EXPECT_NEAR(p.y(), double(j) / double(m), 1e-12) << "face " << f << " vertex " << k;
    }
  }
  // The vertices on the cut have two (u,v): u = 0 and u = 1.
  for(std::size_t j = 0; j <= m; ++j) {
    std::set<double> us;
    for(Seam_vertex sv : vertices(seam_mesh))
      if(tube.target(sv.hd.tmhd) == at(0, j)) us.insert(get(uv, sv).x());
    EXPECT_EQ(us, (std::set<double>{0., 1.})) << "ring " << j;
  }
}

// The total signed uv area of a disc whose border runs once around the unit
// square, counter-clockwise: 1, folds or not. Per face, the seam-mesh corners.
template <class SeamMesh, class UvMap>
double total_signed_area(const SeamMesh& mesh, UvMap uv)
{
  double total = 0;
  for(auto f : faces(mesh)) {
    auto h = halfedge(f, mesh);
    const auto a = get(uv, target(prev(h, mesh), mesh)), b = get(uv, target(h, mesh)),
               c = get(uv, target(next(h, mesh), mesh));
    total += 0.5 * ((b.x() - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (b.y() - a.y()));
  }
  return total;
}

// Checks a seam-mesh parameterization: every vertex finite and in the square,
// the four corners on the square's corners, the faces consistent (the border
// runs once around the square: total signed area 1), and every vertex of the
// cut, but the tip of a slit, with two or more different (u,v).
template <class SeamMesh, class UvMap>
void expect_cut_open_disc(const SeamMesh& mesh, UvMap uv, const diffuv::Diffusion_parameterizer_3<SeamMesh>& parameterizer)
{
  using Seam_mesh_vertex = typename boost::graph_traits<SeamMesh>::vertex_descriptor;
  using Underlying_vertex = typename boost::graph_traits<typename SeamMesh::Triangle_mesh>::vertex_descriptor;
  for(Seam_mesh_vertex v : vertices(mesh)) {
    const auto p = get(uv, v);
    ASSERT_TRUE(std::isfinite(p.x()) && std::isfinite(p.y()));
    EXPECT_TRUE(p.x() >= 0. && p.x() <= 1. && p.y() >= 0. && p.y() <= 1.) << p;
  }
  ASSERT_EQ(parameterizer.corners().size(), 4u);
  for(Seam_mesh_vertex c : parameterizer.corners()) EXPECT_TRUE(is_square_corner(get(uv, c))) << get(uv, c);
  EXPECT_NEAR(total_signed_area(mesh, uv), 1., 1e-9);

  std::unordered_map<Underlying_vertex, std::vector<std::decay_t<decltype(get(uv, *vertices(mesh).begin()))>>> uv_of_vertex;
  for(Seam_mesh_vertex v : vertices(mesh)) uv_of_vertex[target(v.hd.tmhd, mesh.mesh())].push_back(get(uv, v));
  std::size_t cut = 0;
  for(const auto& entry : uv_of_vertex) {
    // As many copies as wedges between seam edges (and the border).
    std::size_t seam_edges = 0;
    for(auto h : CGAL::halfedges_around_target(entry.first, mesh.mesh())) seam_edges += mesh.has_on_seam(h);
    const bool on_border = static_cast<bool>(is_border(entry.first, mesh.mesh()));
    const std::size_t copies = on_border ? 1 + seam_edges : std::max<std::size_t>(1, seam_edges);
    ASSERT_EQ(entry.second.size(), copies);
    if(copies == 1) continue; // not on the cut, or the tip of a slit
    ++cut;
    for(std::size_t a = 0; a < entry.second.size(); ++a)
      for(std::size_t b = a + 1; b < entry.second.size(); ++b) EXPECT_NE(entry.second[a], entry.second[b]);
  }
  EXPECT_GT(cut, 0u);
}

using Seam_edge_uhm = CGAL::Unique_hash_map<boost::graph_traits<Poly>::edge_descriptor, bool>;
using Seam_vertex_uhm = CGAL::Unique_hash_map<Poly_vertex, bool>;
using Poly_seam_mesh = CGAL::Seam_mesh<Poly, boost::associative_property_map<Seam_edge_uhm>,
                                       boost::associative_property_map<Seam_vertex_uhm>>;
using Poly_uv_uhm = CGAL::Unique_hash_map<Poly_halfedge, SC_kernel::Point_2>;

TEST(CgalParameterizer, SeamMeshFromCgalsSelectionFiles)
{
  // CGAL's seam_Polyhedron_3 example with our parameterizer: a Polyhedron_3,
  // seams read from a selection file, a uv map on the underlying halfedges.
  for(const std::string name : {"blob", "lion"}) {
    SCOPED_TRACE(name);
    Poly poly = read_polyhedron(name + ".off");
    ASSERT_GT(num_faces(poly), 0u);
    Seam_edge_uhm seam_edge_uhm(false);
    Seam_vertex_uhm seam_vertex_uhm(false);
    boost::associative_property_map<Seam_edge_uhm> seam_edge_pm(seam_edge_uhm);
    boost::associative_property_map<Seam_vertex_uhm> seam_vertex_pm(seam_vertex_uhm);
    Poly_seam_mesh mesh(poly, seam_edge_pm, seam_vertex_pm);
    const std::string selection = data_path("selections/" + name + ".selection.txt");
    ASSERT_NE(mesh.add_seams(selection.c_str()), Poly_halfedge());

    Poly_uv_uhm uv_uhm;
    boost::associative_property_map<Poly_uv_uhm> uv(uv_uhm);
    const auto bhd = PMP::longest_border(mesh).first;
    diffuv::Diffusion_parameterizer_3<Poly_seam_mesh> parameterizer;
    const SMP::Error_code err = SMP::parameterize(mesh, parameterizer, bhd, uv);
    if(name == "blob") { // a disc slit along the seams: still a disc
      ASSERT_EQ(err, SMP::OK) << parameterizer.status().what();
      expect_cut_open_disc(mesh, uv, parameterizer);
    } else { // lion.off has holes, and they are still there once cut: not a disc
      EXPECT_EQ(err, SMP::ERROR_NO_TOPOLOGICAL_DISC);
      EXPECT_EQ(parameterizer.status().code, diffuv::Status_code::several_borders) << parameterizer.status().what();
      for(Poly_halfedge h : halfedges(poly)) EXPECT_FALSE(uv_uhm.is_defined(h));
    }
  }
}

TEST(CgalParameterizer, SeamMeshClosedSphereCutAlongAPath)
{
  // A closed mesh (a sphere) cut along an edge path between two far vertices
  // is a disc whose border runs along both sides of the path.
  Mesh sphere = cgal_mesh("sphere.off");
  const vertex_descriptor start(0);
  std::vector<vertex_descriptor> parent(num_vertices(sphere), Mesh::null_vertex());
  std::vector<vertex_descriptor> queue = {start};
  parent[start] = start;
  for(std::size_t k = 0; k < queue.size(); ++k) // breadth first: the last one is the farthest
    for(vertex_descriptor w : CGAL::vertices_around_target(queue[k], sphere))
      if(parent[w] == Mesh::null_vertex()) {
        parent[w] = queue[k];
        queue.push_back(w);
      }
  ASSERT_EQ(queue.size(), num_vertices(sphere));

  Seam_edge_pmap seam_edges = sphere.add_property_map<Mesh::Edge_index, bool>("e:seam", false).first;
  Seam_vertex_pmap seam_vertices = sphere.add_property_map<vertex_descriptor, bool>("v:seam", false).first;
  Tube_seam_mesh mesh(sphere, seam_edges, seam_vertices);
  std::size_t path_edges = 0;
  for(vertex_descriptor v = queue.back(); v != start; v = parent[v], ++path_edges) ASSERT_TRUE(mesh.add_seam(v, parent[v]));
  ASSERT_GE(path_edges, 3u);
  EXPECT_EQ(num_vertices(mesh), num_vertices(sphere) + path_edges - 1); // the tips are not doubled

  std::unordered_map<Seam_vertex, Point_2> uv_of;
  boost::associative_property_map<std::unordered_map<Seam_vertex, Point_2>> uv(uv_of);
  const Seam_halfedge bhd = PMP::longest_border(mesh).first;
  ASSERT_NE(bhd, Seam_halfedge());
  diffuv::Diffusion_parameterizer_3<Tube_seam_mesh> parameterizer;
  ASSERT_EQ(SMP::parameterize(mesh, parameterizer, bhd, uv), SMP::OK) << parameterizer.status().what();
  EXPECT_EQ(uv_of.size(), num_vertices(mesh));
  expect_cut_open_disc(mesh, uv, parameterizer);
}

} // namespace
