// Tests of diffuv/metrics/distortion.h: known answers on procedural charts
// (isometry, scale, shear, non-uniform scale, flips, overlaps), CGAL's own
// mean-value parameterization of a real mesh, an O(F^2) exact overlap count,
// and Eigen's SVD for the closed-form singular values.
#include <diffuv/metrics/distortion.h>
#include <diffuv/metrics/texture_use.h>

#include "test_data.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh_parameterization/Mean_value_coordinates_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>
#include <CGAL/intersections.h>

#include <Eigen/Dense>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

namespace {

using diffuv_test::Mesh;
using diffuv_test::Point_2;
using diffuv_test::Point_3;
using Vertex = Mesh::Vertex_index;
using Face = Mesh::Face_index;
using Uv_map = Mesh::Property_map<Vertex, Point_2>;

constexpr double tol = 1e-12;

Uv_map add_uv(Mesh& m) { return m.add_property_map<Vertex, Point_2>("v:uv", Point_2(0, 0)).first; }

std::vector<Face> all_faces(const Mesh& m) { return std::vector<Face>(m.faces().begin(), m.faces().end()); }

// A plane through (1,-2,0.5) tilted in 3D, with an orthonormal frame (e1, e2):
// plane coordinates (x, y) are then an isometric (u,v) of the surface.
Point_3 embed(const Point_2& xy)
{
  const double e1[3] = {1.0 / 3, 2.0 / 3, 2.0 / 3};
  const double e2[3] = {2.0 / 3, 1.0 / 3, -2.0 / 3};
  return Point_3(1 + xy.x() * e1[0] + xy.y() * e2[0], -2 + xy.x() * e1[1] + xy.y() * e2[1],
                 0.5 + xy.x() * e1[2] + xy.y() * e2[2]);
}

// Grid of nx x ny squares of side h in the tilted plane. Vertex (i,j) has
// index i + (nx+1) j; square (i,j) gives faces 2(i + nx j) (lower right,
// (i,j)(i+1,j)(i+1,j+1)) and 2(i + nx j) + 1 (upper left), both
// counter-clockwise in plane coordinates. Returns the plane coordinates.
std::vector<Point_2> fill_square_grid(Mesh& m, int nx, int ny, double h)
{
  std::vector<Point_2> xy;
  std::vector<Vertex> v;
  for(int j = 0; j <= ny; ++j)
    for(int i = 0; i <= nx; ++i) {
      xy.emplace_back(i * h, j * h);
      v.push_back(m.add_vertex(embed(xy.back())));
    }
  auto id = [&](int i, int j) { return v[i + (nx + 1) * j]; };
  for(int j = 0; j < ny; ++j)
    for(int i = 0; i < nx; ++i) {
      m.add_face(id(i, j), id(i + 1, j), id(i + 1, j + 1));
      m.add_face(id(i, j), id(i + 1, j + 1), id(i, j + 1));
    }
  return xy;
}

// uv = M xy + t, with M = [[a, b], [c, d]].
void set_affine_uv(const Mesh& m, Uv_map uv, const std::vector<Point_2>& xy, double a, double b, double c, double d,
                   double tx = 0, double ty = 0)
{
  for(Vertex v : m.vertices()) {
    const Point_2& p = xy[v.idx()];
    put(uv, v, Point_2(a * p.x() + b * p.y() + tx, c * p.x() + d * p.y() + ty));
  }
}

// Measures a 4 x 3 grid of squares of side 0.25 mapped by uv = M xy + t.
diffuv::Distortion_summary measure_affine(double a, double b, double c, double d,
                                          std::vector<diffuv::Triangle_distortion>* per_face)
{
  Mesh m;
  const std::vector<Point_2> xy = fill_square_grid(m, 4, 3, 0.25);
  Uv_map uv = add_uv(m);
  set_affine_uv(m, uv, xy, a, b, c, d, 0.3, -1.7);
  return diffuv::measure_distortion(m, m.points(), all_faces(m), uv, per_face);
}

// Every face, and the summary, have the given angle, area and stretch.
void expect_uniform(const diffuv::Distortion_summary& s, const std::vector<diffuv::Triangle_distortion>& per_face,
                    double angle, double area, double l2, double linf)
{
  ASSERT_EQ(per_face.size(), s.faces);
  for(const auto& t : per_face) {
    EXPECT_NEAR(t.angle, angle, tol * angle);
    EXPECT_NEAR(t.area, area, tol);
    EXPECT_NEAR(t.stretch_l2, l2, tol * l2);
    EXPECT_NEAR(t.stretch_linf, linf, tol * linf);
    EXPECT_FALSE(t.flipped);
    EXPECT_FALSE(t.degenerate);
  }
  EXPECT_NEAR(s.angle_mean, angle, tol * angle);
  EXPECT_NEAR(s.angle_max, angle, tol * angle);
  EXPECT_NEAR(s.area_mean, area, tol);
  EXPECT_NEAR(s.area_max, area, tol);
  EXPECT_NEAR(s.stretch_l2, l2, tol * l2);
  EXPECT_NEAR(s.stretch_linf, linf, tol * linf);
  EXPECT_EQ(s.flipped, 0u);
  EXPECT_EQ(s.degenerate, 0u);
  EXPECT_EQ(s.overlapping_pairs, 0u);
  EXPECT_TRUE(s.injective());
}

// A mesh of two separate triangles, whose uv are given; returns the overlap count.
std::size_t overlaps_of_two(const std::array<Point_2, 3>& a, const std::array<Point_2, 3>& b)
{
  Mesh m;
  Uv_map uv = add_uv(m);
  for(const auto* t : {&a, &b}) {
    std::array<Vertex, 3> v;
    for(int k = 0; k < 3; ++k) {
      v[k] = m.add_vertex(Point_3(k == 1, k == 2, t == &b));
      put(uv, v[k], (*t)[k]);
    }
    m.add_face(v[0], v[1], v[2]);
  }
  return diffuv::count_overlapping_pairs(m, all_faces(m), uv);
}

// CGAL's mean value coordinates with its default circular border: a convex
// border, hence a provably injective map (Floater 2003).
Uv_map parameterize_mvc(Mesh& m)
{
  namespace SMP = CGAL::Surface_mesh_parameterization;
  Uv_map uv = add_uv(m);
  const auto border = CGAL::Polygon_mesh_processing::longest_border(m).first;
  const SMP::Error_code err = SMP::parameterize(m, SMP::Mean_value_coordinates_parameterizer_3<Mesh>(), border, uv);
  EXPECT_EQ(err, SMP::OK);
  return uv;
}

// Whether two uv triangles' interiors overlap, decided independently of the
// library: CGAL's exact intersection of the two triangles has positive area.
bool brute_force_overlap(const std::array<Point_2, 3>& a, const std::array<Point_2, 3>& b)
{
  using EK = CGAL::Exact_predicates_exact_constructions_kernel;
  auto tri = [](const std::array<Point_2, 3>& t) {
    return EK::Triangle_2(EK::Point_2(t[0].x(), t[0].y()), EK::Point_2(t[1].x(), t[1].y()),
                          EK::Point_2(t[2].x(), t[2].y()));
  };
  const auto result = CGAL::intersection(tri(a), tri(b));
  if(!result) return false;
  if(const EK::Triangle_2* t = boost::get<EK::Triangle_2>(&*result)) return !t->is_degenerate();
  if(const auto* poly = boost::get<std::vector<EK::Point_2>>(&*result)) {
    EK::FT twice_area = 0;
    for(std::size_t i = 0; i < poly->size(); ++i) {
      const EK::Point_2& p = (*poly)[i];
      const EK::Point_2& q = (*poly)[(i + 1) % poly->size()];
      twice_area += p.x() * q.y() - q.x() * p.y();
    }
    return twice_area != 0;
  }
  return false; // a point or a segment: the triangles only touch
}

std::array<Point_2, 3> uv_triangle(const Mesh& m, Face f, Uv_map uv)
{
  std::array<Point_2, 3> t;
  int k = 0;
  for(Vertex v : CGAL::vertices_around_face(m.halfedge(f), m)) t[k++] = get(uv, v);
  return t;
}

} // namespace

