// diffuv: the checks of a polygon soup read from a mesh file, before a mesh
// is built from it: nothing is repaired, merged or reoriented, so that the
// vertex indices stay those of the file; a soup that would need it is
// refused, naming the element and its line.
#ifndef DIFFUV_IO_INTERNAL_POLYGON_SOUP_CHECKS_H
#define DIFFUV_IO_INTERNAL_POLYGON_SOUP_CHECKS_H

#include <diffuv/core/error.h>
#include <diffuv/internal/message_text.h>
#include <diffuv/io/internal/mesh_scan.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace diffuv {
namespace internal {

/// Names one reason why a soup whose polygons have at least three distinct,
/// valid vertices is not a manifold oriented polygon mesh: CGAL's
/// `is_polygon_soup_a_polygon_mesh()` only answers yes or no. Sets `face` to
/// the face concerned, or to `std::size_t(-1)` if it is about a vertex.
/// Returns an empty string if it finds nothing.
inline std::string describe_non_manifold(const std::vector<std::vector<std::size_t>>& polygons,
                                         std::size_t nb_points, std::size_t& face)
{
  face = std::size_t(-1);
  // An oriented edge used twice: three faces on one edge, or two faces
  // that disagree on the orientation.
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> edge_face;
  for(std::size_t j = 0; j < polygons.size(); ++j) {
    const auto& p = polygons[j];
    for(std::size_t c = 0; c < p.size(); ++c) {
      const std::pair<std::size_t, std::size_t> e(p[c], p[(c + 1) % p.size()]);
      const auto [it, inserted] = edge_face.emplace(e, j);
      if(!inserted) {
        face = j;
        return "faces " + std::to_string(it->second) + " and " + std::to_string(j) +
               " both go from vertex " + std::to_string(e.first) + " to vertex " + std::to_string(e.second);
      }
    }
  }

  // Around a vertex v, each face (.., b, v, a, ..) links a to b; neighbouring
  // faces share a link end. With each oriented edge used once, the links form
  // paths and cycles, one per fan of faces: a manifold vertex has one fan.
  std::vector<std::vector<std::pair<std::size_t, std::size_t>>> links(nb_points);
  for(const auto& p : polygons)
    for(std::size_t c = 0; c < p.size(); ++c)
      links[p[c]].emplace_back(p[(c + 1) % p.size()], p[(c + p.size() - 1) % p.size()]);
  for(std::size_t v = 0; v < nb_points; ++v) {
    auto& link = links[v];
    if(link.size() < 2)
      continue;
    std::sort(link.begin(), link.end());
    std::vector<std::size_t> heads; // link ends that no link leads to: starts of paths
    std::vector<std::size_t> targets;
    for(const auto& l : link)
      targets.push_back(l.second);
    std::sort(targets.begin(), targets.end());
    for(const auto& l : link)
      if(!std::binary_search(targets.begin(), targets.end(), l.first))
        heads.push_back(l.first);
    std::vector<bool> used(link.size(), false);
    auto walk = [&](std::size_t from) {
      for(;;) {
        const auto it = std::lower_bound(link.begin(), link.end(), std::make_pair(from, std::size_t(0)));
        if(it == link.end() || it->first != from || used[it - link.begin()])
          return;
        used[it - link.begin()] = true;
        from = it->second;
      }
    };
    std::size_t fans = 0;
    for(std::size_t h : heads) {
      walk(h);
      ++fans;
    }
    for(std::size_t l = 0; l < link.size(); ++l)
      if(!used[l]) {
        walk(link[l].first); // a cycle
        ++fans;
      }
    if(fans > 1)
      return "the faces around vertex " + std::to_string(v) + " form " + std::to_string(fans) + " separate fans";
  }
  return std::string();
}

/// True if the polygons (each of at least three distinct vertices, all below
/// `nb_points`) form a manifold, consistently oriented polygon mesh: each
/// oriented edge is used once, and the faces around each vertex form one fan.
/// It answers what `CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh()`
/// answers, in linear time: CGAL's check (a set of edges, then a search for
/// singular vertices) took a second on a 300k-face mesh, more than reading it.
///
/// Around a vertex v each face (.., b, v, a, ..) gives the link a -> b. An
/// oriented edge v -> a used twice is a repeated link start at v; otherwise
/// the links form paths and cycles, one per fan.
/// With `on_border`, a yes also says which points are on the border (their
/// fan is a path); the answer no leaves it unspecified.
template <class Index>
bool is_manifold_oriented_soup_as(const std::vector<std::vector<std::size_t>>& polygons, std::size_t nb_points,
                                  std::vector<char>* on_border = nullptr)
{
  if(on_border) on_border->assign(nb_points, 0);
  // The links of each vertex, stored vertex by vertex (counting sort), with
  // indices as small as the mesh allows: the pages of fresh memory are what
  // this costs on a large mesh.
  std::vector<std::size_t> first(nb_points + 1, 0);
  for(const auto& p : polygons)
    for(std::size_t v : p) ++first[v + 1];
  for(std::size_t v = 0; v < nb_points; ++v) first[v + 1] += first[v];
  using Link = std::pair<Index, Index>;
  std::vector<Link> links(first[nb_points]);
  {
    std::vector<std::size_t> fill(first.begin(), first.end() - 1);
    for(const auto& p : polygons)
      for(std::size_t c = 0, n = p.size(); c < n; ++c)
        links[fill[p[c]]++] = {static_cast<Index>(p[c + 1 < n ? c + 1 : 0]), static_cast<Index>(p[c > 0 ? c - 1 : n - 1])};
  }

  std::vector<Index> ends;
  for(std::size_t v = 0; v < nb_points; ++v) {
    const auto begin = links.begin() + static_cast<std::ptrdiff_t>(first[v]);
    const auto end = links.begin() + static_cast<std::ptrdiff_t>(first[v + 1]);
    const std::size_t degree = first[v + 1] - first[v];
    if(degree < 2) {
      if(on_border && degree == 1) (*on_border)[v] = 1;
      continue;
    }
    std::sort(begin, end);
    for(auto it = begin + 1; it != end; ++it)
      if(it->first == (it - 1)->first) return false; // an oriented edge used twice
    ends.clear();
    for(auto it = begin; it != end; ++it) ends.push_back(it->second);
    std::sort(ends.begin(), ends.end());
    // A path starts at a link start that no link ends at; a fan without such
    // a start is a cycle. Walk the fan from there: one fan covers all links.
    Index start = begin->first;
    std::size_t paths = 0;
    for(auto it = begin; it != end; ++it)
      if(!std::binary_search(ends.begin(), ends.end(), it->first)) {
        start = it->first;
        if(++paths > 1) return false;
      }
    std::size_t walked = 0;
    for(Index at = start; walked < degree; ++walked) {
      const auto it = std::lower_bound(begin, end, Link(at, Index(0)));
      if(it == end || it->first != at) break;
      at = it->second;
      if(paths == 0 && at == start) { ++walked; break; } // the cycle closed
    }
    if(walked != degree) return false;
    if(on_border && paths == 1) (*on_border)[v] = 1;
  }
  return true;
}

inline bool is_manifold_oriented_soup(const std::vector<std::vector<std::size_t>>& polygons, std::size_t nb_points,
                                      std::vector<char>* on_border = nullptr)
{
  if(nb_points < (std::size_t(1) << 32))
    return is_manifold_oriented_soup_as<std::uint32_t>(polygons, nb_points, on_border);
  return is_manifold_oriented_soup_as<std::size_t>(polygons, nb_points, on_border);
}

/// Checks the soup of `path`, in file order so that the first problem is
/// reported: at least one face; finite coordinates; faces of at least three
/// vertex indices, in range and distinct; coordinates a double can compute
/// with; a manifold, consistently oriented polygon mesh. `locate` gives the
/// lines. With `scan_quotes_indices` (OBJ, whose indices count from 1 or
/// back from the end), an index out of range is reported as the scan quotes
/// it, as written in the file. With `repair_follows`, a face that uses a
/// point twice and a soup that is not a manifold oriented mesh are left to
/// `repair_polygon_soup()`.
/// \returns whether each point is used by a face
/// \throws Input_error naming `path` (see `read_triangle_mesh()`)
template <class Point>
std::vector<bool> check_polygon_soup(const std::string& path, const std::vector<Point>& points,
                                     const std::vector<std::vector<std::size_t>>& polygons, Line_locator& locate,
                                     bool scan_quotes_indices, bool repair_follows = false)
{
  using Polygon = std::vector<std::size_t>;
  if(polygons.empty())
    throw Input_error(path, 0, "the file has no face");
  for(std::size_t i = 0; i < points.size(); ++i) {
    const Point& p = points[i];
    if(!std::isfinite(CGAL::to_double(p.x())) || !std::isfinite(CGAL::to_double(p.y())) ||
       !std::isfinite(CGAL::to_double(p.z())))
      throw Input_error(path, locate.vertex_line(i), non_finite_message(i));
  }
  std::vector<bool> used(points.size(), false);
  for(std::size_t j = 0; j < polygons.size(); ++j) {
    const Polygon& polygon = polygons[j];
    if(polygon.size() < 3)
      throw Input_error(path, locate.face_line(j), "face " + std::to_string(j) + " has only " +
                                                      count_text(polygon.size(), "vertex", "vertices"));
    for(std::size_t index : polygon) {
      if(index >= points.size()) {
        // CGAL's OBJ reader lets the index one past the last vertex through;
        // the scan quotes the index as written.
        if(scan_quotes_indices && !locate.scan().error.empty())
          throw Input_error(path, locate.scan().error_line, locate.scan().error);
        throw Input_error(path, locate.face_line(j),
                          out_of_range_message(j, index_text(index), points.size()));
      }
    }
    // A triangle is compared pair by pair; a longer polygon sorted (the
    // smallest repeated index is the one named).
    const bool triangle_repeats =
        polygon.size() == 3 && (polygon[0] == polygon[1] || polygon[1] == polygon[2] || polygon[0] == polygon[2]);
    if(!repair_follows && (polygon.size() > 3 || triangle_repeats)) {
      Polygon sorted = polygon;
      std::sort(sorted.begin(), sorted.end());
      const auto twice = std::adjacent_find(sorted.begin(), sorted.end());
      if(twice != sorted.end())
        throw Input_error(path, locate.face_line(j), "face " + std::to_string(j) + " uses vertex " +
                                                        std::to_string(*twice) + " twice");
    }
    for(std::size_t index : polygon)
      used[index] = true;
  }
  // Scale: lengths are squared and areas multiplied in double precision, so
  // a mesh far beyond 1e60 or within 1e-60 gives infinities or zeros (every
  // vertex at the centre of the square): refuse it rather than answer wrong.
  {
    constexpr double largest = 1e60, smallest = 1e-60;
    double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    for(std::size_t i = 0; i < points.size(); ++i) {
      if(!used[i]) continue;
      const double c[3] = {CGAL::to_double(points[i].x()), CGAL::to_double(points[i].y()),
                           CGAL::to_double(points[i].z())};
      for(int k = 0; k < 3; ++k) {
        if(std::abs(c[k]) > largest) {
          std::ostringstream what;
          what << "vertex " << i << " has a coordinate of " << c[k]
               << ", too large to compute with (beyond 1e60): rescale the mesh";
          throw Input_error(path, locate.vertex_line(i), what.str());
        }
        lo[k] = (std::min)(lo[k], c[k]);
        hi[k] = (std::max)(hi[k], c[k]);
      }
    }
    const double extent = (std::max)({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
    if(extent < smallest) {
      std::ostringstream what;
      what << "the mesh is too small to compute with (it spans " << extent << ", under 1e-60): rescale the mesh";
      throw Input_error(path, 0, what.str());
    }
  }
  if(!repair_follows && !is_manifold_oriented_soup(polygons, points.size())) {
    std::size_t face = 0;
    const std::string detail = describe_non_manifold(polygons, points.size(), face);
    // Unwelded copies of a point (common in STL exports and scans) are the
    // usual cause: say so, with the first pair.
    std::string hint;
    std::vector<std::size_t> order;
    for(std::size_t i = 0; i < points.size(); ++i)
      if(used[i]) order.push_back(i);
    const auto position = [&](std::size_t i) {
      return std::make_tuple(points[i].x(), points[i].y(), points[i].z());
    };
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return position(a) < position(b); });
    std::size_t first = std::size_t(-1), second = 0;
    for(std::size_t k = 1; k < order.size(); ++k)
      if(position(order[k - 1]) == position(order[k]) && (std::min)(order[k - 1], order[k]) < first) {
        first = (std::min)(order[k - 1], order[k]);
        second = (std::max)(order[k - 1], order[k]);
      }
    if(first != std::size_t(-1))
      hint = "; vertices " + std::to_string(first) + " and " + std::to_string(second) +
             " have the same position: the mesh may need welding";
    throw Input_error(path, face == std::size_t(-1) ? 0 : locate.face_line(face),
                      "non-manifold edge or vertex, or inconsistent orientation" +
                          (detail.empty() ? std::string() : " (" + detail + ")") + hint);
  }
  return used;
}

} // namespace internal
} // namespace diffuv

#endif // DIFFUV_IO_INTERNAL_POLYGON_SOUP_CHECKS_H
