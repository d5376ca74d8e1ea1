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
#include <cstdint>
#include <cstring>
#include <limits>
#include <numeric>
#include <string>
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

/// Sentinel of the index tables below.
template <class Index>
constexpr Index no_index = static_cast<Index>(-1);

/// A 64-bit mix (the finaliser of MurmurHash3): spreads a key over the low
/// bits that an open-addressing table of a power-of-two size uses.
inline std::uint64_t mix_bits(std::uint64_t h)
{
  h ^= h >> 33;
  h *= 0xff51afd7ed558ccdull;
  h ^= h >> 33;
  h *= 0xc4ceb9fe1a85ec53ull;
  h ^= h >> 33;
  return h;
}

/// A power of two at least twice `n` (and at least 16): the size of an
/// open-addressing table that stays at most half full.
inline std::size_t table_size_for(std::size_t n)
{
  std::size_t size = 16;
  while(size < 2 * n) size *= 2;
  return size;
}

/// For each point of `which` (in increasing order), the first point of
/// `which` at exactly the same position; `no_index` for the points not in
/// `which`. 0 and -0 are one position. An open-addressing table over the
/// coordinates' bits: linear in the number of points, where sorting them by
/// position cost more than reading the file.
template <class Index, class Point>
std::vector<Index> coinciding_points(const std::vector<Point>& points, const std::vector<Index>& which)
{
  std::vector<Index> first_at(points.size(), no_index<Index>);
  const std::size_t mask = table_size_for(which.size()) - 1;
  std::vector<Index> table(mask + 1, no_index<Index>);
  const auto coordinates = [&](std::size_t i) {
    // + 0.0 turns -0 into 0, which compare equal but differ in their bits.
    return std::array<double, 3>{CGAL::to_double(points[i].x()) + 0.0, CGAL::to_double(points[i].y()) + 0.0,
                                 CGAL::to_double(points[i].z()) + 0.0};
  };
  for(Index i : which) {
    const std::array<double, 3> at = coordinates(i);
    std::uint64_t h = 0;
    for(double x : at) {
      std::uint64_t bits;
      std::memcpy(&bits, &x, sizeof bits);
      h = mix_bits(h ^ bits);
    }
    for(std::size_t slot = h & mask;; slot = (slot + 1) & mask) {
      if(table[slot] == no_index<Index>) {
        table[slot] = i;
        first_at[i] = i;
        break;
      }
      if(coordinates(table[slot]) == at) {
        first_at[i] = table[slot];
        break;
      }
    }
  }
  return first_at;
}

/// An edge of a polygon, seen from its lower end: the polygons' edges are
/// grouped by their lower end (a counting sort) and, within a group, sorted
/// by the other end, so that the polygons sharing an edge are adjacent.
template <class Index>
struct Soup_half_edge {
  Index other;   ///< the higher end
  Index polygon; ///< the polygon it belongs to
  Index corner;  ///< the edge goes from the polygon's corner `corner` to the next
  bool forward;  ///< the polygon goes from the lower end to the higher
};

/// The edges of `polygons` (of points below `nb_points`; edges from a point
/// to itself left out), the edges of lower end v at
/// `edges[first[v] .. first[v + 1])`, sorted by (other end, polygon).
/// Linear in the soup's size but for the sort of each point's few edges.
template <class Index>
void soup_half_edges(const std::vector<std::vector<std::size_t>>& polygons, std::size_t nb_points,
                     std::vector<std::size_t>& first, std::vector<Soup_half_edge<Index>>& edges)
{
  first.assign(nb_points + 1, 0);
  for(const auto& polygon : polygons)
    for(std::size_t c = 0, n = polygon.size(); c < n; ++c) {
      const std::size_t a = polygon[c], b = polygon[c + 1 < n ? c + 1 : 0];
      if(a != b) ++first[(std::min)(a, b) + 1];
    }
  for(std::size_t v = 0; v < nb_points; ++v) first[v + 1] += first[v];
  edges.resize(first[nb_points]);
  std::vector<std::size_t> fill(first.begin(), first.end() - 1);
  for(std::size_t p = 0; p < polygons.size(); ++p)
    for(std::size_t c = 0, n = polygons[p].size(); c < n; ++c) {
      const std::size_t a = polygons[p][c], b = polygons[p][c + 1 < n ? c + 1 : 0];
      if(a != b)
        edges[fill[(std::min)(a, b)]++] = {static_cast<Index>((std::max)(a, b)), static_cast<Index>(p),
                                           static_cast<Index>(c), a < b};
    }
  for(std::size_t v = 0; v < nb_points; ++v)
    if(first[v + 1] - first[v] > 1)
      std::sort(edges.begin() + static_cast<std::ptrdiff_t>(first[v]),
                edges.begin() + static_cast<std::ptrdiff_t>(first[v + 1]),
                [](const Soup_half_edge<Index>& x, const Soup_half_edge<Index>& y) {
                  return x.other != y.other ? x.other < y.other : x.polygon < y.polygon;
                });
}