TEST(Metrics, SingularValuesMatchEigen)
{
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> coef(-2, 2);
  for(int n = 0; n < 200; ++n) {
    Eigen::Matrix2d j;
    j << coef(rng), coef(rng), coef(rng), coef(rng);
    const Eigen::Vector2d ref = Eigen::JacobiSVD<Eigen::Matrix2d>(j).singularValues();
    const auto sv = diffuv::internal::singular_values_2x2(j(0, 0), j(0, 1), j(1, 0), j(1, 1));
    EXPECT_NEAR(sv.first, ref(0), 1e-12);
    EXPECT_NEAR(sv.second, ref(1), 1e-12);
  }
}

TEST(Metrics, TriangleLaidFlatIsAnIsometry)
{
  // A triangle in general position, unfolded by the law of cosines.
  Mesh m;
  const Point_3 p[3] = {Point_3(0.3, -1, 2), Point_3(1.7, 0.2, 1.1), Point_3(-0.4, 0.9, 2.6)};
  const double c = std::sqrt(CGAL::squared_distance(p[0], p[1]));
  const double b = std::sqrt(CGAL::squared_distance(p[0], p[2]));
  const double a = std::sqrt(CGAL::squared_distance(p[1], p[2]));
  const double x = (b * b + c * c - a * a) / (2 * c);
  const Point_2 q[3] = {Point_2(5, 5), Point_2(5 + c, 5), Point_2(5 + x, 5 + std::sqrt(b * b - x * x))};
  Uv_map uv = add_uv(m);
  std::array<Vertex, 3> v;
  for(int k = 0; k < 3; ++k) {
    v[k] = m.add_vertex(p[k]);
    put(uv, v[k], q[k]);
  }
  m.add_face(v[0], v[1], v[2]);
  std::vector<diffuv::Triangle_distortion> per_face;
  const auto s = diffuv::measure_distortion(m, m.points(), all_faces(m), uv, &per_face);
  ASSERT_EQ(per_face.size(), 1u);
  EXPECT_NEAR(per_face[0].area_3d, CGAL::Polygon_mesh_processing::area(m), tol);
  EXPECT_NEAR(per_face[0].signed_area_uv, per_face[0].area_3d, 1e-12);
  expect_uniform(s, per_face, 1, 1, 1, 1);
}

