// Tests of diffuv/compare/cgal_parameterizers.h: CGAL's parameterizers on
// one patch with our four corners. Expectations come from the mathematics,
// not from the code: Tutte's and Floater's theorems (a convex border gives an
// injective map), linear precision of mean value and cotangent weights (a
// flat patch is reproduced exactly), the symmetry of a regular grid (every
// symmetric weight reproduces it), and our corner and side convention.
#include "compare/cgal_parameterizers.h"
#include <diffuv/io/selection_file.h>
#include <diffuv/metrics/distortion.h>
#include <diffuv/layout/disc_patches.h>
#include <diffuv/patches/corners.h>
#include <diffuv/patches/region_sides.h>

#include "test_data.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <set>
#include <string>
#include <vector>

namespace {

using namespace diffuv_test;
namespace SMP = CGAL::Surface_mesh_parameterization;
using diffuv::Cgal_method;
using Vertex = Mesh::Vertex_index;
using Face = Mesh::Face_index;
using Corners = std::array<Vertex, 4>;

const Point_2 unset(-77, -77); // what the output map holds where nothing was written

/// An output uv map over a const mesh: a vector indexed by vertex index.
struct Uv_vector {
  explicit Uv_vector(const Mesh& m) : mesh(&m), values(m.number_of_vertices(), unset) {}
  auto map() { return boost::make_iterator_property_map(values.begin(), get(boost::vertex_index, *mesh)); }
  const Point_2& operator[](Vertex v) const { return values[std::size_t(v)]; }
  const Mesh* mesh;
  std::vector<Point_2> values;
};

std::vector<Face> all_faces(const Mesh& m) { return std::vector<Face>(m.faces().begin(), m.faces().end()); }

std::vector<Cgal_method> fixed_border_methods()
{
  return {Cgal_method::tutte, Cgal_method::mean_value, Cgal_method::discrete_authalic, Cgal_method::discrete_conformal};
}

Corners grid_corners(std::size_t nx, std::size_t i0, std::size_t i1, std::size_t j0, std::size_t j1)
{
  return {grid_vertex(nx, i0, j0), grid_vertex(nx, i1, j0), grid_vertex(nx, i1, j1), grid_vertex(nx, i0, j1)};
}

/// nefertiti's corners from CGAL's selection file, put in our order: the first
/// listed goes to (0,0), the others counter-clockwise (see the README).
diffuv::Four_sides<Vertex> nefertiti_sides(const Mesh& m)
{
  const std::string file = data_path("selections/square_corners.selection.txt");
  const auto listed = diffuv::selection_vertices(m, diffuv::read_selection_file(file), file);
  Mesh::Halfedge_index border;
  for(auto h : m.halfedges())
    if(m.is_border(h)) border = h;
  diffuv::Four_sides<Vertex> sides;
  EXPECT_TRUE(diffuv::sides_from_corners(diffuv::counterclockwise_boundary(m, border), listed, sides));
  return sides;
}

/// Total signed uv area of the faces, in the faces' vertex order (> 0: counter-clockwise, not mirrored).
double total_signed_area(const Mesh& m, const std::vector<Face>& faces, const Uv_vector& uv)
{
  double sum = 0;
  for(Face f : faces) sum += signed_uv_area(m, f, [&](Vertex v) { return uv[v]; });
  return sum;
}

/// The Dirichlet energy of the piecewise-linear map, by the cotangent formula:
/// 1/4 sum over the faces' corners of cot(angle) |uv of the opposite edge|^2.
double dirichlet_energy(const Mesh& m, const std::vector<Face>& faces, const Uv_vector& uv)
{
  double energy = 0;
  for(Face f : faces) {
    std::array<Vertex, 3> v;
    int k = 0;
    for(Vertex x : CGAL::vertices_around_face(m.halfedge(f), m)) v[k++] = x;
    for(int i = 0; i < 3; ++i) {
      const Vertex a = v[i], b = v[(i + 1) % 3], c = v[(i + 2) % 3];
      const Kernel::Vector_3 e1 = m.point(b) - m.point(a), e2 = m.point(c) - m.point(a);
      const double cot = (e1 * e2) / std::sqrt(CGAL::cross_product(e1, e2).squared_length());
      energy += 0.25 * cot * (uv[b] - uv[c]).squared_length();
    }
  }
  return energy;
}

TEST(CgalCompare, MethodNamesAreShortStableAndRoundTrip)
{
  const std::vector<std::string> expected = {"tutte", "mean_value", "authalic", "conformal", "lscm", "arap"};
  ASSERT_EQ(diffuv::all_cgal_methods.size(), expected.size());
  for(std::size_t i = 0; i < expected.size(); ++i) {
    const Cgal_method m = diffuv::all_cgal_methods[i];
    EXPECT_EQ(diffuv::method_name(m), expected[i]);
    EXPECT_EQ(diffuv::cgal_method_from_name(expected[i]), m);
    EXPECT_EQ(diffuv::has_fixed_border(m), i < 4) << expected[i];
  }
  EXPECT_FALSE(diffuv::cgal_method_from_name("Tutte").has_value());
}

// A regular grid is reproduced exactly by any weights that are symmetric in
// each (centrally symmetric) vertex ring, Tutte's uniform ones included; the
// arc-length square border puts the border vertices at their grid positions.
TEST(CgalCompare, RegularGridIsReproducedWithCornersOnTheSquare)
{
  const std::size_t nx = 12, ny = 5; // cells 1/12 by 1/5: not square
  const Mesh m = make_grid(nx, ny);
  const auto faces = all_faces(m);
  const Corners corners = grid_corners(nx, 0, nx, 0, ny);
  const std::array<Point_2, 4> square = {Point_2(0, 0), Point_2(1, 0), Point_2(1, 1), Point_2(0, 1)};
  for(Cgal_method method : fixed_border_methods()) {
    SCOPED_TRACE(diffuv::method_name(method));
    Uv_vector uv(m);
    const auto r = diffuv::cgal_parameterize_patch(m, faces, corners, method, uv.map());
    ASSERT_TRUE(r.ok()) << "error code " << r.error;
    EXPECT_EQ(r.vertices.size(), m.number_of_vertices());
    EXPECT_EQ(r.uv.size(), r.vertices.size());
    EXPECT_GT(r.milliseconds, 0);
    EXPECT_GT(r.extraction_milliseconds, 0);
    for(int c = 0; c < 4; ++c) { // exactly, not within a tolerance
      EXPECT_EQ(uv[corners[c]].x(), square[c].x()) << "corner " << c;
      EXPECT_EQ(uv[corners[c]].y(), square[c].y()) << "corner " << c;
    }
    double worst = 0;
    for(Vertex v : m.vertices()) {
      worst = std::max(worst, std::abs(uv[v].x() - m.point(v).x()));
      worst = std::max(worst, std::abs(uv[v].y() - m.point(v).y()));
    }
    EXPECT_LT(worst, 1e-9);
    // The struct holds the same uv as the map.
    for(std::size_t i = 0; i < r.vertices.size(); ++i) EXPECT_EQ(r.uv[i], uv[r.vertices[i]]);
  }
}

// The same grid with corners given from another vertex: corners[i] still
// lands on our position i, and (u,v) turn with them (u along corners[0] -> [1]).
TEST(CgalCompare, RotatedCornersRotateTheChart)
{
  const std::size_t n = 6;
  const Mesh m = make_grid(n, n);
  const Corners corners = {grid_vertex(n, n, 0), grid_vertex(n, n, n), grid_vertex(n, 0, n), grid_vertex(n, 0, 0)};
  for(Cgal_method method : fixed_border_methods()) {
    SCOPED_TRACE(diffuv::method_name(method));
    Uv_vector uv(m);
    ASSERT_TRUE(diffuv::cgal_parameterize_patch(m, all_faces(m), corners, method, uv.map()).ok());
    for(Vertex v : m.vertices()) { // a quarter turn: u = y, v = 1 - x
      EXPECT_NEAR(uv[v].x(), m.point(v).y(), 1e-9);
      EXPECT_NEAR(uv[v].y(), 1 - m.point(v).x(), 1e-9);
    }
  }
}

// Mean value and cotangent weights have linear precision: a flat patch whose
// border already lies on (an affine image of) the square is reproduced
// exactly, whatever its triangles. Tutte's uniform weights are not. The patch
// is a jittered 2 x 1 rectangle tilted in 3D; the mesh's own points are
// something else, so this also checks that the given point map is used.
TEST(CgalCompare, FlatJitteredPatchLinearPrecisionUsesThePointMap)
{
  const std::size_t nx = 10, ny = 8;
  Mesh m = make_grid(nx, ny);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> jitter(-0.2, 0.2);
  std::vector<Point_2> plane(m.number_of_vertices()); // the chart we expect: (X / 2, Y)
  for(std::size_t j = 0; j <= ny; ++j)
    for(std::size_t i = 0; i <= nx; ++i) {
      double x = double(i), y = double(j);
      const bool border_i = i == 0 || i == nx, border_j = j == 0 || j == ny;
      if(!border_i) x += jitter(rng); // border vertices slide along their side only
      if(!border_j) y += jitter(rng);
      plane[j * (nx + 1) + i] = Point_2(x / nx, y / ny);
    }
  for(Face f : m.faces()) // the jitter kept every triangle counter-clockwise
    ASSERT_GT(signed_uv_area(m, f, [&](Vertex v) { return plane[std::size_t(v)]; }), 0);

  // X = 2 u, Y = v in the plane through o spanned by the orthonormal e1, e2.
  const Kernel::Vector_3 e1(2. / 3, 2. / 3, 1. / 3), e2(-2. / 3, 1. / 3, 2. / 3), o(1, -2, 0.5);
  std::vector<Point_3> positions;
  for(const Point_2& p : plane) positions.push_back(CGAL::ORIGIN + o + 2 * p.x() * e1 + p.y() * e2);
  for(Vertex v : m.vertices()) m.point(v) = Point_3(0, 0, double(std::size_t(v) % 3)); // not a surface
  const auto vpm = boost::make_iterator_property_map(positions.begin(), get(boost::vertex_index, m));

  const auto faces = all_faces(m);
  const Corners corners = grid_corners(nx, 0, nx, 0, ny);
  auto error = [&](Cgal_method method) {
    Uv_vector uv(m);
    const auto r = diffuv::cgal_parameterize_patch(m, faces, vpm, corners, method, uv.map());
    EXPECT_TRUE(r.ok()) << diffuv::method_name(method);
    double worst = 0;
    for(Vertex v : m.vertices())
      worst = std::max({worst, std::abs(uv[v].x() - plane[std::size_t(v)].x()),
                        std::abs(uv[v].y() - plane[std::size_t(v)].y())});
    return worst;
  };
  EXPECT_LT(error(Cgal_method::mean_value), 1e-9);
  EXPECT_LT(error(Cgal_method::discrete_conformal), 1e-9);
  EXPECT_GT(error(Cgal_method::tutte), 1e-3); // uniform weights ignore the geometry
}

// nefertiti with CGAL's square corners: every fixed-border map is injective
// (Tutte and mean value by theorem: convex border); every corner and side
// lands where ours do; the cotangent map has the least Dirichlet energy of the four.
TEST(CgalCompare, NefertitiFixedBorderMethodsAreInjectiveWithOurCornersAndSides)
{
  const Mesh& m = cgal_mesh("nefertiti.off");
  const auto sides = nefertiti_sides(m);
  const auto faces = all_faces(m);
  const std::array<Point_2, 4> square = {Point_2(0, 0), Point_2(1, 0), Point_2(1, 1), Point_2(0, 1)};
  std::vector<double> energy;
  ASSERT_EQ(fixed_border_methods().back(), Cgal_method::discrete_conformal);
  for(Cgal_method method : fixed_border_methods()) {
    SCOPED_TRACE(diffuv::method_name(method));
    Uv_vector uv(m);
    const auto r = diffuv::cgal_parameterize_patch(m, faces, sides.corners, method, uv.map());
    ASSERT_TRUE(r.ok()) << "error code " << r.error;
    ASSERT_EQ(r.vertices.size(), m.number_of_vertices());
    for(int c = 0; c < 4; ++c) EXPECT_EQ(uv[sides.corners[c]], square[c]) << "corner " << c;
    // Our sides: v1 on v = 0, u2 on u = 1, v2 on v = 1, u1 on u = 0, exactly,
    // with u increasing along v1 (arc length from corners[0]).
    for(Vertex v : sides.v1) EXPECT_EQ(uv[v].y(), 0);
    for(Vertex v : sides.u2) EXPECT_EQ(uv[v].x(), 1);
    for(Vertex v : sides.v2) EXPECT_EQ(uv[v].y(), 1);
    for(Vertex v : sides.u1) EXPECT_EQ(uv[v].x(), 0);
    for(std::size_t k = 1; k < sides.v1.size(); ++k) EXPECT_GT(uv[sides.v1[k]].x(), uv[sides.v1[k - 1]].x());
    for(Vertex v : m.vertices()) {
      EXPECT_GE(uv[v].x(), -1e-12);
      EXPECT_LE(uv[v].x(), 1 + 1e-12);
      EXPECT_GE(uv[v].y(), -1e-12);
      EXPECT_LE(uv[v].y(), 1 + 1e-12);
    }
    EXPECT_GT(total_signed_area(m, faces, uv), 0); // not mirrored
    const auto d = diffuv::measure_distortion(m, m.points(), faces, uv.map());
    // A theorem for Tutte and mean value; authalic and cotangent weights can
    // be negative and fold in general, but do not on this mesh.
    EXPECT_TRUE(d.injective()) << d.flipped << " flipped, " << d.degenerate << " degenerate, "
                               << d.overlapping_pairs << " overlapping pairs";
    energy.push_back(dirichlet_energy(m, faces, uv));
  }
  // All four share the same border values; the cotangent (harmonic) map is
  // the one that minimises the Dirichlet energy among maps with those values.
  const double conformal = energy[3];
  for(std::size_t k = 0; k < 3; ++k) EXPECT_LT(conformal, energy[k] * (1 + 1e-9)) << k;
  EXPECT_LT(conformal, energy[0] * 0.999); // strictly better than Tutte's here
}

// LSCM and ARAP leave the border free: they ignore the corners (any values)
// and are not mirrored; ARAP post-processes to a one-to-one map.
TEST(CgalCompare, NefertitiFreeBorderMethods)
{
  const Mesh& m = cgal_mesh("nefertiti.off");
  const auto faces = all_faces(m);
  const Corners no_corners = {Vertex(), Vertex(), Vertex(), Vertex()};
  for(Cgal_method method : {Cgal_method::lscm, Cgal_method::arap}) {
    SCOPED_TRACE(diffuv::method_name(method));
    Uv_vector uv(m);
    const auto r = diffuv::cgal_parameterize_patch(m, faces, no_corners, method, uv.map());
    ASSERT_TRUE(r.ok()) << "error code " << r.error;
    for(Vertex v : m.vertices()) {
      EXPECT_NE(uv[v], unset);
      EXPECT_TRUE(std::isfinite(uv[v].x()) && std::isfinite(uv[v].y()));
    }
    EXPECT_GT(total_signed_area(m, faces, uv), 0);
    const auto d = diffuv::measure_distortion(m, m.points(), faces, uv.map());
    EXPECT_EQ(d.flipped, 0u);
    EXPECT_EQ(d.overlapping_pairs, 0u);
    EXPECT_LT(d.angle_mean, 1.5);
  }
}

// Half of a grid as a patch of the whole: its vertices (and no other) are
// mapped, and the half is reproduced like a whole grid.
TEST(CgalCompare, HalfGridPatchMapsItsVerticesOnly)
{
  const std::size_t nx = 10, ny = 6, half = 5;
  const Mesh m = make_grid(nx, ny);
  std::vector<Face> left;
  for(Face f : m.faces())
    if(m.point(m.target(m.halfedge(f))).x() <= 0.5 && m.point(m.source(m.halfedge(f))).x() <= 0.5 &&
       m.point(m.target(m.next(m.halfedge(f)))).x() <= 0.5)
      left.push_back(f);
  ASSERT_EQ(left.size(), 2 * half * ny);
  const Corners corners = grid_corners(nx, 0, half, 0, ny);
  for(Cgal_method method : diffuv::all_cgal_methods) {
    SCOPED_TRACE(diffuv::method_name(method));
    Uv_vector uv(m);
    const auto r = diffuv::cgal_parameterize_patch(m, left, corners, method, uv.map());
    ASSERT_TRUE(r.ok()) << "error code " << r.error;
    EXPECT_EQ(r.vertices.size(), (half + 1) * (ny + 1));
    for(std::size_t j = 0; j <= ny; ++j)
      for(std::size_t i = 0; i <= nx; ++i) {
        const Vertex v = grid_vertex(nx, i, j);
        if(i > half) {
          EXPECT_EQ(uv[v], unset) << i << "," << j;
          continue;
        }
        ASSERT_NE(uv[v], unset) << i << "," << j;
        if(diffuv::has_fixed_border(method)) {
          EXPECT_NEAR(uv[v].x(), double(i) / half, 1e-9);
          EXPECT_NEAR(uv[v].y(), double(j) / ny, 1e-9);
        }
      }
    EXPECT_GT(total_signed_area(m, left, uv), 0);
  }
}

// A patch of diffuv's own automatic segmentation of cow, with the corners of
// region_sides(): exactly its vertices are mapped, corners exact, and the
// convex-border methods (Tutte, mean value) do not fold.
TEST(CgalCompare, SegmentationPatchOfCow)
{
  const Mesh& m = cgal_mesh("cow.off");
  diffuv::Segmentation<Mesh> seg;
  ASSERT_TRUE(diffuv::disc_patches(m, m.points(), {}, seg));
  ASSERT_GT(seg.number_of_patches(), 1u);
  std::size_t p = 0; // the largest patch
  for(std::size_t q = 1; q < seg.number_of_patches(); ++q)
    if(seg.patch_faces[q].size() > seg.patch_faces[p].size()) p = q;
  diffuv::Four_sides<Vertex> sides;
  ASSERT_TRUE(diffuv::region_sides(m, m.points(), seg, p, sides));
  const auto& faces = seg.patch_faces[p];
  std::set<Vertex> patch_vertices;
  for(Face f : faces)
    for(Vertex v : CGAL::vertices_around_face(m.halfedge(f), m)) patch_vertices.insert(v);

  const std::array<Point_2, 4> square = {Point_2(0, 0), Point_2(1, 0), Point_2(1, 1), Point_2(0, 1)};
  for(Cgal_method method : diffuv::all_cgal_methods) {
    SCOPED_TRACE(diffuv::method_name(method));
    Uv_vector uv(m);
    const auto r = diffuv::cgal_parameterize_patch(m, faces, sides.corners, method, uv.map());
    ASSERT_TRUE(r.ok()) << "error code " << r.error;
    EXPECT_EQ(std::set<Vertex>(r.vertices.begin(), r.vertices.end()), patch_vertices);
    EXPECT_EQ(r.vertices.size(), patch_vertices.size());
    for(Vertex v : m.vertices()) EXPECT_EQ(uv[v] != unset, patch_vertices.count(v) == 1) << v;
    EXPECT_GT(total_signed_area(m, faces, uv), 0);
    if(diffuv::has_fixed_border(method)) {
      for(int c = 0; c < 4; ++c) EXPECT_EQ(uv[sides.corners[c]], square[c]) << "corner " << c;
    }
    if(method == Cgal_method::tutte || method == Cgal_method::mean_value) {
      const auto d = diffuv::measure_distortion(m, m.points(), faces, uv.map());
      EXPECT_EQ(d.flipped, 0u);
      EXPECT_EQ(d.overlapping_pairs, 0u);
    }
  }
}

void expect_error_everywhere(const Mesh& m, const std::vector<Face>& faces, const Corners& corners,
                             SMP::Error_code expected)
{
  for(Cgal_method method : diffuv::all_cgal_methods) {
    SCOPED_TRACE(diffuv::method_name(method));
    Uv_vector uv(m);
    const auto r = diffuv::cgal_parameterize_patch(m, faces, corners, method, uv.map());
    EXPECT_EQ(r.error, expected) << "error code " << r.error;
    EXPECT_TRUE(r.uv.empty());
    EXPECT_EQ(r.milliseconds, 0); // CGAL was not called
    for(Vertex v : m.vertices()) EXPECT_EQ(uv[v], unset);
  }
}

TEST(CgalCompare, AnnulusIsNotADisc)
{
  const std::size_t n = 6;
  const Mesh m = make_grid(n, n);
  std::vector<Face> ring; // without the 2 x 2 cells in the middle
  for(std::size_t j = 0; j < n; ++j)
    for(std::size_t i = 0; i < n; ++i)
      if(!(i >= 2 && i < 4 && j >= 2 && j < 4)) {
        const std::size_t f = 2 * (j * n + i); // make_grid adds two faces per cell, row by row
        ring.push_back(Face(Mesh::size_type(f)));
        ring.push_back(Face(Mesh::size_type(f + 1)));
      }
  ASSERT_EQ(ring.size(), 2 * (n * n - 4));
  expect_error_everywhere(m, ring, grid_corners(n, 0, n, 0, n), SMP::ERROR_NO_TOPOLOGICAL_DISC);
}

TEST(CgalCompare, ClosedMeshIsNotADisc)
{
  const Mesh& m = cgal_mesh("octahedron.off");
  ASSERT_EQ(m.number_of_faces(), 8u);
  const Corners corners = {Vertex(0), Vertex(1), Vertex(2), Vertex(3)};
  expect_error_everywhere(m, all_faces(m), corners, SMP::ERROR_NO_TOPOLOGICAL_DISC);
}

TEST(CgalCompare, DisconnectedAndPinchedPatchesAreNotDiscs)
{
  const std::size_t n = 3;
  const Mesh m = make_grid(n, n);
  auto cell_faces = [&](std::size_t i, std::size_t j) {
    return std::vector<Face>{Face(Mesh::size_type(2 * (j * n + i))), Face(Mesh::size_type(2 * (j * n + i) + 1))};
  };
  // Two cells touching at a vertex only.
  std::vector<Face> two = cell_faces(0, 0);
  for(Face f : cell_faces(1, 1)) two.push_back(f);
  expect_error_everywhere(m, two, grid_corners(n, 0, 1, 0, 1), SMP::ERROR_NO_TOPOLOGICAL_DISC);

  // The ring of cells around the middle one, less the upper-left triangle of
  // cell (1,0): connected through edges, but its boundary passes twice through
  // vertex (1,0).
  std::vector<Face> pinched;
  for(std::size_t j = 0; j < n; ++j)
    for(std::size_t i = 0; i < n; ++i)
      if(!(i == 1 && j == 1))
        for(Face f : cell_faces(i, j))
          if(!(i == 1 && j == 0 && std::size_t(f) % 2 == 1)) pinched.push_back(f);
  ASSERT_EQ(pinched.size(), 15u);
  expect_error_everywhere(m, pinched, grid_corners(n, 0, n, 0, n), SMP::ERROR_NO_TOPOLOGICAL_DISC);
}

TEST(CgalCompare, EmptyAndNonTriangularPatches)
{
  const Mesh grid = make_grid(2, 2);
  expect_error_everywhere(grid, {}, grid_corners(2, 0, 2, 0, 2), SMP::ERROR_EMPTY_MESH);

  Mesh quads;
  std::vector<Vertex> v;
  for(int j = 0; j < 2; ++j)
    for(int i = 0; i < 3; ++i) v.push_back(quads.add_vertex(Point_3(i, j, 0)));
  quads.add_face(v[0], v[1], v[4], v[3]);
  quads.add_face(v[1], v[2], v[5], v[4]);
  expect_error_everywhere(quads, all_faces(quads), {v[0], v[2], v[5], v[3]}, SMP::ERROR_NON_TRIANGULAR_MESH);
}

// A patch whose points all coincide: CGAL's LSCM would crash on it; every
// method reports that no system can be solved.
TEST(CgalCompare, CoincidentPointsAreAnErrorNotACrash)
{
  Mesh grid = make_grid(3, 3);
  for(Vertex v : vertices(grid)) grid.point(v) = Point_3(1, 1, 1);
  expect_error_everywhere(grid, all_faces(grid), grid_corners(3, 0, 3, 0, 3), SMP::ERROR_CANNOT_SOLVE_LINEAR_SYSTEM);
}

// Bad corners are reported for the methods that use them, and ignored by LSCM and ARAP.
TEST(CgalCompare, BadCornersAreWrongParameters)
{
  const std::size_t n = 4;
  const Mesh m = make_grid(n, n);
  const auto faces = all_faces(m);
  const Corners good = grid_corners(n, 0, n, 0, n);
  const std::vector<Corners> bad = {
      {good[0], good[3], good[2], good[1]},                 // clockwise: would mirror the chart
      {good[0], good[2], good[1], good[3]},                 // out of order
      {good[0], good[1], good[1], good[3]},                 // twice the same
      {good[0], good[1], grid_vertex(n, 2, 2), good[3]},    // an interior vertex
      {good[0], good[1], good[2], Vertex(1000)}};           // not in the patch
  for(const Corners& corners : bad)
    for(Cgal_method method : diffuv::all_cgal_methods) {
      SCOPED_TRACE(diffuv::method_name(method));
      Uv_vector uv(m);
      const auto r = diffuv::cgal_parameterize_patch(m, faces, corners, method, uv.map());
      if(diffuv::has_fixed_border(method)) {
        EXPECT_EQ(r.error, SMP::ERROR_WRONG_PARAMETER) << "error code " << r.error;
        EXPECT_EQ(uv[good[0]], unset);
      } else {
        EXPECT_TRUE(r.ok()) << "error code " << r.error;
      }
    }
}

} // namespace