/// Calls `group(v, begin, end)` for each run of edges of `soup_half_edges()`
/// that join the same two points: one edge of the soup and its polygons.
template <class Index, class Group>
void for_each_soup_edge(const std::vector<std::size_t>& first, const std::vector<Soup_half_edge<Index>>& edges,
                        Group group)
{
  for(std::size_t v = 0; v + 1 < first.size(); ++v)
    for(std::size_t k = first[v]; k < first[v + 1];) {
      std::size_t end = k + 1;
      while(end < first[v + 1] && edges[end].other == edges[k].other) ++end;
      group(v, k, end);
      k = end;
    }
}

/// With `manifold` set true when the soup is a manifold, consistently oriented
/// polygon mesh: the number of its border points that lie exactly where an
/// earlier border point lies (borders that stitching would look at; 0 when
/// the soup is not such a mesh).
template <class Index, class Point>
std::size_t coinciding_border_points(const std::vector<Point>& points,
                                     const std::vector<std::vector<std::size_t>>& polygons, bool& manifold)
{
  std::vector<char> on_border;
  manifold = is_manifold_oriented_soup(polygons, points.size(), &on_border);
  if(!manifold) return 0;
  std::vector<Index> border;
  for(std::size_t i = 0; i < on_border.size(); ++i)
    if(on_border[i]) border.push_back(static_cast<Index>(i));
  const std::vector<Index> first_at = coinciding_points(points, border);
  std::size_t coinciding = 0;
  for(Index i : border) coinciding += first_at[i] != i ? 1 : 0;
  return coinciding;
}

/// True when the soup needs none of the repairs: a manifold, consistently
/// oriented polygon mesh, no face using a point twice, no two border points
/// at one position (the first thing stitching would look at).
template <class Index, class Point>
bool soup_needs_no_repair(const std::vector<Point>& points, const std::vector<std::vector<std::size_t>>& polygons)
{
  std::vector<std::size_t> sorted;
  for(const auto& polygon : polygons) {
    if(polygon.size() == 3) {
      if(polygon[0] == polygon[1] || polygon[1] == polygon[2] || polygon[0] == polygon[2]) return false;
      continue;
    }
    sorted.assign(polygon.begin(), polygon.end());
    std::sort(sorted.begin(), sorted.end());
    if(std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) return false;
  }
  bool manifold = false;
  return coinciding_border_points<Index>(points, polygons, manifold) == 0 && manifold;
}

