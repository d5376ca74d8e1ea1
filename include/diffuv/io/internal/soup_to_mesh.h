// diffuv: a checked polygon soup into a CGAL::Surface_mesh in one linear
// pass, with the connectivity CGAL's own builder gives.
//
// `CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh()` adds the
// polygons one by one with `Euler::add_face()`, which looks each edge up by
// walking around its vertex and relinks the border as it grows: about 0.45 µs
// a face, a third of reading a 1M-vertex OFF file (doc/performance.md). For a
// soup that is already a manifold, consistently oriented polygon mesh (what
// read_triangle_mesh() has made sure of before it builds), the whole result
// can be computed at once. It must be CGAL's result exactly, halfedge for
// halfedge: the layout's tie-breaks walk around vertices starting at
// `halfedge(v)`, so another numbering could give another atlas. What
// `Euler::add_face()` leaves, polygon by polygon in order, is:
// - edge e is the e-th pair of vertices met (polygons in order, each
//   polygon's edges in order), its halfedge 2e running the way that first
//   polygon runs it;
// - a face's halfedge is the one from its last corner to its first;
// - next is the polygon's next corner inside a face, and on the border the
//   border halfedge leaving the vertex a border halfedge enters (unique on a
//   manifold);
// - `halfedge(v)` is the border halfedge entering v on the border; inside,
//   the halfedge entering v of the last polygon (in order) that uses v: that
//   polygon closes the last gap around v, whose entering border halfedge
//   `adjust_incoming_halfedge()` had chosen, and nothing moves it after.
// `IoSoupToMesh.*` (test_io_read_mesh.cpp) checks every array against CGAL's
// builder on real meshes and on random soups with holes, polygons, several
// components, isolated points and shuffled polygons.
#ifndef DIFFUV_IO_INTERNAL_SOUP_TO_MESH_H
#define DIFFUV_IO_INTERNAL_SOUP_TO_MESH_H

#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