TEST(Metrics, IsometryOfTiltedGrid)
{
  const double c = std::cos(0.6), s = std::sin(0.6);
  std::vector<diffuv::Triangle_distortion> per_face;
  const auto sum = measure_affine(c, -s, s, c, &per_face);
  EXPECT_EQ(sum.faces, 24u);
  double area = 0;
  for(const auto& t : per_face) {
    EXPECT_NEAR(t.signed_area_uv, t.area_3d, 1e-14);
    EXPECT_NEAR(t.area_3d, 0.25 * 0.25 / 2, 1e-14);
    area += t.area_3d;
  }
  EXPECT_NEAR(area, 1.0 * 0.75, 1e-13);
  expect_uniform(sum, per_face, 1, 1, 1, 1);
}

TEST(Metrics, UniformScaleScoresOne)
{
  // 3.7 times a rotation: every measure is normalised by the chart's scale.
  const double k = 3.7, c = std::cos(2.0), s = std::sin(2.0);
  std::vector<diffuv::Triangle_distortion> per_face;
  const auto sum = measure_affine(k * c, -k * s, k * s, k * c, &per_face);
  for(const auto& t : per_face) EXPECT_NEAR(t.signed_area_uv, k * k * t.area_3d, 1e-13);
  expect_uniform(sum, per_face, 1, 1, 1, 1);
}

TEST(Metrics, ShearMatchesAnalyticValue)
{
  // [[1, k], [0, 1]] has J^T J = [[1, k], [k, 1 + k^2]], whose eigenvalues give
  // sigma = (sqrt(k^2 + 4) +- k) / 2. det = 1, so the scale normalisation is 1,
  // and uv -> 3D has Gamma = 1/sigma_min = sigma_max, gamma = sigma_min.
  const double k = 0.75, r = std::sqrt(k * k + 4);
  const double s_max = (r + k) / 2, s_min = (r - k) / 2;
  std::vector<diffuv::Triangle_distortion> per_face;
  const auto sum = measure_affine(1, k, 0, 1, &per_face);
  expect_uniform(sum, per_face, (r + k) / (r - k), 1, std::sqrt((s_max * s_max + s_min * s_min) / 2), s_max);
  EXPECT_NEAR(std::sqrt((s_max * s_max + s_min * s_min) / 2), std::sqrt((2 + k * k) / 2), tol);
}

TEST(Metrics, NonUniformScaleAngleIsTheRatio)
{
  const double a = 3, b = 0.5, scale = std::sqrt(a * b);
  std::vector<diffuv::Triangle_distortion> per_face;
  const auto sum = measure_affine(a, 0, 0, b, &per_face);
  expect_uniform(sum, per_face, a / b, 1, std::sqrt((1 / (a * a) + 1 / (b * b)) / 2) * scale, scale / b);
}

