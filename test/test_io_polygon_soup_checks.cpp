// Tests of include/diffuv/io/internal/polygon_soup_checks.h: the linear check
// that a soup is a manifold, consistently oriented polygon mesh answers as
// CGAL's is_polygon_soup_a_polygon_mesh() does (the independent reference),
// on real meshes and on thousands of damaged copies of them.
#include "test_data.h"

#include <diffuv/io/internal/polygon_soup_checks.h>

#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

namespace {

using Soup = std::vector<std::vector<std::size_t>>;

Soup soup_of(const diffuv_test::Mesh& m)
{
  Soup soup;
  for(auto f : faces(m)) {
    std::vector<std::size_t> polygon;
    for(auto v : CGAL::vertices_around_face(halfedge(f, m), m)) polygon.push_back(v);
    soup.push_back(polygon);
  }
  return soup;
}

bool has_distinct_corners(const Soup& soup)
{
  for(auto p : soup) {
    std::sort(p.begin(), p.end());
    if(p.size() < 3 || std::adjacent_find(p.begin(), p.end()) != p.end()) return false;
  }
  return true;
}

TEST(IoPolygonSoupChecks, RealMeshesAreManifoldSoups)
{
  for(const char* name : {"cow.off", "nefertiti.off", "mushroom.off", "elephant.off"}) {
    const diffuv_test::Mesh& m = diffuv_test::cgal_mesh(name);
    const Soup soup = soup_of(m);
    EXPECT_TRUE(diffuv::internal::is_manifold_oriented_soup(soup, m.number_of_vertices())) << name;
    EXPECT_TRUE(CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(soup)) << name;
  }
}

// Damage of every kind that makes a soup non-manifold or misoriented: a face
// flipped, repeated or removed (holes make boundary vertices with two fans
// when two holes touch), two vertices glued, a face of a copy added at a
// vertex; the answers of both checks agree on each damaged soup.
TEST(IoPolygonSoupChecks, AnswersAsCgalOnDamagedSoups)
{
  std::mt19937 random(20261204);
  std::size_t checked = 0, refused = 0;
  for(const char* name : {"cow.off", "nefertiti.off"}) {
    const diffuv_test::Mesh& m = diffuv_test::cgal_mesh(name);
    const Soup original = soup_of(m);
    const std::size_t nv = m.number_of_vertices();
    for(int trial = 0; trial < 600; ++trial) {
      Soup soup = original;
      std::uniform_int_distribution<std::size_t> face(0, soup.size() - 1), vertex(0, nv - 1);
      const int damages = 1 + trial % 4;
      for(int d = 0; d < damages; ++d) {
        switch(random() % 5) {
          case 0: { auto& p = soup[face(random)]; std::reverse(p.begin(), p.end()); break; }
          case 1: soup.push_back(soup[face(random)]); break;
          case 2: soup.erase(soup.begin() + static_cast<std::ptrdiff_t>(face(random))); break;
          case 3: { // glue vertex a onto b
            const std::size_t a = vertex(random), b = vertex(random);
            for(auto& p : soup) std::replace(p.begin(), p.end(), a, b);
            break;
          }
          case 4: { // a triangle joining a vertex to a new pair of points
            soup.push_back({vertex(random), nv, nv + 1});
            break;
          }
        }
      }
      if(!has_distinct_corners(soup)) continue; // checked before, by check_polygon_soup()
      const bool cgal = CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(soup);
      EXPECT_EQ(diffuv::internal::is_manifold_oriented_soup(soup, nv + 2), cgal) << name << " trial " << trial;
      ++checked;
      refused += cgal ? 0 : 1;
    }
  }
  // Both answers occur often enough for the comparison to mean something.
  EXPECT_GT(checked, 800u);
  EXPECT_GT(refused, 200u);
  EXPECT_GT(checked - refused, 50u);
}

TEST(IoPolygonSoupChecks, TwoFansAtAVertexAndAnEdgeUsedTwiceAreRefused)
{
  // Two triangles meeting at vertex 0 only (a bow tie).
  EXPECT_FALSE(diffuv::internal::is_manifold_oriented_soup({{0, 1, 2}, {0, 3, 4}}, 5));
  // Two triangles with edge 0 -> 1 both ways round: misoriented.
  EXPECT_FALSE(diffuv::internal::is_manifold_oriented_soup({{0, 1, 2}, {0, 1, 3}}, 4));
  // Consistently oriented, they are a mesh.
  EXPECT_TRUE(diffuv::internal::is_manifold_oriented_soup({{0, 1, 2}, {1, 0, 3}}, 4));
  // A closed fan (a tetrahedron), and one with an isolated point.
  EXPECT_TRUE(diffuv::internal::is_manifold_oriented_soup({{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {1, 3, 2}}, 5));
  // Two closed fans glued at a vertex (two tetrahedra sharing vertex 0).
  EXPECT_FALSE(diffuv::internal::is_manifold_oriented_soup(
      {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {1, 3, 2}, {0, 4, 5}, {0, 5, 6}, {0, 6, 4}, {4, 6, 5}}, 7));
}

} // namespace