namespace diffuv {
namespace internal {

// Whether a polygon lists a point twice: pairwise for the usual few corners,
// by sorting a copy for long ones.
template <class Polygon>
bool used_twice(const Polygon& polygon)
{
  const std::size_t n = polygon.size();
  if(n <= 8) {
    for(std::size_t a = 0; a < n; ++a)
      for(std::size_t b = a + 1; b < n; ++b)
        if(polygon[a] == polygon[b]) return true;
    return false;
  }
  std::vector<std::size_t> sorted(polygon.begin(), polygon.end());
  std::sort(sorted.begin(), sorted.end());
  return std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end();
}

// Builds `mesh` (cleared first) from a soup whose polygons have at least three
// distinct points each and form a manifold, consistently oriented polygon mesh;
// every point becomes a vertex, in order, and polygon j becomes face j.
// \returns false, leaving `mesh` empty, if the soup is not such a mesh (an
//          index out of range, a point used twice in a polygon, an edge run
//          the same way twice, an edge of three or more polygons, a vertex
//          where polygons meet in more than one fan): the caller then uses
//          CGAL's builder (read_triangle_mesh() has refused all of these before)
template <class P, class Point, class Polygon>
bool soup_to_surface_mesh(const std::vector<Point>& points, const std::vector<Polygon>& polygons, CGAL::Surface_mesh<P>& mesh)
{
  using Mesh = CGAL::Surface_mesh<P>;
  using Vertex = typename Mesh::Vertex_index;
  using Halfedge = typename Mesh::Halfedge_index;
  using Face = typename Mesh::Face_index;
  using Index = std::uint32_t;
  constexpr Index none = (std::numeric_limits<Index>::max)();
  CGAL::clear(mesh);
  const std::size_t nv = points.size(), nf = polygons.size();
  // Scratch arrays are written whole before they are read, so they are not
  // zeroed first: on a 1M-vertex mesh, fresh memory is most of the cost.
  auto array = [](std::size_t n) { return std::unique_ptr<Index[]>(new Index[n]); };
  // Corners in polygon order: corner c0 + i of polygon j runs from its point i
  // to point i + 1.
  std::vector<Index> first_corner(nf + 1, 0);
  for(std::size_t j = 0; j < nf; ++j) {
    const auto& polygon = polygons[j];
    if(polygon.size() < 3) return false;
    for(std::size_t a = 0; a < polygon.size(); ++a)
      if(polygon[a] >= nv) return false;
    if(used_twice(polygon)) return false;  // Euler::add_face() leaves such a polygon out
    // Halfedge indices keep their top bit free (it marks the border below).
    if(first_corner[j] + polygon.size() >= none / 4) return false;
    first_corner[j + 1] = first_corner[j] + static_cast<Index>(polygon.size());
  }
  const std::size_t nc = first_corner[nf];
  if(nv >= none) return false;
  // Each corner's end point, and the corners leaving each vertex in
  // compressed rows.
  const auto target = array(nc), leaving = array(nc);
  std::vector<Index> row(nv + 1, 0);
  for(std::size_t j = 0; j < nf; ++j) {
    const auto& polygon = polygons[j];
    const std::size_t n = polygon.size();
    for(std::size_t i = 0; i < n; ++i) {
      target[first_corner[j] + i] = static_cast<Index>(polygon[(i + 1) % n]);
      ++row[polygon[i] + 1];
    }
  }
  for(std::size_t v = 0; v < nv; ++v) row[v + 1] += row[v];
  {
    std::vector<Index> fill(row.begin(), row.end() - 1);
    for(std::size_t j = 0; j < nf; ++j)
      for(std::size_t i = 0; i < polygons[j].size(); ++i) leaving[fill[polygons[j][i]]++] = first_corner[j] + static_cast<Index>(i);
  }
  // Each corner's halfedge: the opposite corner's, turned, if that came
  // first; else a new edge's first halfedge. The top bit marks a corner
  // without an opposite one, whose turned halfedge is a border halfedge.
  constexpr Index on_border = Index(1) << 31;
  const auto halfedge_of = array(nc);
  Index edges = 0;
  for(std::size_t j = 0; j < nf; ++j) {
    const auto& polygon = polygons[j];
    for(std::size_t i = 0; i < polygon.size(); ++i) {
      const Index c = first_corner[j] + static_cast<Index>(i), a = static_cast<Index>(polygon[i]), b = target[c];
      Index opposite = none;
      for(Index k = row[b]; k < row[b + 1]; ++k)
        if(target[leaving[k]] == a) {
          if(opposite != none) return false;  // an edge of three or more polygons
          opposite = leaving[k];
        }
      for(Index k = row[a]; k < row[a + 1]; ++k)
        if(leaving[k] != c && target[leaving[k]] == b) return false;  // an edge run the same way twice
      if(opposite == none) halfedge_of[c] = (2 * edges++) | on_border;
      else halfedge_of[c] = opposite < c ? ((halfedge_of[opposite] & ~on_border) ^ 1u) : 2 * edges++;
    }
  }
  // The border halfedge leaving and entering each vertex (at most one each on
  // a manifold), and the halfedge entering it in the last polygon that uses it.
  std::vector<Index> border_leaving(nv, none), entering(nv, none);
  std::vector<char> on_the_border(nv, 0);
  for(std::size_t j = 0; j < nf; ++j) {
    const auto& polygon = polygons[j];
    for(std::size_t i = 0; i < polygon.size(); ++i) {
      const Index c = first_corner[j] + static_cast<Index>(i), a = static_cast<Index>(polygon[i]), b = target[c];
      if(!on_the_border[b]) entering[b] = halfedge_of[c] & ~on_border;
      if(!(halfedge_of[c] & on_border)) continue;
      const Index border = (halfedge_of[c] & ~on_border) ^ 1u;  // from b to a
      if(border_leaving[b] != none || on_the_border[a]) return false;  // two gaps at a vertex
      border_leaving[b] = border;
      entering[a] = border;
      on_the_border[a] = 1;
    }
  }

  using size_type = typename Mesh::size_type;
  mesh.reserve(static_cast<size_type>(nv), static_cast<size_type>(edges), static_cast<size_type>(nf));
  for(const auto& p : points) mesh.add_vertex(CGAL::Polygon_mesh_processing::internal::convert_to_pm_point<P>(p));
  for(Index e = 0; e < edges; ++e) mesh.add_edge();
  for(std::size_t j = 0; j < nf; ++j) {
    const Face f = mesh.add_face();
    const auto& polygon = polygons[j];
    const std::size_t n = polygon.size();
    const Index c0 = first_corner[j];
    for(std::size_t i = 0; i < n; ++i) {
      const Index c = c0 + static_cast<Index>(i);
      const Halfedge h(halfedge_of[c] & ~on_border);
      mesh.set_target(h, Vertex(target[c]));
      mesh.set_face(h, f);
      mesh.set_next(h, Halfedge(halfedge_of[c0 + (i + 1) % n] & ~on_border));
      if(!(halfedge_of[c] & on_border)) continue;
      const Halfedge border = mesh.opposite(h);
      mesh.set_target(border, Vertex(static_cast<Index>(polygon[i])));
      mesh.set_face(border, Mesh::null_face());
      mesh.set_next(border, Halfedge(border_leaving[polygon[i]]));
    }
    mesh.set_halfedge(f, Halfedge(halfedge_of[c0 + n - 1] & ~on_border));
  }
  for(std::size_t v = 0; v < nv; ++v)
    if(entering[v] != none) mesh.set_halfedge(Vertex(static_cast<Index>(v)), Halfedge(entering[v]));
  // A vertex where the polygons meet in several fans, all closed but one at
  // most (two cones on one apex), passes the checks above; the walk around it
  // then misses some of its polygons. CGAL's builder would drop polygons there.
  for(std::size_t v = 0; v < nv; ++v) {
    if(entering[v] == none) continue;
    const Index expected = (row[v + 1] - row[v]) + (on_the_border[v] ? 1 : 0);
    Index around = 0;
    const Halfedge start(entering[v]);
    Halfedge h = start;
    do {
      ++around;
      h = mesh.opposite(mesh.next(h));
    } while(h != start && around <= expected);
    if(around != expected) {
      CGAL::clear(mesh);
      return false;
    }
  }
  return true;
}

// The soup as a mesh, with CGAL's builder for meshes other than
// `CGAL::Surface_mesh` and for soups `soup_to_surface_mesh()` refuses.
template <class TriangleMesh, class Point, class Polygon>
void soup_to_mesh(const std::vector<Point>& points, const std::vector<Polygon>& polygons, TriangleMesh& mesh)
{
  CGAL::clear(mesh);
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons, mesh);
}

template <class P, class Point, class Polygon>
void soup_to_mesh(const std::vector<Point>& points, const std::vector<Polygon>& polygons, CGAL::Surface_mesh<P>& mesh)
{
  if(soup_to_surface_mesh(points, polygons, mesh)) return;
  CGAL::clear(mesh);
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons, mesh);
}

} // namespace internal
} // namespace diffuv

#endif // DIFFUV_IO_INTERNAL_SOUP_TO_MESH_H
