// diffuv: the repairs of a polygon soup that reading makes by default, none
// of which moves a point or renumbers the file's points:
//
//   border edges that coincide in pairs are stitched (their points merged
//     into the one of smallest index; the others stay, used by no face)
//   -> faces that use a point twice, and faces that repeat an earlier
//      face's points, are dropped
//   -> faces are oriented consistently, component by component, keeping the
//      orientation of most of each component's faces (a walk over the edges
//      of two faces); a surface that no orientation can make consistent (a
//      Moebius strip) is refused
//   -> the points where faces meet in more than one fan (non-manifold
//      vertices, and the ends of edges of three or more faces) get a copy
//      per extra fan, appended after the file's points
//      (CGAL::Polygon_mesh_processing::orient_polygon_soup(), called only then).
//
// CGAL's repair_polygon_soup() also merges points, but renumbers them;
// diffuv's outputs, label files and selections follow the file's numbering.
#ifndef DIFFUV_IO_INTERNAL_REPAIR_POLYGON_SOUP_H
#define DIFFUV_IO_INTERNAL_REPAIR_POLYGON_SOUP_H

#include <diffuv/core/error.h>
#include <diffuv/internal/index_list_hash.h>
#include <diffuv/internal/message_text.h>
#include <diffuv/io/internal/mesh_scan.h>
#include <diffuv/io/internal/polygon_soup_checks.h>

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <numeric>
#include <string>
#include <tuple>
#include <unordered_set>
#include <utility>
#include <vector>

namespace diffuv {

/// What reading repaired; all zero when the file needed nothing.
struct Mesh_repair_report {
  std::size_t points_merged = 0;      ///< points merged into a coinciding point, stitching two borders into one
  std::size_t degenerate_faces = 0;   ///< faces dropped that use a point twice (in the file, or once stitched)
  std::size_t duplicate_faces = 0;    ///< faces dropped that repeat an earlier face's points
  std::size_t faces_reoriented = 0;   ///< faces whose vertex order was reversed
  std::size_t non_manifold_edges = 0; ///< edges of three or more faces, cut apart
  std::size_t vertices_split = 0;     ///< non-manifold points (faces around them in several fans), split
  std::size_t vertex_copies = 0;      ///< the copies of them added after the file's points, one per extra fan

  bool any() const
  {
    return points_merged + degenerate_faces + duplicate_faces + faces_reoriented + non_manifold_edges +
               vertex_copies > 0;
  }
};

namespace internal {

/// Where the repair put the file's elements. Empty vectors mean "as in the file".
struct Soup_repair_map {
  std::vector<std::size_t> file_polygon;    ///< for each polygon kept, its number in the file
  std::vector<std::size_t> vertex_of_point; ///< for each point of the file, the point its faces now use
  std::vector<std::size_t> point_of_vertex; ///< for each point after the repair, the file's point it copies
};

/// The visitor of CGAL's orient_polygon_soup(): which polygons it turned
/// (none, after diffuv's own walk; kept so that the count stays right), which
/// points it copied.
struct Orientation_record : CGAL::Polygon_mesh_processing::Default_orientation_visitor {
  std::vector<char>* turned = nullptr;
  std::vector<std::pair<std::size_t, std::size_t>>* copies = nullptr; // (point, its copy)

