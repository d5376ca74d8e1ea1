// The consumer test's program: uses an installed diffuv (found with
// find_package) to parameterize a flat square grid built here, and checks the
// result. Exits non-zero on any failure. The umbrella header comes first, so
// that it is checked to compile on its own, from the installed tree.
#include <diffuv/diffuv.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using vertex_descriptor = boost::graph_traits<Mesh>::vertex_descriptor;
using Point_2 = diffuv::Uv_atlas<Mesh>::Point_2;

namespace {

int failures = 0;

void check(bool ok, const std::string& what)
{
  if(!ok) {
    std::cerr << "FAILED: " << what << std::endl;
    ++failures;
  }
}

// n x n vertices on [0,1]^2 in the plane z = 0, two triangles per cell,
// counter-clockwise seen from +z. grid[i][j] is the vertex at (i/(n-1), j/(n-1)).
std::vector<std::vector<vertex_descriptor>> make_grid(Mesh& mesh, int n)
{
  std::vector<std::vector<vertex_descriptor>> grid(n, std::vector<vertex_descriptor>(n));
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < n; ++j)
      grid[i][j] = mesh.add_vertex(Kernel::Point_3(double(i) / (n - 1), double(j) / (n - 1), 0.));
  for(int i = 0; i + 1 < n; ++i)
    for(int j = 0; j + 1 < n; ++j) {
      mesh.add_face(grid[i][j], grid[i + 1][j], grid[i + 1][j + 1]);
      mesh.add_face(grid[i][j], grid[i + 1][j + 1], grid[i][j + 1]);
    }
  return grid;
}

// Checks what holds for any corners: one chart, every uv in [0,1]^2, the
// corners on the square's corners, every side on its side, no fold.
template <class UvMap>
void check_map(const Mesh& mesh, const diffuv::Uv_atlas<Mesh>& atlas, const diffuv::Four_sides<vertex_descriptor>& sides,
               const UvMap& uv, const std::string& name)
{
  const double eps = 1e-9;
  check(atlas.number_of_charts() == 1, name + ": one chart");
  for(vertex_descriptor v : vertices(mesh)) {
    const Point_2 p = get(uv, v);
    const bool inside = std::isfinite(p.x()) && std::isfinite(p.y()) && p.x() >= -eps && p.x() <= 1 + eps &&
                        p.y() >= -eps && p.y() <= 1 + eps;
    check(inside, name + ": uv of vertex " + std::to_string(std::size_t(v)) + " in [0,1]^2");
  }
  const std::array<Point_2, 4> square{Point_2(0, 0), Point_2(1, 0), Point_2(1, 1), Point_2(0, 1)};
  for(std::size_t c = 0; c < 4; ++c) {
    const Point_2 p = get(uv, sides.corners[c]);
    std::cout << name << ": corner " << c << " (vertex " << std::size_t(sides.corners[c]) << ") -> (" << p << ")\n";
    check(std::abs(p.x() - square[c].x()) < eps && std::abs(p.y() - square[c].y()) < eps,
          name + ": corner " + std::to_string(c) + " on the square's corner");
  }
  auto on_side = [&](const std::vector<vertex_descriptor>& side, int coordinate, double value, const char* label) {
    check(side.size() >= 2, name + ": side " + label + " has vertices");
    for(vertex_descriptor v : side) {
      const Point_2 p = get(uv, v);
      check(std::abs((coordinate == 0 ? p.x() : p.y()) - value) < eps,
            name + ": vertex " + std::to_string(std::size_t(v)) + " on side " + label);
    }
  };
  on_side(sides.v1, 1, 0., "v = 0");
  on_side(sides.u2, 0, 1., "u = 1");
  on_side(sides.v2, 1, 1., "v = 1");
  on_side(sides.u1, 0, 0., "u = 0");
  std::size_t boundary = sides.v1.size() + sides.u2.size() + sides.v2.size() + sides.u1.size() - 4;
  check(boundary == 4 * (std::size_t(std::sqrt(double(num_vertices(mesh)))) - 1), name + ": sides cover the boundary");

  double area = 0;
  for(auto f : faces(mesh)) {
    std::array<Point_2, 3> t;
    int k = 0;
    for(vertex_descriptor v : vertices_around_face(halfedge(f, mesh), mesh)) t[k++] = get(uv, v);
    const double a = CGAL::area(t[0], t[1], t[2]);
    check(a > 0, name + ": face " + std::to_string(std::size_t(f)) + " keeps its orientation");
    area += a;
  }
  check(std::abs(area - 1) < 1e-6, name + ": the faces cover the unit square (area " + std::to_string(area) + ")");
}

} // namespace

int main()
{
  const int n = 9;

  // Corners chosen by diffuv.
  {
    Mesh mesh;
    make_grid(mesh, n);
    diffuv::Uv_atlas<Mesh> atlas(mesh);
    diffuv::Four_sides<vertex_descriptor> sides;
    diffuv::Disc_parameterization_report<Mesh> disc_report;
    const diffuv::Status status = diffuv::parameterize_disc(mesh, mesh.points(), {}, atlas, {}, &disc_report);
    sides = disc_report.sides;
    check(bool(status), "automatic corners: parameterize_disc: " + status.what());
    if(status) check_map(mesh, atlas, sides, atlas.vertex_uv_map(), "automatic corners");
  }

  // The grid's own corners, counter-clockwise from (0,0): the map of a flat
  // square onto the unit square with its corners fixed is close to the identity.
  {
    Mesh mesh;
    const auto grid = make_grid(mesh, n);
    diffuv::Uv_atlas<Mesh> atlas(mesh);
    diffuv::Four_sides<vertex_descriptor> sides;
    const std::vector<vertex_descriptor> corners{grid[0][0], grid[n - 1][0], grid[n - 1][n - 1], grid[0][n - 1]};
    diffuv::Disc_parameterization_report<Mesh> disc_report;
    const diffuv::Status status = diffuv::parameterize_disc(mesh, mesh.points(), corners, atlas, {}, &disc_report);
    sides = disc_report.sides;
    check(bool(status), "grid corners: parameterize_disc: " + status.what());
    if(status) {
      auto uv = atlas.vertex_uv_map();
      check_map(mesh, atlas, sides, uv, "grid corners");
      for(std::size_t c = 0; c < 4; ++c) check(sides.corners[c] == corners[c], "grid corners: corner kept");
      double worst = 0;
      for(vertex_descriptor v : vertices(mesh)) {
        const Point_2 p = get(uv, v);
        const auto& q = mesh.point(v);
        worst = (std::max)(worst, (std::max)(std::abs(p.x() - q.x()), std::abs(p.y() - q.y())));
      }
      std::cout << "grid corners: largest |uv - xy| = " << worst << "\n";
      check(worst < 0.05, "grid corners: uv close to xy");
    }
  }

  if(failures) {
    std::cerr << failures << " check(s) failed" << std::endl;
    return EXIT_FAILURE;
  }
  std::cout << "diffuv consumer: all checks passed" << std::endl;
  return EXIT_SUCCESS;
}
