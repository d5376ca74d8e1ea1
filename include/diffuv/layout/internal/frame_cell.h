// diffuv: extremities of the four-sided layout. A cell much deeper than its
// rim is wide (a finger, a horn, a hoof) would give sectors that run from its
// tip down to two short sides at its rim. It is framed instead: walls from
// each junction and midpoint on its rim up to an inner loop round its tip, and
// the tip split in quads inside that loop, so that each wall has a side
// running the whole length (the paper's section 2.7).
#ifndef DIFFUV_LAYOUT_INTERNAL_FRAME_CELL_H
#define DIFFUV_LAYOUT_INTERNAL_FRAME_CELL_H

#include <diffuv/layout/fan_split.h>
#include <diffuv/layout/internal/local_region.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <functional>
#include <limits>
#include <queue>
#include <unordered_map>
#include <utility>
#include <vector>

namespace diffuv {
namespace internal {

/// Quads as their faces and their corners, counter-clockwise.
template <class TriangleMesh>
using Quad_pieces = std::vector<std::pair<std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>,
                                          std::array<typename boost::graph_traits<TriangleMesh>::vertex_descriptor, 4>>>;

// A framed split of a deep disc cell (see the top of this header): a fan from its
// deepest vertex to every junction and midpoint on its rim (`loop`, with
// `junctions` positions in it and `mid_of(a)` the midpoint of the arc after
// junction a), each sector cut across near the tip into a wall (two rim
// corners, two on the inner loop) and an inner piece; inner pieces pair into
// quads round the centre (one quad when there are four). Appends the quads
// (faces, corners counter-clockwise) to `out` and returns true, or returns
// false and appends nothing.
template <class TriangleMesh, class VertexPointMap, class MidOf>
bool frame_cell(const TriangleMesh& tm, VertexPointMap vpm,
                const std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>& faces,
                const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& loop,
                const std::vector<std::size_t>& junctions, MidOf mid_of, std::vector<int>& scratch,
                Quad_pieces<TriangleMesh>& out)
{
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  auto vindex = get(boost::vertex_index, tm);
  const auto region = make_local_region(tm, vpm, faces, loop, scratch);
  const std::size_t k = junctions.size(), n = 2 * k;
  std::vector<int> targets;
  for(std::size_t a = 0; a < k; ++a) {
    targets.push_back(region.local(get(vindex, loop[junctions[a]])));
    targets.push_back(region.local(get(vindex, mid_of(a))));
  }
  for(int t : targets)
    if(t < 0) return false;
  std::vector<double> depth;
  region.dijkstra(region.loop, depth);
  int centre = -1;
  for(std::size_t i = 0; i < region.verts.size(); ++i)
    if(!region.on_border[i] && region.neighbours[i].size() >= n && (centre < 0 || depth[i] > depth[static_cast<std::size_t>(centre)]))
      centre = static_cast<int>(i);
  if(centre < 0) return false;
  Fan fan;
  if(fan_split(region, targets, fan, 1.5, centre) != Fan_failure::none) return false;

  // The inner loop crosses each cut a quarter of the rim's length from the
  // centre (a hemisphere's geodesic radius), at most 0.6 of the shortest cut.
  double rim = 0, shortest = std::numeric_limits<double>::infinity();
  for(std::size_t i = 0; i < region.loop.size(); ++i) rim += region.length(region.loop[i], region.loop[(i + 1) % region.loop.size()]);
  std::vector<double> cut_length(n, 0.);
  for(std::size_t a = 0; a < n; ++a) {
    for(std::size_t i = 1; i < fan.cuts[a].size(); ++i) cut_length[a] += region.length(fan.cuts[a][i - 1], fan.cuts[a][i]);
    shortest = std::min(shortest, cut_length[a]);
  }
  const double reach = std::min(rim / 4, 0.6 * shortest);
  std::vector<int> inner_corner(n, -1);
  std::vector<char> on_cut(region.verts.size(), 0);
  for(std::size_t a = 0; a < n; ++a) {
    const auto& cut = fan.cuts[a];
    if(cut.size() < 3) return false;
    for(int v : cut) on_cut[static_cast<std::size_t>(v)] = 1;
    double along = 0;
    for(std::size_t i = 1; i + 1 < cut.size(); ++i) {
      along += region.length(cut[i - 1], cut[i]);
      inner_corner[a] = cut[i];
      if(along >= reach) break;
    }
  }
  auto key = [](int x, int y) { return (static_cast<long long>(std::min(x, y)) << 32) | static_cast<long long>(std::max(x, y)); };
  std::unordered_map<long long, std::vector<std::size_t>> faces_of_edge;
  for(std::size_t f = 0; f < region.face_verts.size(); ++f)
    for(int e = 0; e < 3; ++e) faces_of_edge[key(region.face_verts[f][e], region.face_verts[f][(e + 1) % 3])].push_back(f);
  std::vector<std::vector<face_descriptor>> wall(n), inner(n);
  for(std::size_t s = 0; s < n; ++s) {
    const int from = inner_corner[s], to = inner_corner[(s + 1) % n];
    // The vertices strictly inside sector s, and the two inner corners.
    std::vector<char> allowed(region.verts.size(), 0);
    for(std::size_t f = 0; f < region.face_verts.size(); ++f)
      if(fan.sector_of_face[f] == static_cast<int>(s))
        for(int v : region.face_verts[f])
          if(!region.on_border[static_cast<std::size_t>(v)] && !on_cut[static_cast<std::size_t>(v)]) allowed[static_cast<std::size_t>(v)] = 1;
    allowed[static_cast<std::size_t>(from)] = allowed[static_cast<std::size_t>(to)] = 1;
    auto in_sector = [&](int x, int y) {
      for(std::size_t f : faces_of_edge[key(x, y)])
        if(fan.sector_of_face[f] == static_cast<int>(s)) return true;
      return false;
    };
    std::vector<double> dist(region.verts.size(), std::numeric_limits<double>::infinity());
    std::vector<int> prev(region.verts.size(), -1);
    using Entry = std::pair<double, int>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
    dist[static_cast<std::size_t>(from)] = 0;
    queue.emplace(0., from);
    while(!queue.empty()) {
      const auto [d, i] = queue.top();
      queue.pop();
      if(d > dist[static_cast<std::size_t>(i)]) continue;
      if(i == to) break;
      for(int j : region.neighbours[static_cast<std::size_t>(i)]) {
        if(!allowed[static_cast<std::size_t>(j)] || !in_sector(i, j)) continue;
        const double nd = d + region.length(i, j);
        if(nd < dist[static_cast<std::size_t>(j)]) {
          dist[static_cast<std::size_t>(j)] = nd;
          prev[static_cast<std::size_t>(j)] = i;
          queue.emplace(nd, j);
        }
      }
    }
    if(prev[static_cast<std::size_t>(to)] < 0) return false;
    std::unordered_map<long long, char> blocked;
    for(int i = to; i != from; i = prev[static_cast<std::size_t>(i)]) blocked[key(i, prev[static_cast<std::size_t>(i)])] = 1;
    // The wall: the sector's faces reached from its rim without crossing the path.
    std::vector<char> outer(region.face_verts.size(), 0);
    std::vector<std::size_t> stack;
    for(std::size_t f = 0; f < region.face_verts.size(); ++f) {
      if(fan.sector_of_face[f] != static_cast<int>(s)) continue;
      for(int e = 0; e < 3; ++e) {
        const int x = region.face_verts[f][e], y = region.face_verts[f][(e + 1) % 3];
        if(faces_of_edge[key(x, y)].size() == 1 && !outer[f]) { outer[f] = 1; stack.push_back(f); }
      }
    }
    while(!stack.empty()) {
      const std::size_t f = stack.back();
      stack.pop_back();
      for(int e = 0; e < 3; ++e) {
        const int x = region.face_verts[f][e], y = region.face_verts[f][(e + 1) % 3];
        if(blocked.count(key(x, y))) continue;
        for(std::size_t g : faces_of_edge[key(x, y)])
          if(!outer[g] && fan.sector_of_face[g] == static_cast<int>(s)) { outer[g] = 1; stack.push_back(g); }
      }
    }
    for(std::size_t f = 0; f < region.face_verts.size(); ++f) {
      if(fan.sector_of_face[f] != static_cast<int>(s)) continue;
      (outer[f] ? wall[s] : inner[s]).push_back(region.faces[f]);
      if(outer[f])
        for(int v : region.face_verts[f])
          if(v == centre) return false;  // the path does not separate the tip from the rim
    }
    if(wall[s].empty() || inner[s].empty()) return false;
  }
  const vertex_descriptor c = region.verts[static_cast<std::size_t>(centre)];
  auto b = [&](std::size_t a) { return region.verts[static_cast<std::size_t>(inner_corner[a % n])]; };
  auto p = [&](std::size_t a) { return region.verts[static_cast<std::size_t>(targets[a % n])]; };
  const std::size_t first = out.size();
  for(std::size_t s = 0; s < n; ++s) out.emplace_back(std::move(wall[s]), std::array<vertex_descriptor, 4>{p(s), p(s + 1), b(s + 1), b(s)});
  if(n == 4) {
    std::vector<face_descriptor> tip;
    for(auto& piece : inner) tip.insert(tip.end(), piece.begin(), piece.end());
    out.emplace_back(std::move(tip), std::array<vertex_descriptor, 4>{b(0), b(1), b(2), b(3)});
  } else {
    for(std::size_t s = 0; s < n; s += 2) {
      std::vector<face_descriptor> tip = std::move(inner[s]);
      tip.insert(tip.end(), inner[s + 1].begin(), inner[s + 1].end());
      out.emplace_back(std::move(tip), std::array<vertex_descriptor, 4>{c, b(s), b(s + 1), b(s + 2)});
    }
  }
  (void)first;
  return true;
}

} // namespace internal
} // namespace diffuv

#endif // DIFFUV_LAYOUT_INTERNAL_FRAME_CELL_H
