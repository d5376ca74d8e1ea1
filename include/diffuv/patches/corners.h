// diffuv: choosing a patch's four corners on its boundary loop, and cutting
// the loop into the four sides there (core/four_sides.h has the convention).
#ifndef DIFFUV_PATCHES_CORNERS_H
#define DIFFUV_PATCHES_CORNERS_H

#include <diffuv/core/error.h>
#include <diffuv/core/four_sides.h>
#include <diffuv/internal/index_marks.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/squared_distance_3.h>
#include <CGAL/Kernel/global_functions.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <string>
#include <tuple>
#include <vector>

namespace diffuv {


/// Returns the vertices of the boundary loop that contains the border halfedge
/// `border`, counter-clockwise around the patch (in the direction of the faces'
/// orientation: the interior is on the left).
///
/// \tparam FaceGraph a model of `FaceGraph`
/// \param border a halfedge with `is_border(border, tm)`
template <class FaceGraph>
std::vector<typename boost::graph_traits<FaceGraph>::vertex_descriptor>
counterclockwise_boundary(const FaceGraph& tm, typename boost::graph_traits<FaceGraph>::halfedge_descriptor border)
{
  // Border halfedges run clockwise around the patch (their opposite halfedges
  // belong to the faces, which are counter-clockwise); reverse their order.
  std::vector<typename boost::graph_traits<FaceGraph>::vertex_descriptor> loop;
  for(auto h : CGAL::halfedges_around_face(border, tm))
    loop.push_back(target(h, tm));
  std::reverse(loop.begin(), loop.end());
  return loop;
}

/// Cuts a counter-clockwise boundary loop into four sides at the given corners.
///
/// `corners[0]` goes to (0,0); the three others may be given in any order:
/// they are sorted by their position along the loop after `corners[0]`.
///
/// \param loop the boundary, as returned by `counterclockwise_boundary()`
/// \param corners four distinct vertices of `loop`
/// \param sides receives the sides when the result is `ok`
/// \returns `corner_count`, `corner_duplicated`, `corner_not_on_border` (detail: the
///          position of the corner in `corners`) or `ok`
template <class VertexDescriptor>
Status sides_from_corners(const std::vector<VertexDescriptor>& loop, const std::vector<VertexDescriptor>& corners,
                          Four_sides<VertexDescriptor>& sides)
{
  if(corners.size() != 4)
    return Status(Status_code::corner_count, std::to_string(corners.size()) + " given");
  if(loop.size() < 4)
    return Status(Status_code::border_too_short, std::to_string(loop.size()) + " boundary vertices");
  std::array<std::size_t, 4> position{};
  for(std::size_t c = 0; c < 4; ++c) {
    for(std::size_t d = 0; d < c; ++d)
      if(corners[d] == corners[c])
        return Status(Status_code::corner_duplicated, "corners #" + std::to_string(d + 1) + " and #" + std::to_string(c + 1) + " listed");
    const auto it = std::find(loop.begin(), loop.end(), corners[c]);
    if(it == loop.end())
      return Status(Status_code::corner_not_on_border, "corner #" + std::to_string(c + 1) + " listed");
    position[c] = static_cast<std::size_t>(it - loop.begin());
  }
  // Positions along the loop, counted from corners[0].
  const std::size_t n = loop.size();
  std::array<std::size_t, 4> offset{};
  for(std::size_t c = 0; c < 4; ++c) offset[c] = (position[c] + n - position[0]) % n;
  std::array<std::size_t, 4> order = {0, 1, 2, 3};
  std::sort(order.begin() + 1, order.end(), [&](std::size_t a, std::size_t b) { return offset[a] < offset[b]; });

  for(std::size_t c = 0; c < 4; ++c) sides.corners[c] = corners[order[c]];
  auto arc = [&](std::size_t from, std::size_t to) { // inclusive, along the loop
    std::vector<VertexDescriptor> side;
    const std::size_t a = offset[order[from]];
    const std::size_t b = (to == 0) ? n : offset[order[to]];
    for(std::size_t k = a; k <= b; ++k) side.push_back(loop[(position[0] + k) % n]);
    return side;
  };
  sides.v1 = arc(0, 1);
  sides.u2 = arc(1, 2);
  sides.v2 = arc(2, 3);
  sides.u1 = arc(3, 0);
  return Status();
}

/// Chooses four corners on a boundary loop automatically: the first is the
/// boundary vertex with the smallest interior angle (the sharpest corner of
/// the patch; the lowest vertex index on a tie), the three others cut the loop
/// into four arcs of equal length (the vertex nearest to each quarter of the
/// length, kept distinct and in order).
///
/// The rule depends on the surface only, not on coordinates' axes.
///
/// \tparam TriangleMesh a model of `FaceGraph` with an internal vertex index
/// \tparam VertexPointMap a `ReadablePropertyMap` from vertices to a CGAL `Point_3`
/// \pre `loop` is a counter-clockwise boundary loop of `tm` with at least four vertices
/// \returns the corners in counter-clockwise order, `[0]` first
template <class TriangleMesh, class VertexPointMap>
std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>
equal_arc_corners(const TriangleMesh& tm, VertexPointMap vpm,
                  const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& loop)
{
  const std::size_t n = loop.size();
  auto vindex = get(boost::vertex_index, tm);

  // Interior angle at each boundary vertex: the sum of its faces' angles there.
  auto interior_angle = [&](auto v) {
    double sum = 0;
    for(auto h : CGAL::halfedges_around_target(halfedge(v, tm), tm)) {
      if(is_border(h, tm)) continue;
      const auto p = get(vpm, v);
      const auto a = get(vpm, source(h, tm));
      const auto b = get(vpm, target(next(h, tm), tm));
      const auto va = a - p, vb = b - p;
      const double la = std::sqrt(CGAL::to_double(va.squared_length()));
      const double lb = std::sqrt(CGAL::to_double(vb.squared_length()));
      if(la > 0 && lb > 0)
        sum += std::acos(std::clamp(CGAL::to_double(va * vb) / (la * lb), -1., 1.));
    }
    return sum;
  };
  std::size_t start = 0;
  double sharpest = interior_angle(loop[0]);
  for(std::size_t i = 1; i < n; ++i) {
    const double a = interior_angle(loop[i]);
    if(a < sharpest || (a == sharpest && get(vindex, loop[i]) < get(vindex, loop[start]))) {
      sharpest = a;
      start = i;
    }
  }

  // Arc length from the start vertex, counter-clockwise.
  std::vector<double> arc(n + 1, 0.);
  for(std::size_t k = 0; k < n; ++k) {
    const auto a = get(vpm, loop[(start + k) % n]);
    const auto b = get(vpm, loop[(start + k + 1) % n]);
    arc[k + 1] = arc[k] + std::sqrt(CGAL::to_double(CGAL::squared_distance(a, b)));
  }
  const double total = arc[n];
  std::array<std::size_t, 4> k_of{0, 0, 0, 0};
  for(std::size_t c = 1; c < 4; ++c) {
    const double target_length = total * static_cast<double>(c) / 4.;
    std::size_t k = static_cast<std::size_t>(std::lower_bound(arc.begin(), arc.end(), target_length) - arc.begin());
    if(k > 0 && target_length - arc[k - 1] <= arc[k] - target_length) --k;
    // Keep corners distinct and ordered, leaving room for the ones after.
    k = std::max(k, k_of[c - 1] + 1);
    k = std::min(k, n - (4 - c));
    k_of[c] = k;
  }
  std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> corners;
  for(std::size_t c = 0; c < 4; ++c) corners.push_back(loop[(start + k_of[c]) % n]);
  return corners;
}


/// Moves corners so that no triangle has its three vertices on one side.
///
/// Such a triangle (an "ear" of the border, or a face cut off by a chord) is
/// flat in any map that sends each side onto a straight edge of the square.
/// So are the triangles around interior vertices whose border neighbours all
/// lie on one side and that reach no other interior vertex (a valence-3
/// vertex next to the border, measured on bull; a fin of several, on pinion):
/// a convex combination of points on a line stays on it. Each such set of
/// border positions (a face's three, the border neighbours of a connected
/// group of interior vertices) must not lie on one side.
///
/// First, greedily, the middle vertex of a flat set along its side becomes a
/// corner: one of the side's two corners moves there, whichever leaves fewer
/// flat sets; this repeats while it helps. Where that gets stuck (moving a
/// corner onto one ear makes another face flat, measured on cow and man), every
/// placement of the four corners within a few positions of where they
/// started is tried, and the one with fewest flat sets, then the shortest total
/// move, wins. The corners keep their cyclic order and stay distinct. Among
/// moves that leave as few flat sets, the shortest arc length wins, so the
/// result does not depend on where the loop starts (nor on vertex order).
///
/// \tparam FaceGraph a model of `FaceGraph`
/// \tparam InPatch a predicate on faces: whether a face belongs to the patch bounded by `loop`
/// \param loop the patch's boundary, counter-clockwise
/// \param corners four positions in `loop`, in counter-clockwise order; updated
/// \param edge_lengths n entries: length of the loop edge from position i to i+1
/// \returns how many times a corner moved (0 if none did)
template <class FaceGraph, class InPatch>
std::size_t separate_flat_triangles(const FaceGraph& g,
                                    const std::vector<typename boost::graph_traits<FaceGraph>::vertex_descriptor>& loop,
                                    std::array<std::size_t, 4>& corners, InPatch in_patch,
                                    const std::vector<double>& edge_lengths)
{
  using vertex_descriptor = typename boost::graph_traits<FaceGraph>::vertex_descriptor;
  const std::size_t n = loop.size();
  // Loop positions and searches by vertex index, in tables kept per thread
  // from one call to the next so that a call is O(patch): std::maps here were
  // a fifth of the paper's method on man's 1,096 patches (doc/performance.md).
  const auto vindex = get(boost::vertex_index, g);
  // (4 bytes per entry: 16 bytes per vertex of the largest mesh seen, per thread.)
  thread_local internal::Index_marks on_loop, met;
  thread_local std::vector<std::uint32_t> position_of, search_of;
  const std::size_t nv = num_vertices(g);
  on_loop.reset(nv);
  met.reset(nv);
  if(position_of.size() < nv) {
    position_of.resize(nv);
    search_of.resize(nv);
  }
  for(std::size_t i = 0; i < n; ++i) {
    const std::size_t vi = get(vindex, loop[i]);
    if(on_loop.insert(vi)) position_of[vi] = static_cast<std::uint32_t>(i);
  }
  auto position = [&](vertex_descriptor v) {
    const std::size_t vi = get(vindex, v);
    return on_loop.contains(vi) ? std::size_t(position_of[vi]) : n;
  };

  // The sets of border positions that must not lie on one side: the faces
  // with three border vertices, and the links of interior vertices whose
  // neighbours are all border vertices.
  std::vector<std::vector<std::size_t>> border_sets;
  std::vector<vertex_descriptor> inner;  // interior vertices next to the border
  for(std::size_t i = 0; i < n; ++i)
    for(auto h : CGAL::halfedges_around_target(halfedge(loop[i], g), g)) {
      if(is_border(h, g) || !in_patch(face(h, g))) continue;
      std::array<std::size_t, 3> t{};
      std::size_t on_border = 0;
      for(vertex_descriptor v : CGAL::vertices_around_face(h, g)) {
        const std::size_t at = position(v);
        if(at == n) inner.push_back(v);
        else if(on_border++ < 3) t[on_border - 1] = at;
      }
      if(on_border == 3) border_sets.emplace_back(t.begin(), t.end());
    }
  // The interior vertices next to the border, grouped into connected
  // components across interior edges: a convex combination map puts a whole
  // component on a side's line when all its border neighbours lie on that
  // side (a fin of interior vertices hanging off one side, measured on
  // pinion and turbine). A component larger than the border (the patch's
  // main interior, in practice never on one side) is left out, so this stays
  // cheap on a large disc.
  std::sort(inner.begin(), inner.end());
  inner.erase(std::unique(inner.begin(), inner.end()), inner.end());
  const std::size_t max_component = std::max<std::size_t>(n, 64);
  std::vector<std::size_t> attached;
  std::vector<vertex_descriptor> stack;
  for(std::size_t k = 0; k < inner.size(); ++k) {
    // search_of[v]: the search that met interior vertex v first
    if(!met.insert(get(vindex, inner[k]))) continue;
    search_of[get(vindex, inner[k])] = static_cast<std::uint32_t>(k);
    attached.clear();
    stack.assign(1, inner[k]);
    std::size_t size = 1;
    // A search stopped early leaves its component unfinished: meeting one of
    // its vertices means this is the same large component.
    bool large = false;
    while(!stack.empty() && !large) {
      const vertex_descriptor v = stack.back();
      stack.pop_back();
      for(auto h : CGAL::halfedges_around_target(halfedge(v, g), g)) {
        const vertex_descriptor w = source(h, g);
        const std::size_t at = position(w);
        if(at != n) {
          attached.push_back(at);
          continue;
        }
        const std::size_t wi = get(vindex, w);
        if(met.insert(wi)) {
          search_of[wi] = static_cast<std::uint32_t>(k);
          stack.push_back(w);
          large = ++size > max_component;
        } else if(search_of[wi] != static_cast<std::uint32_t>(k)) {
          large = true;
        }
      }
    }
    std::sort(attached.begin(), attached.end());
    attached.erase(std::unique(attached.begin(), attached.end()), attached.end());
    if(!large && attached.size() >= 3) border_sets.push_back(attached);
  }
  // Each face is met from each of its vertices; keep every set once.
  for(auto& t : border_sets) std::sort(t.begin(), t.end());
  std::sort(border_sets.begin(), border_sets.end());
  border_sets.erase(std::unique(border_sets.begin(), border_sets.end()), border_sets.end());
  if(border_sets.empty()) return 0;

  // A set is flat if its positions lie on one side; returns that side or 4.
  auto flat_side = [&](const std::vector<std::size_t>& t, const std::array<std::size_t, 4>& c) {
    for(std::size_t s = 0; s < 4; ++s) {
      const std::size_t length = (c[(s + 1) % 4] + n - c[s]) % n;
      if(std::all_of(t.begin(), t.end(), [&](std::size_t i) { return (i + n - c[s]) % n <= length; })) return s;
    }
    return std::size_t(4);
  };
  auto count_flat = [&](const std::array<std::size_t, 4>& c) {
    std::size_t count = 0;
    for(const auto& t : border_sets) count += flat_side(t, c) < 4;
    return count;
  };

  // Arc length from position a forwards to b, summed from a: the same sum
  // wherever the loop starts (a prefix sum would round differently).
  auto arc = [&](std::size_t a, std::size_t b) {
    double sum = 0;
    for(std::size_t i = a; i != b; i = (i + 1) % n) sum += edge_lengths[i];
    return sum;
  };
  // A placement's vertices in increasing order: the last tie-break, the same
  // whichever way the loop runs and wherever it starts.
  auto sorted_vertices = [&](const std::array<std::size_t, 4>& c) {
    std::array<vertex_descriptor, 4> v{loop[c[0]], loop[c[1]], loop[c[2]], loop[c[3]]};
    std::sort(v.begin(), v.end());
    return v;
  };
  const std::array<std::size_t, 4> start = corners;
  std::size_t moves = 0;
  std::size_t flat = count_flat(corners);

  // Greedy: move one of the two corners of a flat set's side onto the set's
  // middle position, whichever leaves fewer flat sets; stop when no move helps.
  while(flat > 0) {
    std::size_t best_flat = flat;
    double best_shift = std::numeric_limits<double>::infinity();
    std::array<std::size_t, 4> best = corners;
    for(const auto& t : border_sets) {
      const std::size_t s = flat_side(t, corners);
      if(s == 4) continue;
      std::vector<std::size_t> offset;
      for(std::size_t i : t) offset.push_back((i + n - corners[s]) % n);
      std::sort(offset.begin(), offset.end());
      // The set's middle; of an even set, either of its two middles (taking
      // the upper one alone would depend on which way the loop runs).
      // (Strictly inside the side: the offsets are distinct, the set has three or more.)
      const std::size_t middles = offset.size() % 2 == 0 ? 2 : 1;
      for(std::size_t k = 0; k < middles; ++k)
      for(std::size_t c : {s, (s + 1) % 4}) {
        const std::size_t middle = (corners[s] + offset[(offset.size() - 1) / 2 + k]) % n;
        std::array<std::size_t, 4> candidate = corners;
        candidate[c] = middle;
        const std::size_t candidate_flat = count_flat(candidate);
        // The corner moves along side s: forwards from corners[s], backwards from corners[s+1].
        const double shift = c == s ? arc(corners[s], middle) : arc(middle, corners[c]);
        // Equal shifts (to rounding: the sum runs the other way on a copy
        // with its faces turned): the placement of the smaller vertices.
        const bool same_shift = std::abs(shift - best_shift) <= 1e-12 * std::max(shift, best_shift);
        const bool shorter = same_shift ? sorted_vertices(candidate) < sorted_vertices(best) : shift < best_shift;
        if(candidate_flat < best_flat || (candidate_flat == best_flat && best_flat < flat && shorter)) {
          best_flat = candidate_flat;
          best_shift = shift;
          best = candidate;
        }
      }
    }
    if(best_flat == flat) break;
    corners = best;
    flat = best_flat;
    ++moves;
  }
  if(flat == 0) return moves;

  // Stuck: the placement that leaves no flat set and moves the corners the
  // shortest total arc length from where they started, if there is one. A
  // set S is not flat iff, for each gap between cyclically consecutive
  // positions of S, a corner lies strictly on the other side of the gap (in
  // the open arc from the gap's end round to its start). With corner 0 fixed,
  // the loop unrolls to a line of offsets from it and each such arc not
  // holding corner 0 is an interval that corners 1-3 must hit: a dynamic
  // programme over the offsets of corners 1, 2, 3 in increasing order.
  constexpr std::size_t none = std::numeric_limits<std::size_t>::max();
  // Arc lengths from each start corner, summed from that corner (not from
  // the loop's first vertex), so that equal placements cost exactly the same
  // wherever the loop starts; ties go to the smallest signed moves.
  std::array<std::vector<double>, 4> ahead, behind;
  for(std::size_t k = 0; k < 4; ++k) {
    ahead[k].assign(n, 0.);
    behind[k].assign(n, 0.);
    for(std::size_t step = 0; step + 1 < n; ++step) {
      const std::size_t i = (start[k] + step) % n, j = (start[k] + n - step) % n;
      ahead[k][(i + 1) % n] = ahead[k][i] + edge_lengths[i];
      behind[k][(j + n - 1) % n] = behind[k][j] + edge_lengths[(j + n - 1) % n];
    }
  }
  auto move_of = [&](std::size_t k, std::size_t x) { return ahead[k][x] <= behind[k][x] ? ahead[k][x] : -behind[k][x]; };
  // Equal costs (to rounding): the placement of the smaller vertices.
  double loop_length = 0;
  for(double l : edge_lengths) loop_length += l;
  auto placement_key = [&](const std::array<std::size_t, 4>& c, double cost) {
    return std::make_pair(std::round(cost * 1e9 / std::max(loop_length, 1e-300)), sorted_vertices(c));
  };
  std::vector<std::pair<std::size_t, std::size_t>> arcs;  // open arcs (from, to) that need a corner
  for(const auto& t : border_sets)
    for(std::size_t i = 0; i < t.size(); ++i) arcs.emplace_back(t[(i + 1) % t.size()], t[i]);
  const double infinity = std::numeric_limits<double>::infinity();
  double best_cost = infinity;
  std::array<std::size_t, 4> best = corners;
  // Corner 0 anywhere on a short loop (O(n^3) in all), else within 12
  // positions of where it started.
  const std::size_t reach = 12, tries = n <= 64 ? n : 2 * reach + 1;
  for(std::size_t step = 0; step < tries; ++step) {
    const std::size_t x0 = n <= 64 ? step : (start[0] + n - reach + step) % n;
    // limit[x]: the largest offset the next corner may take after one at
    // offset x (an interval (lo, hi) with lo >= x needs a corner below hi).
    std::vector<std::size_t> limit(n + 1, none);
    for(const auto& [from, to] : arcs) {
      const std::size_t lo = (from + n - x0) % n, hi = to == x0 ? n : (to + n - x0) % n;
      if(lo < hi && hi - lo >= 2) limit[lo] = std::min(limit[lo], hi - 1);
      else if(lo < hi) limit[lo] = 0;  // an empty open interval: no placement hits it
    }
    for(std::size_t x = n; x-- > 0;) limit[x] = std::min(limit[x], limit[x + 1]);
    // cost[k][x]: corners 1..k placed, corner k at offset x.
    std::array<std::vector<double>, 4> cost;
    std::array<std::vector<std::size_t>, 4> from;
    for(auto& c : cost) c.assign(n, infinity);
    for(auto& f : from) f.assign(n, none);
    cost[0][0] = std::abs(move_of(0, x0));
    for(std::size_t k = 1; k < 4; ++k)
      for(std::size_t x = 1; x < n; ++x) {
        for(std::size_t y = 0; y < x; ++y)
          if(cost[k - 1][y] < infinity && x <= limit[y] && cost[k - 1][y] < cost[k][x]) {
            cost[k][x] = cost[k - 1][y];
            from[k][x] = y;
          }
        if(cost[k][x] < infinity) cost[k][x] += std::abs(move_of(k, (x0 + x) % n));
      }
    for(std::size_t x = 1; x < n; ++x) {
      if(!(cost[3][x] < infinity) || limit[x] != none) continue;
      std::array<std::size_t, 4> candidate{};
      std::size_t y = x;
      for(std::size_t k = 4; k-- > 1;) {
        candidate[k] = (x0 + y) % n;
        y = from[k][y];
      }
      candidate[0] = x0;
      if(best_cost == infinity || placement_key(candidate, cost[3][x]) < placement_key(best, best_cost)) {
        best_cost = cost[3][x];
        best = candidate;
      }
    }
  }
  if(best_cost < infinity && best != corners) {
    corners = best;
    ++moves;
  }
  return moves;
}

} // namespace diffuv

#endif // DIFFUV_PATCHES_CORNERS_H