  void polygon_orientation_reversed(std::size_t p) { (*turned)[p] = !(*turned)[p]; }
  void duplicated_vertex(std::size_t point, std::size_t copy) { copies->emplace_back(point, copy); }
};

/// A point's coordinates as a key: points that coincide exactly compare equal.
template <class Point>
std::tuple<double, double, double> position_key(const std::vector<Point>& points, std::size_t i)
{
  return std::make_tuple(CGAL::to_double(points[i].x()), CGAL::to_double(points[i].y()), CGAL::to_double(points[i].z()));
}

/// True when the soup needs none of the repairs: a manifold, consistently
/// oriented polygon mesh, no face using a point twice, no two border points
/// at one position (the first thing stitching would look at).
template <class Point>
bool soup_needs_no_repair(const std::vector<Point>& points, const std::vector<std::vector<std::size_t>>& polygons)
{
  for(const auto& polygon : polygons) {
    if(polygon.size() == 3) {
      if(polygon[0] == polygon[1] || polygon[1] == polygon[2] || polygon[0] == polygon[2]) return false;
      continue;
    }
    std::vector<std::size_t> sorted = polygon;
    std::sort(sorted.begin(), sorted.end());
    if(std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) return false;
  }
  std::vector<char> on_border;
  if(!is_manifold_oriented_soup(polygons, points.size(), &on_border)) return false;
  std::vector<std::size_t> border;
  for(std::size_t i = 0; i < on_border.size(); ++i)
    if(on_border[i]) border.push_back(i);
  const auto position = [&](std::size_t i) { return position_key(points, i); };
  std::sort(border.begin(), border.end(), [&](std::size_t a, std::size_t b) { return position(a) < position(b); });
  for(std::size_t k = 1; k < border.size(); ++k)
    if(position(border[k - 1]) == position(border[k])) return false;
  return true;
}

/// Repairs the soup (see the top of this file) in place: `polygons` loses
/// the faces dropped and has the others oriented and renumbered, `points`
/// gains the copies of non-manifold points. The file's points keep their
/// numbers. Counts go to `report`.
/// \returns the maps from the file's elements to the repaired soup's (empty
///          when nothing was repaired)
/// \throws Input_error naming `path`: "the surface is not orientable ...",
///         "non-manifold edge or vertex left after repair (...)"
template <class Point>
Soup_repair_map repair_polygon_soup(const std::string& path, std::vector<Point>& points,
                                    std::vector<std::vector<std::size_t>>& polygons, Line_locator& locate,
                                    Mesh_repair_report& report)
{
  using Polygon = std::vector<std::size_t>;
  Soup_repair_map map;
  report = Mesh_repair_report();
  if(soup_needs_no_repair(points, polygons)) return map;

  const std::size_t file_points = points.size();
  const auto position = [&](std::size_t i) { return position_key(points, i); };

  // ---- stitching: border edges (edges of one face) that coincide in pairs
  // have their points merged, each into the one of smallest index. Points
  // that merely coincide (two borders touching at a point) are left apart.
  std::vector<std::size_t> merged_into(file_points);
  std::iota(merged_into.begin(), merged_into.end(), std::size_t(0));
  {
    struct Edge { std::size_t a, b; };
    std::vector<Edge> edges;
    for(const Polygon& polygon : polygons)
      for(std::size_t c = 0, n = polygon.size(); c < n; ++c) {
        const std::size_t a = polygon[c], b = polygon[c + 1 < n ? c + 1 : 0];
        if(a != b) edges.push_back({(std::min)(a, b), (std::max)(a, b)});
      }
    std::sort(edges.begin(), edges.end(), [](const Edge& x, const Edge& y) { return std::tie(x.a, x.b) < std::tie(y.a, y.b); });
    std::vector<Edge> border;
    for(std::size_t k = 0; k < edges.size();) {
      std::size_t end = k + 1;
      while(end < edges.size() && edges[end].a == edges[k].a && edges[end].b == edges[k].b) ++end;
      if(end == k + 1) {
        Edge e = edges[k];
        if(position(e.b) < position(e.a)) std::swap(e.a, e.b); // ends ordered by position
        border.push_back(e);
      }
      k = end;
    }
    const auto key = [&](const Edge& e) { return std::make_pair(position(e.a), position(e.b)); };
    std::sort(border.begin(), border.end(), [&](const Edge& x, const Edge& y) { return key(x) < key(y); });
    std::vector<std::size_t> parent = merged_into;
    const auto root = [&](std::size_t i) {
      while(parent[i] != i) i = parent[i] = parent[parent[i]];
      return i;
    };
    const auto unite = [&](std::size_t i, std::size_t j) {
      i = root(i);
      j = root(j);
      if(i != j) parent[(std::max)(i, j)] = (std::min)(i, j);
    };
    for(std::size_t k = 0; k < border.size();) {
      std::size_t end = k + 1;
      while(end < border.size() && key(border[end]) == key(border[k])) ++end;
      // Two border edges on one segment: one seam. Three or more would make
      // an edge of three faces; they stay apart.
      if(end == k + 2 && position(border[k].a) != position(border[k].b)) {
        unite(border[k].a, border[k + 1].a);
        unite(border[k].b, border[k + 1].b);
      }
      k = end;
    }
    for(std::size_t i = 0; i < file_points; ++i) {
      merged_into[i] = root(i);
      if(merged_into[i] != i) ++report.points_merged;
    }
  }

  // ---- faces: renumbered, then dropped if they use a point twice or repeat an earlier face
  std::vector<Polygon> kept;
  kept.reserve(polygons.size());
  map.file_polygon.reserve(polygons.size());
  {
    std::unordered_set<Polygon, Index_list_hash> seen;
    for(std::size_t j = 0; j < polygons.size(); ++j) {
      Polygon polygon;
      polygon.reserve(polygons[j].size());
      for(std::size_t v : polygons[j]) {
        v = merged_into[v];
        if(polygon.empty() || polygon.back() != v) polygon.push_back(v);
      }
      while(polygon.size() > 1 && polygon.back() == polygon.front()) polygon.pop_back();
      Polygon sorted = polygon;
      std::sort(sorted.begin(), sorted.end());
      if(polygon.size() < 3 || std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) {
        ++report.degenerate_faces;
        continue;
      }
      if(!seen.insert(std::move(sorted)).second) {
        ++report.duplicate_faces;
        continue;
      }
      kept.push_back(std::move(polygon));
      map.file_polygon.push_back(j);
    }
  }
  if(kept.empty())
    throw Input_error(path, 0, "the file has no face that uses three distinct points");

  // ---- orientation: across an edge of exactly two faces, the two must go
  // opposite ways. A walk over those edges turns faces over where needed; a
  // face reached again with the other orientation means no orientation
  // exists (a Moebius strip). Each component then keeps the orientation most
  // of its faces had.
  std::vector<char> turned(kept.size(), 0);
  {
    struct Side {
      std::size_t a, b, polygon;
      bool forward; // the face goes from a to b (a < b)
    };
    std::vector<Side> sides;
    for(std::size_t p = 0; p < kept.size(); ++p)
      for(std::size_t c = 0, n = kept[p].size(); c < n; ++c) {
        const std::size_t a = kept[p][c], b = kept[p][c + 1 < n ? c + 1 : 0];
        sides.push_back({(std::min)(a, b), (std::max)(a, b), p, a < b});
      }
    std::sort(sides.begin(), sides.end(), [](const Side& x, const Side& y) {
      return x.a != y.a ? x.a < y.a : x.b != y.b ? x.b < y.b : x.polygon < y.polygon;
    });
    // The links between faces (the other face, and whether it must be
    // turned relative to this one), stored face by face.
    struct Link { std::size_t face, a, b; bool flip; };
    std::vector<std::size_t> first(kept.size() + 1, 0);
    std::vector<std::pair<std::size_t, Link>> pairs;
    for(std::size_t k = 0; k < sides.size();) {
      std::size_t end = k + 1;
      while(end < sides.size() && sides[end].a == sides[k].a && sides[end].b == sides[k].b) ++end;
      if(end == k + 2) {
        const Side& x = sides[k];
        const Side& y = sides[k + 1];
        const bool flip = x.forward == y.forward;
        pairs.push_back({x.polygon, {y.polygon, x.a, x.b, flip}});
        pairs.push_back({y.polygon, {x.polygon, x.a, x.b, flip}});
      } else if(end > k + 2) {
        ++report.non_manifold_edges;
      }
      k = end;
    }
    for(const auto& pair : pairs) ++first[pair.first + 1];
    for(std::size_t p = 0; p < kept.size(); ++p) first[p + 1] += first[p];
    std::vector<Link> links(pairs.size());
    {
      std::vector<std::size_t> fill(first.begin(), first.end() - 1);
      for(const auto& pair : pairs) links[fill[pair.first]++] = pair.second;
    }
    std::vector<char> seen(kept.size(), 0);
    std::vector<std::size_t> members, stack;
    for(std::size_t start = 0; start < kept.size(); ++start) {
      if(seen[start]) continue;
      members.clear();
      seen[start] = 1;
      stack.push_back(start);
      while(!stack.empty()) {
        const std::size_t p = stack.back();
        stack.pop_back();
        members.push_back(p);
        for(std::size_t k = first[p]; k < first[p + 1]; ++k) {
          const Link& link = links[k];
          const char wanted = static_cast<char>(turned[p] ^ (link.flip ? 1 : 0));
          if(!seen[link.face]) {
            seen[link.face] = 1;
            turned[link.face] = wanted;
            stack.push_back(link.face);
          } else if(turned[link.face] != wanted) {
            const std::size_t f = map.file_polygon[p], g = map.file_polygon[link.face];
            throw Input_error(path, locate.face_line((std::max)(f, g)),
                              "the surface is not orientable (like a Moebius strip): faces " +
                                  std::to_string((std::min)(f, g)) + " and " + std::to_string((std::max)(f, g)) +
                                  " meet at the edge between vertices " + std::to_string(link.a) + " and " +
                                  std::to_string(link.b) + " and no orientation of the faces makes them agree there");
          }
        }
      }
      std::size_t turned_here = 0;
      for(std::size_t p : members) turned_here += turned[p] ? 1 : 0;
      if(2 * turned_here > members.size())
        for(std::size_t p : members) turned[p] = !turned[p];
    }
    for(std::size_t p = 0; p < kept.size(); ++p)
      if(turned[p]) std::reverse(kept[p].begin(), kept[p].end());
  }

  // ---- non-manifold points (and the ends of edges of three or more faces),
  // by CGAL: the faces now agree wherever they can, so its orientation pass
  // keeps them and its second pass gives each extra fan a copy.
  map.point_of_vertex.resize(points.size());
  std::iota(map.point_of_vertex.begin(), map.point_of_vertex.end(), std::size_t(0));
  if(report.non_manifold_edges > 0 || !is_manifold_oriented_soup(kept, points.size())) {
    std::vector<std::pair<std::size_t, std::size_t>> copies;
    Orientation_record record;
    record.turned = &turned;
    record.copies = &copies;
    CGAL::Polygon_mesh_processing::orient_polygon_soup(points, kept, CGAL::parameters::visitor(record));
    std::vector<std::size_t> split;
    for(const auto& copy : copies) split.push_back(copy.first);
    std::sort(split.begin(), split.end());
    report.vertices_split = static_cast<std::size_t>(std::unique(split.begin(), split.end()) - split.begin());
    report.vertex_copies = copies.size();
    map.point_of_vertex.resize(points.size());
    for(std::size_t v = file_points; v < points.size(); ++v) map.point_of_vertex[v] = v;
    for(const auto& [point, copy] : copies) map.point_of_vertex[copy] = map.point_of_vertex[point];
  }
  for(char t : turned) report.faces_reoriented += t ? 1 : 0;

  if(!is_manifold_oriented_soup(kept, points.size())) {
    std::size_t face = 0;
    const std::string detail = describe_non_manifold(kept, points.size(), face);
    const std::size_t file_face = face == std::size_t(-1) ? std::size_t(-1) : map.file_polygon[face];
    throw Input_error(path, file_face == std::size_t(-1) ? 0 : locate.face_line(file_face),
                      "non-manifold edge or vertex left after repair" + (detail.empty() ? std::string() : " (" + detail + ")"));
  }

  map.vertex_of_point = std::move(merged_into);
  polygons = std::move(kept);
  return map;
}

} // namespace internal
} // namespace diffuv

#endif // DIFFUV_IO_INTERNAL_REPAIR_POLYGON_SOUP_H