/// repair_polygon_soup() with indices of type `Index` (32 bits when the soup
/// allows: the pages of fresh memory are much of what the repair costs).
template <class Index, class Point>
Soup_repair_map repair_polygon_soup_as(const std::string& path, std::vector<Point>& points,
                                       std::vector<std::vector<std::size_t>>& polygons, Line_locator& locate,
                                       Mesh_repair_report& report)
{
  using Polygon = std::vector<std::size_t>;
  using Edge = Soup_half_edge<Index>;
  Soup_repair_map map;
  report = Mesh_repair_report();
  if(soup_needs_no_repair<Index>(points, polygons)) return map;

  const std::size_t file_points = points.size();
  std::vector<std::size_t> first;
  std::vector<Edge> edges;

  // ---- stitching: border edges (edges of one face) that coincide in pairs
  // have their points merged, each into the one of smallest index. Points
  // that merely coincide (two borders touching at a point) are left apart.
  std::vector<std::size_t> merged_into(file_points);
  std::iota(merged_into.begin(), merged_into.end(), std::size_t(0));
  {
    soup_half_edges(polygons, file_points, first, edges);
    struct Border_edge { Index a, b, at_a, at_b; }; // at_a < at_b: the first points at the ends' positions
    std::vector<Border_edge> border;
    for_each_soup_edge(first, edges, [&](std::size_t v, std::size_t k, std::size_t end) {
      if(end == k + 1) border.push_back({static_cast<Index>(v), edges[k].other, 0, 0});
    });
    if(!border.empty()) {
      std::vector<Index> ends;
      {
        std::vector<char> is_end(file_points, 0);
        for(const Border_edge& e : border) is_end[e.a] = is_end[e.b] = 1;
        for(std::size_t i = 0; i < file_points; ++i)
          if(is_end[i]) ends.push_back(static_cast<Index>(i));
      }
      const std::vector<Index> first_at = coinciding_points(points, ends);
      std::size_t kept_edges = 0;
      for(Border_edge e : border) {
        e.at_a = first_at[e.a];
        e.at_b = first_at[e.b];
        if(e.at_a == e.at_b) continue; // both ends at one position: nothing to stitch along
        if(e.at_b < e.at_a) {
          std::swap(e.a, e.b);
          std::swap(e.at_a, e.at_b);
        }
        border[kept_edges++] = e;
      }
      border.resize(kept_edges);
      // Grouped by position: by the first end (a counting sort), then the second.
      std::vector<std::size_t> at(file_points + 1, 0);
      for(const Border_edge& e : border) ++at[e.at_a + 1];
      for(std::size_t i = 0; i < file_points; ++i) at[i + 1] += at[i];
      std::vector<Border_edge> by_position(border.size());
      {
        std::vector<std::size_t> fill(at.begin(), at.end() - 1);
        for(const Border_edge& e : border) by_position[fill[e.at_a]++] = e;
      }
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
      for(std::size_t i = 0; i < file_points; ++i) {
        const auto begin = by_position.begin() + static_cast<std::ptrdiff_t>(at[i]);
        const auto end = by_position.begin() + static_cast<std::ptrdiff_t>(at[i + 1]);
        if(end - begin < 2) continue;
        std::sort(begin, end, [](const Border_edge& x, const Border_edge& y) { return x.at_b < y.at_b; });
        for(auto k = begin; k != end;) {
          auto run = k + 1;
          while(run != end && run->at_b == k->at_b) ++run;
          // Two border edges on one segment: one seam. Three or more would
          // make an edge of three faces; they stay apart.
          if(run == k + 2) {
            unite(k->a, (k + 1)->a);
            unite(k->b, (k + 1)->b);
          }
          k = run;
        }
      }
      for(std::size_t i = 0; i < file_points; ++i) {
        merged_into[i] = root(i);
        if(merged_into[i] != i) ++report.points_merged;
      }
    }
  }

  // ---- faces: renumbered, then dropped if they use a point twice or
  // repeat an earlier face (an open-addressing table of the kept faces,
  // keyed by their sorted points).
  std::vector<Polygon> kept;
  kept.reserve(polygons.size());
  map.file_polygon.reserve(polygons.size());
  {
    const std::size_t mask = table_size_for(polygons.size()) - 1;
    std::vector<Index> table(mask + 1, no_index<Index>);
    Polygon sorted, other;
    const auto sort_into = [](const Polygon& polygon, Polygon& out) {
      out.assign(polygon.begin(), polygon.end());
      if(out.size() == 3) {
        if(out[1] < out[0]) std::swap(out[0], out[1]);
        if(out[2] < out[1]) std::swap(out[1], out[2]);
        if(out[1] < out[0]) std::swap(out[0], out[1]);
      } else {
        std::sort(out.begin(), out.end());
      }
    };
    for(std::size_t j = 0; j < polygons.size(); ++j) {
      Polygon& polygon = polygons[j];
      if(report.points_merged > 0) {
        std::size_t n = 0;
        for(std::size_t v : polygon) {
          v = merged_into[v];
          if(n == 0 || polygon[n - 1] != v) polygon[n++] = v;
        }
        while(n > 1 && polygon[n - 1] == polygon[0]) --n;
        polygon.resize(n);
      }
      sort_into(polygon, sorted);
      if(polygon.size() < 3 || std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) {
        ++report.degenerate_faces;
        continue;
      }
      bool repeated = false;
      std::size_t slot = mix_bits(Index_list_hash()(sorted)) & mask;
      for(; table[slot] != no_index<Index>; slot = (slot + 1) & mask) {
        const Polygon& earlier = kept[table[slot]];
        if(earlier.size() != sorted.size()) continue;
        sort_into(earlier, other);
        if(other == sorted) {
          repeated = true;
          break;
        }
      }
      if(repeated) {
        ++report.duplicate_faces;
        continue;
      }
      table[slot] = static_cast<Index>(kept.size());
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
    // The edges of the stitching pass serve unless a point was merged or a face dropped.
    if(report.points_merged > 0 || kept.size() != polygons.size()) soup_half_edges(kept, points.size(), first, edges);
    // The face across each corner's edge (when exactly two faces share it),
    // and whether it must be turned relative to this one.
    struct Link { Index face; bool flip; };
    std::vector<std::size_t> corner_of(kept.size() + 1, 0);
    for(std::size_t p = 0; p < kept.size(); ++p) corner_of[p + 1] = corner_of[p] + kept[p].size();
    std::vector<Link> links(corner_of.back(), Link{no_index<Index>, false});
    for_each_soup_edge(first, edges, [&](std::size_t, std::size_t k, std::size_t end) {
      if(end == k + 2) {
        const Edge& x = edges[k];
        const Edge& y = edges[k + 1];
        const bool flip = x.forward == y.forward;
        links[corner_of[x.polygon] + x.corner] = {y.polygon, flip};
        links[corner_of[y.polygon] + y.corner] = {x.polygon, flip};
      } else if(end > k + 2) {
        ++report.non_manifold_edges;
      }
    });
    std::vector<char> seen(kept.size(), 0);
    // The walk's tree: the face each face was reached from, and the corner
    // of that face whose edge it crossed (to name a Moebius strip's seam).
    std::vector<Index> parent(kept.size(), no_index<Index>);
    std::vector<std::size_t> parent_corner(kept.size(), 0);
    std::vector<std::size_t> members, stack;
    const auto refuse_moebius = [&](std::size_t p, std::size_t c, std::size_t q) {
      // The walk closed a cycle of faces (p's path up the tree, q's, and the
      // edge between them) around which no orientation agrees. Name an edge
      // of it across which the file's own faces disagree: one exists (their
      // number is odd), and it is where the user can see the twist.
      std::vector<char> on_path(kept.size(), 0);
      for(std::size_t f = p;; f = parent[f]) {
        on_path[f] = 1;
        if(parent[f] == no_index<Index>) break;
      }
      std::vector<std::size_t> cycle = {corner_of[p] + c}; // corners whose edges make the cycle
      std::size_t common = q;                                // q's path up to p's
      while(!on_path[common]) {
        cycle.push_back(parent_corner[common]);
        common = parent[common];
      }
      for(std::size_t f = p; f != common; f = parent[f]) cycle.push_back(parent_corner[f]);
      std::size_t named = cycle.front();
      for(std::size_t corner : cycle)
        if(links[corner].flip) {
          named = corner;
          break;
        }
      const std::size_t face = static_cast<std::size_t>(
          std::upper_bound(corner_of.begin(), corner_of.end(), named) - corner_of.begin() - 1);
      const std::size_t k = named - corner_of[face], n = kept[face].size();
      const std::size_t f = map.file_polygon[face], g = map.file_polygon[links[named].face];
      const std::size_t a = kept[face][k], b = kept[face][k + 1 < n ? k + 1 : 0];
      throw Input_error(path, locate.face_line((std::max)(f, g)),
                        "the surface is not orientable (like a Moebius strip): faces " +
                            std::to_string((std::min)(f, g)) + " and " + std::to_string((std::max)(f, g)) +
                            " disagree on the direction of the edge between vertices " +
                            std::to_string((std::min)(a, b)) + " and " + std::to_string((std::max)(a, b)) +
                            ", and no choice of orientations makes every face agree with its neighbours");
    };
    const auto coordinates = [&](std::size_t i) {
      return std::array<double, 3>{CGAL::to_double(points[i].x()), CGAL::to_double(points[i].y()),
                                   CGAL::to_double(points[i].z())};
    };
    for(std::size_t start = 0; start < kept.size(); ++start) {
      if(seen[start]) continue;
      members.clear();
      seen[start] = 1;
      stack.push_back(start);
      bool closed = true;
      while(!stack.empty()) {
        const std::size_t p = stack.back();
        stack.pop_back();
        members.push_back(p);
        for(std::size_t c = 0, n = kept[p].size(); c < n; ++c) {
          const Link& link = links[corner_of[p] + c];
          if(link.face == no_index<Index>) {
            closed = false; // a border edge, or an edge of three faces or more
            continue;
          }
          const char wanted = static_cast<char>(turned[p] ^ (link.flip ? 1 : 0));
          if(!seen[link.face]) {
            seen[link.face] = 1;
            turned[link.face] = wanted;
            parent[link.face] = static_cast<Index>(p);
            parent_corner[link.face] = corner_of[p] + c;
            stack.push_back(link.face);
          } else if(turned[link.face] != wanted) {
            refuse_moebius(p, c, link.face);
          }
        }
      }
      // Which way the component faces: a closed one outwards (its signed
      // volume positive), an open one as most of its faces did in the file.
      bool turn_all = false;
      double volume = 0.;
      if(closed) {
        for(std::size_t p : members) {
          const auto& polygon = kept[p];
          const std::array<double, 3> o = coordinates(polygon[0]);
          double six_volume = 0.;
          for(std::size_t k = 1; k + 1 < polygon.size(); ++k) {
            const std::array<double, 3> a = coordinates(polygon[k]), b = coordinates(polygon[k + 1]);
            six_volume += o[0] * (a[1] * b[2] - a[2] * b[1]) - o[1] * (a[0] * b[2] - a[2] * b[0]) +
                          o[2] * (a[0] * b[1] - a[1] * b[0]);
          }
          volume += turned[p] ? -six_volume : six_volume;
        }
      }
      if(closed && volume != 0.) {
        turn_all = volume < 0.;
      } else {
        std::size_t turned_here = 0;
        for(std::size_t p : members) turned_here += turned[p] ? 1 : 0;
        turn_all = 2 * turned_here > members.size();
      }
      if(turn_all)
        for(std::size_t p : members) turned[p] = !turned[p];
    }
    for(std::size_t p = 0; p < kept.size(); ++p)
      if(turned[p]) std::reverse(kept[p].begin(), kept[p].end());
  }

  // ---- non-manifold points (and the ends of edges of three or more faces),
  // by CGAL: the faces now agree wherever they can, so its orientation pass
  // keeps them and its second pass gives each extra fan a copy.
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
    if(!copies.empty()) {
      map.point_of_vertex.resize(points.size());
      std::iota(map.point_of_vertex.begin(), map.point_of_vertex.end(), std::size_t(0));
      for(const auto& [point, copy] : copies) map.point_of_vertex[copy] = map.point_of_vertex[point];
    }
    if(!is_manifold_oriented_soup(kept, points.size())) {
      std::size_t face = 0;
      const std::string detail = describe_non_manifold(kept, points.size(), face);
      const std::size_t file_face = face == std::size_t(-1) ? std::size_t(-1) : map.file_polygon[face];
      throw Input_error(path, file_face == std::size_t(-1) ? 0 : locate.face_line(file_face),
                        "non-manifold edge or vertex left after repair" + (detail.empty() ? std::string() : " (" + detail + ")"));
    }
  }
  for(char t : turned) report.faces_reoriented += t ? 1 : 0;

  map.vertex_of_point = std::move(merged_into);
  polygons = std::move(kept);
  return map;
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
  // Copies of split points may be added: leave room for one per corner.
  std::size_t corners = 0;
  for(const auto& polygon : polygons) corners += polygon.size();
  const std::uint64_t limit = std::numeric_limits<std::uint32_t>::max();
  if(points.size() + corners < limit && polygons.size() < limit)
    return repair_polygon_soup_as<std::uint32_t>(path, points, polygons, locate, report);
  return repair_polygon_soup_as<std::size_t>(path, points, polygons, locate, report);
}

} // namespace internal
} // namespace diffuv

#endif // DIFFUV_IO_INTERNAL_REPAIR_POLYGON_SOUP_H
