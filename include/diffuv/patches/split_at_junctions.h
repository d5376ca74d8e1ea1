// diffuv: a patch that needs more than four corners cut between two of its
// junctions until no piece does.
#ifndef DIFFUV_PATCHES_SPLIT_AT_JUNCTIONS_H
#define DIFFUV_PATCHES_SPLIT_AT_JUNCTIONS_H

#include <diffuv/graph/edge_length_map.h>
#include <diffuv/graph/multi_source_dijkstra.h>
#include <diffuv/patches/internal/face_pieces.h>
#include <diffuv/patches/segmentation.h>

#include <CGAL/boost/graph/Face_filtered_graph.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/centroid.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <queue>
#include <set>
#include <tuple>
#include <unordered_map>
#include <vector>

namespace diffuv {

namespace internal {

// The corners patch p needs, as positions of its boundary `loop` in order:
// its junctions (where the neighbour changes) and its ear tips (boundary
// vertices in one face of p); `is_junction` says which.
template <class TriangleMesh>
void needed_corners(const TriangleMesh& tm, const Segmentation<TriangleMesh>& seg, std::size_t p,
                    const Patch_loop<TriangleMesh>& loop, std::vector<std::size_t>& needed, std::vector<char>& is_junction)
{
  auto findex = get(boost::face_index, tm);
  const std::size_t n = loop.vertices.size();
  needed.clear();
  is_junction.clear();
  for(std::size_t i = 0; i < n; ++i) {
    const bool junction = loop.neighbour[(i + n - 1) % n] != loop.neighbour[i];
    std::size_t faces_here = 0;
    for(auto h : CGAL::halfedges_around_target(halfedge(loop.vertices[i], tm), tm))
      if(!is_border(h, tm) && seg.face_patch[get(findex, face(h, tm))] == p) ++faces_here;
    if(junction || faces_here == 1) {
      needed.push_back(i);
      is_junction.push_back(junction);
    }
  }
}

} // namespace internal

/// Cuts disc patch `p` into pieces that each need at most four corners,
/// along shortest edge paths through its interior between two junctions.
///
/// A patch needs a corner at every junction (where the neighbour changes:
/// each side borders one neighbour) and at every ear's tip (a boundary vertex
/// with a single face of the patch: with its two neighbours on one side that
/// face is flat in the map). With more than four, runs are merged into sides
/// and some ear stays flat whatever the corners; where the border is jagged
/// (a painted region's edge) that is the rule, not the exception (doc/layout.md,
/// "Fallback patches").
/// A cut from junction to junction makes both ends corners of both pieces and
/// keeps every neighbour's run whole on one piece: no neighbour gains a
/// junction.
///
/// Which cut: among the junction pairs joined by an interior path, first
/// those that leave both pieces at most four corners, then those that leave
/// one piece four; among those the path shortest relative to the shorter of
/// the two boundary arcs it cuts off, so pieces are compact; ties go to the
/// ends' points. A cut longer than `max_cut_ratio` times that arc is not made
/// (it would leave a sliver along its path). A cut must give two discs with
/// four boundary vertices each, and one whose path leaves a piece an ear tip
/// (more corners than counted) is taken only if no other is left. Pieces are
/// cut again while they need more than four corners and a cut exists.
/// Every choice is made on points and lengths, so the pieces do not depend
/// on vertex or face order.
///
/// \returns the number of pieces (1: nothing was cut); they replace `p`, in
///          place, with no chosen corners and the parts `Segmentation::split()`
///          gives (1, 2 for one cut; a piece cut again gets 11, 12, ...)
template <class TriangleMesh, class VertexPointMap>
std::size_t split_at_junctions(const TriangleMesh& tm, VertexPointMap vpm, Segmentation<TriangleMesh>& seg, std::size_t p,
                               double max_cut_ratio = 0.5)
{
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  constexpr std::size_t none = std::numeric_limits<std::size_t>::max();
  auto findex = get(boost::face_index, tm);
  const auto loops = patch_loops(tm, vpm, seg, p);
  if(loops.size() != 1) return 1;
  const auto& loop = loops.front();
  const std::size_t n = loop.vertices.size();
  std::vector<std::size_t> needed;  // loop positions, in order
  std::vector<char> is_junction;
  internal::needed_corners(tm, seg, p, loop, needed, is_junction);
  const std::size_t k = needed.size();
  if(k <= 4) return 1;

  // The patch's vertices, numbered locally in the order of their points, and
  // the edges of its faces in that order: ties between paths of equal length
  // then break the same way whatever the mesh's vertex and face order.
  auto vindex = get(boost::vertex_index, tm);
  auto eindex = get(boost::edge_index, tm);
  std::vector<vertex_descriptor> vertex_of;
  for(face_descriptor f : seg.patch_faces[p])
    for(vertex_descriptor v : CGAL::vertices_around_face(halfedge(f, tm), tm)) vertex_of.push_back(v);
  std::sort(vertex_of.begin(), vertex_of.end(), [&](vertex_descriptor a, vertex_descriptor b) {
    return get(vpm, a) != get(vpm, b) ? get(vpm, a) < get(vpm, b) : get(vindex, a) < get(vindex, b);
  });
  vertex_of.erase(std::unique(vertex_of.begin(), vertex_of.end()), vertex_of.end());
  std::unordered_map<std::size_t, std::size_t> local;
  for(std::size_t i = 0; i < vertex_of.size(); ++i) local.emplace(static_cast<std::size_t>(get(vindex, vertex_of[i])), i);
  auto local_of = [&](vertex_descriptor v) { return local.at(static_cast<std::size_t>(get(vindex, v))); };
  struct Step { std::size_t to; double length; std::size_t edge; };
  std::vector<std::vector<Step>> steps(vertex_of.size());
  for(face_descriptor f : seg.patch_faces[p])
    for(auto h : CGAL::halfedges_around_face(halfedge(f, tm), tm)) {
      const std::size_t a = local_of(source(h, tm)), b = local_of(target(h, tm));
      const double length = std::sqrt(CGAL::to_double(CGAL::squared_distance(get(vpm, source(h, tm)), get(vpm, target(h, tm)))));
      const std::size_t e = static_cast<std::size_t>(get(eindex, edge(h, tm)));
      steps[a].push_back({b, length, e});
      steps[b].push_back({a, length, e});
    }
  for(auto& out : steps) std::sort(out.begin(), out.end(), [](const Step& x, const Step& y) { return x.to < y.to; });
  std::vector<char> on_loop(vertex_of.size(), 0);
  for(vertex_descriptor v : loop.vertices) on_loop[local_of(v)] = 1;

  // Shortest paths from one junction that pass through interior vertices only.
  struct Paths { std::vector<double> distance; std::vector<std::size_t> from, by_edge; };
  auto paths_from = [&](std::size_t source) {
    Paths paths{std::vector<double>(vertex_of.size(), std::numeric_limits<double>::infinity()),
                std::vector<std::size_t>(vertex_of.size(), none), std::vector<std::size_t>(vertex_of.size(), none)};
    using Entry = std::pair<double, std::size_t>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
    paths.distance[source] = 0.;
    queue.emplace(0., source);
    while(!queue.empty()) {
      const auto [d, u] = queue.top();
      queue.pop();
      if(d > paths.distance[u] || (u != source && on_loop[u])) continue;  // a boundary vertex ends a path
      for(const Step& s : steps[u])
        if(d + s.length < paths.distance[s.to]) {
          paths.distance[s.to] = d + s.length;
          paths.from[s.to] = u;
          paths.by_edge[s.to] = s.edge;
          queue.emplace(paths.distance[s.to], s.to);
        }
    }
    return paths;
  };
  std::vector<Paths> from_needed(k);
  for(std::size_t i = 0; i < k; ++i)
    if(is_junction[i]) from_needed[i] = paths_from(local_of(loop.vertices[needed[i]]));

  // Arc lengths summed from their first vertex, so that they do not depend on where the loop starts.
  auto arc = [&](std::size_t a, std::size_t b) {
    double length = 0.;
    for(std::size_t i = a; i != b; i = (i + 1) % n) length += loop.length[i];
    return length;
  };
  // A cut between needed corners i and i + m leaves m + 1 and k - m + 1 to the pieces.
  struct Cut { int fit; double score; std::size_t i, m, lower, upper; };  // lower, upper: local indices of its ends
  std::vector<Cut> cuts;
  for(std::size_t i = 0; i < k; ++i)
    for(std::size_t m = 2; m + 2 <= k; ++m) {
      const std::size_t j = (i + m) % k;
      if(!is_junction[i] || !is_junction[j] || j < i) continue;  // each pair once
      const std::size_t a = local_of(loop.vertices[needed[i]]), b = local_of(loop.vertices[needed[j]]);
      const double length = from_needed[i].distance[b];
      if(!std::isfinite(length)) continue;
      const std::size_t larger = std::max(m + 1, k - m + 1), smaller = std::min(m + 1, k - m + 1);
      const int fit = larger <= 4 ? 0 : (smaller == 4 ? 1 : 2);
      const double shorter = std::min(arc(needed[i], needed[j]), arc(needed[j], needed[i]));
      const double score = length / std::max(shorter, 1e-300);
      if(score > max_cut_ratio) continue;  // a piece would be a sliver along the cut
      cuts.push_back({fit, score, i, m, std::min(a, b), std::max(a, b)});
    }
  // Equal scores (a symmetric patch) by the ends' points, not by loop position.
  std::sort(cuts.begin(), cuts.end(), [](const Cut& a, const Cut& b) {
    return std::tie(a.fit, a.score, a.lower, a.upper) < std::tie(b.fit, b.score, b.lower, b.upper);
  });

  // The first cut whose pieces need no more corners than counted above (a
  // vertex of the path can be an ear tip of a piece); failing that, the first
  // that gives two discs.
  std::unique_ptr<Segmentation<TriangleMesh>> cut_made;
  for(const Cut& c : cuts) {
    const Paths& paths = from_needed[c.i];
    std::set<std::size_t> cut;
    for(std::size_t v = local_of(loop.vertices[needed[(c.i + c.m) % k]]); paths.from[v] != none; v = paths.from[v])
      cut.insert(paths.by_edge[v]);
    auto pieces = internal::components_across(tm, seg.patch_faces[p], cut);
    if(pieces.size() != 2) continue;
    // The larger piece first (by 3D area; within a relative 1e-9, the one
    // with the smaller face centroid), so that the order does not depend on
    // face order.
    auto area_of = [&](const std::vector<face_descriptor>& piece) {
      double area = 0.;
      for(face_descriptor f : piece)
        area += CGAL::to_double(CGAL::Polygon_mesh_processing::face_area(f, tm, CGAL::parameters::vertex_point_map(vpm)));
      return area;
    };
    auto lowest_centroid = [&](const std::vector<face_descriptor>& piece) {
      auto lowest = internal::face_centroid(tm, piece.front(), vpm);
      for(face_descriptor f : piece) lowest = std::min(lowest, internal::face_centroid(tm, f, vpm));
      return lowest;
    };
    const double area0 = area_of(pieces[0]), area1 = area_of(pieces[1]);
    if(std::abs(area0 - area1) > 1e-9 * std::max(area0, area1) ? area1 > area0
                                                               : lowest_centroid(pieces[1]) < lowest_centroid(pieces[0]))
      std::swap(pieces[0], pieces[1]);
    auto trial = std::make_unique<Segmentation<TriangleMesh>>(seg);
    trial->split(p, std::move(pieces), findex);
    bool discs = true;
    std::size_t needed_after = 0;  // k + 2 if the path left no ear tip: its ends count twice
    std::vector<Patch_loop<TriangleMesh>> piece_loops;
    for(std::size_t q = p; q < p + 2 && discs; ++q) {
      discs = static_cast<bool>(check_patch_disc(tm, vpm, *trial, q, piece_loops));
      if(!discs) break;
      discs = piece_loops.front().vertices.size() >= 4;
      std::vector<std::size_t> piece_needed;
      std::vector<char> piece_junction;
      internal::needed_corners(tm, *trial, q, piece_loops.front(), piece_needed, piece_junction);
      needed_after += piece_needed.size();
    }
    if(!discs) continue;
    const bool as_counted = needed_after <= k + 2;
    if(!cut_made) cut_made = std::move(trial);
    else if(as_counted) cut_made = std::move(trial);
    if(as_counted) break;
  }
  if(!cut_made) return 1;
  seg = std::move(*cut_made);
  // Each piece again, the later one first so that p's index stays put.
  const std::size_t second = split_at_junctions(tm, vpm, seg, p + 1, max_cut_ratio);
  return split_at_junctions(tm, vpm, seg, p, max_cut_ratio) + second;
}

} // namespace diffuv

#endif // DIFFUV_PATCHES_SPLIT_AT_JUNCTIONS_H