TEST(Metrics, AreaDistortionOfTwoTriangles)
{
  // Unit square (0,1,2)(0,2,3); vertex 1 moved from (1,0) to (2,0) in uv:
  // uv areas 1 and 1/2 (total 3/2) against 3D areas 1/2 and 1/2 (total 1),
  // r = 4/3 and 2/3, so the area distortions are 4/3 and 3/2.
  Mesh m;
  Uv_map uv = add_uv(m);
  const double xy[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  std::array<Vertex, 4> v;
  for(int k = 0; k < 4; ++k) {
    v[k] = m.add_vertex(embed(Point_2(xy[k][0], xy[k][1])));
    put(uv, v[k], Point_2(xy[k][0], xy[k][1]));
  }
  put(uv, v[1], Point_2(2, 0));
  m.add_face(v[0], v[1], v[2]);
  m.add_face(v[0], v[2], v[3]);
  std::vector<diffuv::Triangle_distortion> per_face;
  const auto s = diffuv::measure_distortion(m, m.points(), all_faces(m), uv, &per_face);
  ASSERT_EQ(per_face.size(), 2u);
  EXPECT_NEAR(per_face[0].area, 4.0 / 3, tol);
  EXPECT_NEAR(per_face[1].area, 1.5, tol);
  EXPECT_NEAR(s.area_mean, 17.0 / 12, tol);
  EXPECT_NEAR(s.area_max, 1.5, tol);
  EXPECT_NEAR(per_face[1].angle, 1, tol); // the untouched face is only scaled
  EXPECT_GT(per_face[0].angle, 1.5);
  EXPECT_GT(s.stretch_l2, 1);
  EXPECT_TRUE(s.injective());
}

TEST(Metrics, MirrorImageIsNotFlipped)
{
  // Every face is clockwise: the majority orientation is clockwise, no face is flipped.
  std::vector<diffuv::Triangle_distortion> per_face;
  const auto sum = measure_affine(-1, 0, 0, 1, &per_face);
  for(const auto& t : per_face) EXPECT_NEAR(t.signed_area_uv, -t.area_3d, 1e-14);
  expect_uniform(sum, per_face, 1, 1, 1, 1);
}

TEST(Metrics, OneFlippedTriangle)
{
  // 2 x 1 unit squares. Vertex (2,0) belongs to face 2 only; moving it to
  // (1.2, 0.8) turns face 2 clockwise, inside face 3.
  Mesh m;
  const std::vector<Point_2> xy = fill_square_grid(m, 2, 1, 1.0);
  Uv_map uv = add_uv(m);
  set_affine_uv(m, uv, xy, 1, 0, 0, 1);
  put(uv, Vertex(2), Point_2(1.2, 0.8));
  std::vector<diffuv::Triangle_distortion> per_face;
  const auto s = diffuv::measure_distortion(m, m.points(), all_faces(m), uv, &per_face);
  EXPECT_EQ(s.flipped, 1u);
  ASSERT_EQ(per_face.size(), 4u);
  for(std::size_t i = 0; i < 4; ++i) EXPECT_EQ(per_face[i].flipped, i == 2) << "face " << i;
  EXPECT_LT(per_face[2].signed_area_uv, 0);
  EXPECT_EQ(s.overlapping_pairs, 1u);
  EXPECT_EQ(diffuv::count_overlapping_pairs(m, all_faces(m), uv), 1u);
  EXPECT_EQ(s.degenerate, 0u);
  EXPECT_FALSE(s.injective());

  // The flipped face keeps the angle distortion of its mirror image.
  for(Vertex v : m.vertices()) put(uv, v, Point_2(-get(uv, v).x(), get(uv, v).y()));
  std::vector<diffuv::Triangle_distortion> mirrored;
  diffuv::measure_distortion(m, m.points(), std::vector<Face>{Face(2)}, uv, &mirrored);
  ASSERT_EQ(mirrored.size(), 1u);
  EXPECT_FALSE(mirrored[0].flipped);
  EXPECT_GT(mirrored[0].signed_area_uv, 0);
  EXPECT_NEAR(per_face[2].angle, mirrored[0].angle, tol);
  // J = [[0.2, 0.8], [0.8, 0.2]]: eigenvalues 1 and -0.6, so the angle is 1 / 0.6.
  EXPECT_NEAR(per_face[2].angle, 5.0 / 3, tol);
}

TEST(Metrics, TwoOverlappingTriangles)
{
  using T = std::array<Point_2, 3>;
  const T base{Point_2(0, 0), Point_2(2, 0), Point_2(0, 2)};
  // Overlapping interiors.
  EXPECT_EQ(overlaps_of_two(base, T{Point_2(0.5, 0.5), Point_2(3, 0.5), Point_2(0.5, 3)}), 1u);
  EXPECT_EQ(overlaps_of_two(base, T{Point_2(0.2, 0.2), Point_2(0.6, 0.2), Point_2(0.2, 0.6)}), 1u); // inside
  EXPECT_EQ(overlaps_of_two(base, base), 1u);                                                           // identical
  EXPECT_EQ(overlaps_of_two(base, T{Point_2(0, 0), Point_2(0, 2), Point_2(2, 0)}), 1u);               // clockwise copy
  EXPECT_EQ(overlaps_of_two(base, T{Point_2(0, 0), Point_2(2, 0), Point_2(0.5, 0.5)}), 1u);           // same edge, same side
  EXPECT_EQ(overlaps_of_two(base, T{Point_2(1, 1), Point_2(2, 0), Point_2(0, 0)}), 1u);               // apex on the edge
  EXPECT_EQ(overlaps_of_two(T{Point_2(0, 0), Point_2(3, 0), Point_2(1.5, 3)},
                            T{Point_2(0, 2), Point_2(1.5, -1), Point_2(3, 2)}), 1u); // star of David, no vertex inside
  // Interiors apart.
  EXPECT_EQ(overlaps_of_two(base, T{Point_2(2, 0), Point_2(2, 2), Point_2(0, 2)}), 0u);   // shared edge, other side
  EXPECT_EQ(overlaps_of_two(base, T{Point_2(2, 0), Point_2(4, 0), Point_2(3, 1)}), 0u);   // shared vertex
  EXPECT_EQ(overlaps_of_two(base, T{Point_2(1, 1), Point_2(3, 1), Point_2(1, 3)}), 0u);   // vertex on the hypotenuse
  EXPECT_EQ(overlaps_of_two(base, T{Point_2(1.1, 1.1), Point_2(2, 2), Point_2(1.2, 2)}), 0u); // boxes meet, triangles do not
  EXPECT_EQ(overlaps_of_two(base, T{Point_2(5, 5), Point_2(6, 5), Point_2(5, 6)}), 0u);
  // A degenerate triangle has no interior and is skipped.
  EXPECT_EQ(overlaps_of_two(base, T{Point_2(0, 0), Point_2(1, 1), Point_2(2, 2)}), 0u);

  // Through measure_distortion: both faces counter-clockwise, so nothing is flipped.
  Mesh m;
  Uv_map uv = add_uv(m);
  for(int t = 0; t < 2; ++t) {
    std::array<Vertex, 3> v;
    for(int k = 0; k < 3; ++k) {
      v[k] = m.add_vertex(Point_3(k == 1, k == 2, t));
      put(uv, v[k], Point_2((k == 1) + 0.5 * t, (k == 2) + 0.25 * t));
    }
    m.add_face(v[0], v[1], v[2]);
  }
  const auto s = diffuv::measure_distortion(m, m.points(), all_faces(m), uv);
  EXPECT_EQ(s.overlapping_pairs, 1u);
  EXPECT_EQ(s.flipped, 0u);
  EXPECT_FALSE(s.injective());
}

TEST(Metrics, ValidPlanarGridsHaveNoOverlaps)
{
  // The identity grid: every pair of neighbours touches exactly along an edge
  // or at a vertex, and many bounding boxes share a side.
  Mesh m;
  const std::vector<Point_2> xy = fill_square_grid(m, 20, 20, 0.05);
  Uv_map uv = add_uv(m);
  set_affine_uv(m, uv, xy, 1, 0, 0, 1);
  EXPECT_EQ(diffuv::count_overlapping_pairs(m, all_faces(m), uv), 0u);
  EXPECT_TRUE(diffuv::measure_distortion(m, m.points(), all_faces(m), uv).injective());

  // A smooth warp (identity plus a 0.1-Lipschitz term, hence one-to-one).
  for(Vertex v : m.vertices()) {
    const Point_2& p = xy[v.idx()];
    put(uv, v, Point_2(p.x() + 0.1 * std::sin(3 * p.y()) / 3, p.y() + 0.1 * std::sin(3 * p.x()) / 3));
  }
  const auto s = diffuv::measure_distortion(m, m.points(), all_faces(m), uv);
  EXPECT_EQ(s.faces, 800u);
  EXPECT_EQ(s.overlapping_pairs, 0u);
  EXPECT_TRUE(s.injective());
  EXPECT_GT(s.angle_max, 1.01);
}

// measure_distortion() skips the pairwise overlap test where the chart is
// one-to-one by its border: no flipped or degenerate face and the border one
// loop mapped onto a simple polygon. A strip wound one and a half times
// around a circle keeps every triangle's orientation, yet overlaps itself:
// its border crosses itself, so the pairs are counted.
TEST(Metrics, ABorderThatCrossesItselfStillHasItsOverlapsCounted)
{
  Mesh m;
  const int n = 60;  // cells along the strip
  std::vector<Vertex> inner, outer;
  for(int i = 0; i <= n; ++i) {
    inner.push_back(m.add_vertex(Point_3(0.1 * i, 0, 0)));
    outer.push_back(m.add_vertex(Point_3(0.1 * i, 1, 0)));
  }
  for(int i = 0; i < n; ++i) {
    m.add_face(inner[i], inner[i + 1], outer[i + 1]);
    m.add_face(inner[i], outer[i + 1], outer[i]);
  }
  Uv_map uv = add_uv(m);
  auto wind = [&](double turns) {
    for(int i = 0; i <= n; ++i) {
      const double angle = 2 * M_PI * turns * i / n;
      // The strip's first row on the outer circle: counter-clockwise triangles.
      put(uv, inner[i], Point_2(1.5 * std::cos(angle), 1.5 * std::sin(angle)));
      put(uv, outer[i], Point_2(std::cos(angle), std::sin(angle)));
    }
  };
  wind(1.5);
  auto s = diffuv::measure_distortion(m, m.points(), all_faces(m), uv);
  EXPECT_EQ(s.flipped, 0u);
  EXPECT_EQ(s.degenerate, 0u);
  EXPECT_FALSE(diffuv::internal::border_maps_to_simple_polygon(m, all_faces(m), uv));
  EXPECT_GT(s.overlapping_pairs, 0u);
  EXPECT_EQ(s.overlapping_pairs, diffuv::count_overlapping_pairs(m, all_faces(m), uv));
  EXPECT_FALSE(s.injective());

  // Half a turn: one-to-one, shown by the border alone.
  wind(0.5);
  EXPECT_TRUE(diffuv::internal::border_maps_to_simple_polygon(m, all_faces(m), uv));
  s = diffuv::measure_distortion(m, m.points(), all_faces(m), uv);
  EXPECT_TRUE(s.injective());
  EXPECT_EQ(diffuv::count_overlapping_pairs(m, all_faces(m), uv), 0u);
}

// border_maps_to_simple_polygon() finds a chart's faces by marks on their
// indices when the chart is most of its mesh (a disc mapped whole), and in a
// sorted list when it is a small part of a large mesh. The same strip, alone
// in its mesh and after 1,000 unrelated triangles, gets the same answers.
TEST(Metrics, BorderTestAnswersAlikeForAChartThatIsTheMeshAndOneThatIsASmallPart)
{
  auto make_strip = [](Mesh& m, int filler_triangles, double turns) {
    for(int t = 0; t < filler_triangles; ++t)
      m.add_face(m.add_vertex(Point_3(t, 5, 0)), m.add_vertex(Point_3(t + 1, 5, 0)), m.add_vertex(Point_3(t, 6, 0)));
    const int n = 60;
    std::vector<Vertex> inner, outer;
    for(int i = 0; i <= n; ++i) {
      inner.push_back(m.add_vertex(Point_3(0.1 * i, 0, 0)));
      outer.push_back(m.add_vertex(Point_3(0.1 * i, 1, 0)));
    }
    std::vector<Face> strip;
    for(int i = 0; i < n; ++i) {
      strip.push_back(m.add_face(inner[i], inner[i + 1], outer[i + 1]));
      strip.push_back(m.add_face(inner[i], outer[i + 1], outer[i]));
    }
    Uv_map uv = add_uv(m);
    for(int i = 0; i <= n; ++i) {
      const double angle = 2 * M_PI * turns * i / n;
      put(uv, inner[i], Point_2(1.5 * std::cos(angle), 1.5 * std::sin(angle)));
      put(uv, outer[i], Point_2(std::cos(angle), std::sin(angle)));
    }
    return std::make_pair(strip, uv);
  };
  for(const double turns : {0.5, 1.5}) {
    Mesh alone, among_others;
    const auto [strip_a, uv_a] = make_strip(alone, 0, turns);
    const auto [strip_b, uv_b] = make_strip(among_others, 1000, turns);
    ASSERT_GE(std::size_t(strip_b.front()), 1000u);  // indices far beyond 8 x the chart's 120 faces
    const bool simple = turns < 1;
    EXPECT_EQ(diffuv::internal::border_maps_to_simple_polygon(alone, strip_a, uv_a), simple) << turns;
    EXPECT_EQ(diffuv::internal::border_maps_to_simple_polygon(among_others, strip_b, uv_b), simple) << turns;
    // Listed in another order: the same answer; a face listed twice: no answer.
    std::vector<Face> reversed_a(strip_a.rbegin(), strip_a.rend()), reversed_b(strip_b.rbegin(), strip_b.rend());
    EXPECT_EQ(diffuv::internal::border_maps_to_simple_polygon(alone, reversed_a, uv_a), simple) << turns;
    EXPECT_EQ(diffuv::internal::border_maps_to_simple_polygon(among_others, reversed_b, uv_b), simple) << turns;
    std::vector<Face> twice_a = strip_a, twice_b = strip_b;
    twice_a.push_back(strip_a[7]);
    twice_b.push_back(strip_b[7]);
    EXPECT_FALSE(diffuv::internal::border_maps_to_simple_polygon(alone, twice_a, uv_a)) << turns;
    EXPECT_FALSE(diffuv::internal::border_maps_to_simple_polygon(among_others, twice_b, uv_b)) << turns;
    // Either half of the strip (60 of 120 faces, 8 x 60 >= 120: marks) is a
    // simple polygon at half a turn, and still at one and a half (three
    // quarters of a turn each); the second half's neighbours have lower
    // indices, unmarked.
    const std::vector<Face> first_half(strip_a.begin(), strip_a.begin() + 60), second_half(strip_a.begin() + 60, strip_a.end());
    EXPECT_TRUE(diffuv::internal::border_maps_to_simple_polygon(alone, first_half, uv_a)) << turns;
    EXPECT_TRUE(diffuv::internal::border_maps_to_simple_polygon(alone, second_half, uv_a)) << turns;
  }
}

// A chart with a hole has two border loops: the border cannot show it one-to-one.
TEST(Metrics, AChartWithAHoleIsCheckedPairByPair)
{
  Mesh m;
  const std::vector<Point_2> xy = fill_square_grid(m, 4, 4, 0.25);
  Uv_map uv = add_uv(m);
  set_affine_uv(m, uv, xy, 1, 0, 0, 1);
  std::vector<Face> ring;
  for(Face f : m.faces()) {
    const auto h = m.halfedge(f);
    const Point_2 c = CGAL::centroid(xy[m.source(h).idx()], xy[m.target(h).idx()], xy[m.target(m.next(h)).idx()]);
    if(!(c.x() > 0.25 && c.x() < 0.75 && c.y() > 0.25 && c.y() < 0.75)) ring.push_back(f);
  }
  ASSERT_EQ(ring.size(), 32u - 8u);
  EXPECT_TRUE(diffuv::internal::border_maps_to_simple_polygon(m, all_faces(m), uv));
  EXPECT_FALSE(diffuv::internal::border_maps_to_simple_polygon(m, ring, uv));
  const auto s = diffuv::measure_distortion(m, m.points(), ring, uv);
  EXPECT_EQ(s.overlapping_pairs, 0u);
  EXPECT_TRUE(s.injective());
}

TEST(Metrics, DegenerateTriangleIsReportedAndSkipped)
{
  // Vertex (2,0) of the 2 x 1 grid moved onto the segment (1,0)-(2,1): face 2 collapses.
  Mesh m;
  const std::vector<Point_2> xy = fill_square_grid(m, 2, 1, 1.0);
  Uv_map uv = add_uv(m);
  set_affine_uv(m, uv, xy, 1, 0, 0, 1);
  put(uv, Vertex(2), Point_2(1.5, 0.5));
  std::vector<diffuv::Triangle_distortion> per_face;
  const auto s = diffuv::measure_distortion(m, m.points(), all_faces(m), uv, &per_face);
  EXPECT_EQ(s.degenerate, 1u);
  EXPECT_TRUE(per_face[2].degenerate);
  EXPECT_FALSE(per_face[2].flipped);
  EXPECT_TRUE(std::isinf(per_face[2].angle));
  EXPECT_EQ(s.flipped, 0u);
  EXPECT_EQ(s.overlapping_pairs, 0u);
  EXPECT_FALSE(s.injective());
  // The other faces are an isometry; the summary ignores the degenerate one.
  EXPECT_NEAR(s.angle_max, 1, tol);
  EXPECT_TRUE(std::isfinite(s.stretch_linf));
}

TEST(Metrics, PerFaceFollowsRangeOrder)
{
  Mesh m;
  const std::vector<Point_2> xy = fill_square_grid(m, 3, 3, 1.0);
  Uv_map uv = add_uv(m);
  for(Vertex v : m.vertices()) // a non-affine map: faces differ
    put(uv, v, Point_2(xy[v.idx()].x() * (1 + 0.1 * xy[v.idx()].y()), xy[v.idx()].y() + 0.05 * xy[v.idx()].x() * xy[v.idx()].x()));
  std::vector<Face> faces = all_faces(m);
  std::vector<diffuv::Triangle_distortion> forward, backward;
  diffuv::measure_distortion(m, m.points(), faces, uv, &forward);
  std::reverse(faces.begin(), faces.end());
  diffuv::measure_distortion(m, m.points(), faces, uv, &backward);
  ASSERT_EQ(forward.size(), faces.size());
  ASSERT_EQ(backward.size(), faces.size());
  for(std::size_t i = 0; i < faces.size(); ++i) {
    const auto& f = forward[i];
    const auto& b = backward[faces.size() - 1 - i];
    EXPECT_EQ(f.signed_area_uv, b.signed_area_uv);
    EXPECT_EQ(f.angle, b.angle);
    EXPECT_NEAR(f.stretch_l2, b.stretch_l2, tol); // chart totals are summed in another order
  }
  EXPECT_NE(forward.front().angle, forward.back().angle);

  // A sub-range is a chart of its own, normalised by its own areas.
  std::vector<diffuv::Triangle_distortion> one;
  const auto s = diffuv::measure_distortion(m, m.points(), std::vector<Face>{Face(7)}, uv, &one);
  EXPECT_EQ(s.faces, 1u);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(one[0].angle, forward[7].angle);
  EXPECT_NEAR(one[0].area, 1, tol);

  const auto empty = diffuv::measure_distortion(m, m.points(), std::vector<Face>{}, uv, &one);
  EXPECT_EQ(empty.faces, 0u);
  EXPECT_TRUE(one.empty());
  EXPECT_EQ(empty.angle_mean, 0);
}

TEST(Metrics, NefertitiMeanValueChartIsInjective)
{
  Mesh m = diffuv_test::cgal_mesh("nefertiti.off");
  ASSERT_EQ(m.number_of_faces(), 562u);
  Uv_map uv = parameterize_mvc(m);
  std::vector<diffuv::Triangle_distortion> per_face;
  const auto s = diffuv::measure_distortion(m, m.points(), all_faces(m), uv, &per_face);
  EXPECT_EQ(s.faces, 562u);
  EXPECT_EQ(s.flipped, 0u);
  EXPECT_EQ(s.degenerate, 0u);
  EXPECT_EQ(s.overlapping_pairs, 0u);
  EXPECT_EQ(diffuv::count_overlapping_pairs(m, all_faces(m), uv), 0u);
  EXPECT_TRUE(s.injective());
  EXPECT_GE(s.angle_mean, 1);
  EXPECT_GE(s.angle_max, s.angle_mean);
  EXPECT_GT(s.area_max, 1);
  EXPECT_GE(s.stretch_l2, 1); // Sander's normalised L2 stretch is >= 1
  EXPECT_GE(s.stretch_linf, s.stretch_l2 / std::sqrt(2.0));

  // Areas add up: 3D to CGAL's surface area, uv to the area of the border polygon
  // (border halfedges run opposite to the faces, hence the minus sign).
  double area_3d = 0, area_uv = 0, shoelace = 0;
  for(const auto& t : per_face) {
    area_3d += t.area_3d;
    area_uv += t.signed_area_uv;
  }
  const auto border = CGAL::Polygon_mesh_processing::longest_border(m).first;
  for(auto h : CGAL::halfedges_around_face(border, m)) {
    const Point_2 p = get(uv, m.source(h)), q = get(uv, m.target(h));
    shoelace += 0.5 * (p.x() * q.y() - q.x() * p.y());
  }
  EXPECT_NEAR(area_3d, CGAL::Polygon_mesh_processing::area(m), 1e-9 * area_3d);
  EXPECT_NEAR(area_uv, -shoelace, 1e-9 * std::abs(shoelace));
  EXPECT_GT(std::abs(area_uv), 0.5); // a disc of radius 1/2 would give pi/4
}

TEST(Metrics, BoxOverlapCountEqualsBruteForceOnFoldedChart)
{
  Mesh m = diffuv_test::cgal_mesh("nefertiti.off");
  Uv_map uv = parameterize_mvc(m);
  // Fold the chart: push a few interior vertices across their neighbours.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> shift(-0.15, 0.15);
  std::vector<Vertex> interior;
  for(Vertex v : m.vertices())
    if(!m.is_border(v)) interior.push_back(v);
  std::shuffle(interior.begin(), interior.end(), rng);
  for(std::size_t i = 0; i < 12; ++i) {
    const Point_2 p = get(uv, interior[i]);
    put(uv, interior[i], Point_2(p.x() + shift(rng), p.y() + shift(rng)));
  }

  const std::vector<Face> faces = all_faces(m);
  const auto s = diffuv::measure_distortion(m, m.points(), faces, uv);
  ASSERT_EQ(s.degenerate, 0u); // the brute force below skips nothing
  std::vector<std::array<Point_2, 3>> tri;
  for(Face f : faces) tri.push_back(uv_triangle(m, f, uv));
  std::size_t brute = 0;
  for(std::size_t i = 0; i < tri.size(); ++i)
    for(std::size_t j = i + 1; j < tri.size(); ++j)
      if(brute_force_overlap(tri[i], tri[j])) ++brute;

  EXPECT_GT(brute, 0u);
  EXPECT_EQ(s.overlapping_pairs, brute);
  EXPECT_EQ(diffuv::count_overlapping_pairs(m, faces, uv), brute);
  EXPECT_GT(s.flipped, 0u);
  EXPECT_FALSE(s.injective());
}

namespace {

TEST(Distortion, TwoHalvesCombineIntoTheWhole)
{
  // Angle distortion is scale-free, so measuring a chart in two halves and
  // combining them gives the whole chart's counts, angle mean and maximum.
  const Mesh& mesh = diffuv_test::cgal_mesh("mushroom.off");
  std::vector<Point_2> uv;
  std::mt19937 random(3);
  std::uniform_real_distribution<double> jitter(-0.01, 0.01);
  for(Vertex v : vertices(mesh)) uv.emplace_back(mesh.point(v).x() + jitter(random), mesh.point(v).z() + jitter(random));
  const auto uv_map = boost::make_iterator_property_map(uv.begin(), get(boost::vertex_index, mesh));
  const std::vector<Mesh::Face_index> all(faces(mesh).begin(), faces(mesh).end());
  const std::vector<Mesh::Face_index> first(all.begin(), all.begin() + all.size() / 3), second(all.begin() + all.size() / 3, all.end());
  const auto whole = diffuv::measure_distortion(mesh, mesh.points(), all, uv_map);
  const auto a = diffuv::measure_distortion(mesh, mesh.points(), first, uv_map);
  const auto b = diffuv::measure_distortion(mesh, mesh.points(), second, uv_map);
  const auto sum = diffuv::combined(a, b);
  EXPECT_EQ(sum.faces, whole.faces);
  EXPECT_EQ(sum.degenerate, whole.degenerate);
  EXPECT_EQ(sum.flipped, a.flipped + b.flipped); // each half flips against its own majority
  EXPECT_NEAR(sum.measured_area, whole.measured_area, 1e-9 * whole.measured_area);
  EXPECT_NEAR(sum.angle_mean, whole.angle_mean, 1e-9 * whole.angle_mean);
  EXPECT_EQ(sum.angle_max, whole.angle_max);
  EXPECT_GT(sum.angle_mean, 1.);
  // Combining with nothing changes nothing.
  const auto same = diffuv::combined(diffuv::Distortion_summary(), whole);
  EXPECT_EQ(same.angle_mean, whole.angle_mean);
  EXPECT_EQ(same.stretch_l2, whole.stretch_l2);
  EXPECT_EQ(same.overlapping_pairs, whole.overlapping_pairs);
}

} // namespace

TEST(TextureUse, CoveredSharedAndDensityCountedTexelByTexel)
{
  // Chart 0: the left half of the texture, two triangles, 3D area 2.
  // Chart 1: a quarter square in the top right, 3D area 1 (the same density).
  // Chart 2: the bottom right quarter and a strip above it, at twice that
  // density, overlapping chart 1 by the strip.
  using T = diffuv::Uv_triangle_in_chart;
  std::vector<T> t;
  auto square = [&](double x0, double y0, double x1, double y1, double area, std::size_t chart) {
    t.push_back(T{{{{x0, y0}, {x1, y0}, {x1, y1}}}, area / 2, chart});
    t.push_back(T{{{{x0, y0}, {x1, y1}, {x0, y1}}}, area / 2, chart});
  };
  square(0, 0, 0.5, 1, 2., 0);
  square(0.5, 0.5, 1, 1, 1., 1);
  square(0.5, 0., 1, 0.5 + 1. / 16, 0.28125, 2);  // uv area 0.28125 = 3D area: density 64, twice the others
  const diffuv::Texture_use use = diffuv::measure_texture_use(t, 64);
  EXPECT_DOUBLE_EQ(use.covered, 1.);
  // The strip shared by charts 1 and 2: 64 texels wide, 4 rows (y from 0.5 to 0.5625).
  EXPECT_DOUBLE_EQ(use.shared, 4. * 32 / (64 * 64));
  // Densities: 64 * sqrt(0.5 / 2) = 32 for charts 0 and 1, 64 for chart 2.
  EXPECT_NEAR(use.density_median, 32., 1e-9);
  EXPECT_NEAR(use.within_10_percent, 3. / 3.28125, 1e-12);
  EXPECT_NEAR(use.lowest, 1., 1e-12);
  EXPECT_NEAR(use.highest, 2., 1e-9);
  // Outside the unit square nothing is counted; clockwise triangles count as well.
  std::vector<T> outside{T{{{{1.5, 1.5}, {2., 1.5}, {2., 2.}}}, 1., 0}, T{{{{0., 0.}, {0., 0.5}, {0.5, 0.}}}, 1., 1}};
  const diffuv::Texture_use o = diffuv::measure_texture_use(outside, 16);
  // The lower left half of a quarter: texel centres with i + j <= 7, those on the diagonal included.
  EXPECT_DOUBLE_EQ(o.covered, 36. / 256.);
  EXPECT_EQ(o.shared, 0.);
  EXPECT_THROW(diffuv::measure_texture_use(t, 0), std::invalid_argument);
}
