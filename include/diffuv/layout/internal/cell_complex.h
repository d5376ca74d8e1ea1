// diffuv: the cell complex the four-sided layout splits (quads_from_cells()):
// each cell's rim as runs of one neighbour ("arcs") between junctions, with
// the midpoint where each arc is cut, and the cells that are extremities.
#ifndef DIFFUV_LAYOUT_INTERNAL_CELL_COMPLEX_H
#define DIFFUV_LAYOUT_INTERNAL_CELL_COMPLEX_H

#include <diffuv/layout/internal/local_region.h>
#include <diffuv/patches/segmentation.h>

#include <CGAL/boost/graph/iterator.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <unordered_map>
#include <vector>

namespace diffuv {
namespace internal {

/// A run of one neighbour along a cell's rim, between two junctions.
template <class TriangleMesh>
struct Cell_arc {
  static constexpr std::size_t none = std::numeric_limits<std::size_t>::max();
  double length = 0;
  std::size_t interior = 0;          // vertices strictly inside the arc
  typename boost::graph_traits<TriangleMesh>::vertex_descriptor mid;
  bool has_mid = false;
  bool near_junction = false;        // the crossing is next to an end of a short arc
  bool collapsed = false;
  std::array<std::size_t, 2> cell{{none, none}};  // `none` on the mesh border
  std::array<std::size_t, 2> end{{none, none}};   // junction vertex indices
};

/// A cell's rim: its border loop cut at its junctions into arcs.
template <class TriangleMesh>
struct Cell_rim {
  Patch_loop<TriangleMesh> loop;
  std::vector<std::size_t> junctions;  // loop positions
  std::vector<std::size_t> arc;        // arc a runs from junctions[a] to junctions[a+1]
};

/// The cells' arcs and what becomes of each cell.
template <class TriangleMesh>
struct Cell_complex {
  static constexpr std::size_t none = Cell_arc<TriangleMesh>::none;
  std::vector<Cell_arc<TriangleMesh>> arcs;
  std::vector<Cell_rim<TriangleMesh>> cell;  // by cell
  std::vector<char> fallback;                // cells left as ordinary patches (not a disc, no fan)
  std::vector<char> framed;                  // extremities, framed by walls (frame_cell.h)
};

/// The arcs of every disc cell, each found once and shared by its two cells,
/// with their midpoints; cells with more than one border loop or fewer than
/// two junctions are marked as fallbacks. `centre_distance`: each face's
/// distance to its cell's centre (cell_centres.h).
template <class TriangleMesh, class VertexPointMap>
Cell_complex<TriangleMesh> cell_complex(const TriangleMesh& tm, VertexPointMap vpm, const Segmentation<TriangleMesh>& cells,
                                        const std::vector<double>& centre_distance)
{
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  constexpr std::size_t none = Cell_complex<TriangleMesh>::none;
  auto vindex = get(boost::vertex_index, tm);
  auto findex = get(boost::face_index, tm);
  auto eindex = get(boost::edge_index, tm);
  const std::size_t nc = cells.number_of_patches();
  Cell_complex<TriangleMesh> complex;
  auto& arcs = complex.arcs;
  complex.cell.resize(nc);
  complex.fallback.assign(nc, 0);
  complex.framed.assign(nc, 0);
  std::unordered_map<std::size_t, std::size_t> arc_of_edge;  // smallest edge index -> arc
  for(std::size_t c = 0; c < nc; ++c) {
    auto loops = patch_loops(tm, vpm, cells, c);
    if(loops.size() != 1) { complex.fallback[c] = 1; continue; }
    Cell_rim<TriangleMesh>& cc = complex.cell[c];
    cc.loop = std::move(loops.front());
    const auto& loop = cc.loop;
    const std::size_t n = loop.vertices.size();
    for(std::size_t i = 0; i < n; ++i)
      if(loop.neighbour[(i + n - 1) % n] != loop.neighbour[i]) cc.junctions.push_back(i);
    const std::size_t k = cc.junctions.size();
    if(k < 2) { complex.fallback[c] = 1; continue; }
    for(std::size_t a = 0; a < k; ++a) {
      const std::size_t from = cc.junctions[a], to = cc.junctions[(a + 1) % k];
      std::size_t smallest = none;
      for(std::size_t i = from; i != to; i = (i + 1) % n)
        smallest = std::min<std::size_t>(smallest, get(eindex, edge(loop.halfedges[i], tm)));
      auto found = arc_of_edge.find(smallest);
      if(found != arc_of_edge.end()) {
        arcs[found->second].cell[1] = c;
        cc.arc.push_back(found->second);
        continue;
      }
      Cell_arc<TriangleMesh> arc;
      arc.cell[0] = c;
      arc.end = {static_cast<std::size_t>(get(vindex, loop.vertices[from])), static_cast<std::size_t>(get(vindex, loop.vertices[to]))};
      const std::size_t neighbour = loop.neighbour[from];
      if(neighbour == Patch_loop<TriangleMesh>::mesh_border) arc.cell[1] = none;
      // The midpoint: the interior vertex where the two cells' centres are
      // nearest each other across the arc (the dual edge's crossing); on the
      // mesh border, the one nearest the cell's centre. A vertex's distance to
      // a centre goes through its nearest face (the face's distance plus the
      // way to its centroid); on a tie, the vertex nearer the arc's middle.
      double best = std::numeric_limits<double>::infinity(), best_middle = best;
      std::size_t best_step = 0, step = 0;
      for(std::size_t i = from; i != to; i = (i + 1) % n) arc.length += loop.length[i];
      double along = 0;
      for(std::size_t i = (from + 1) % n; i != to; i = (i + 1) % n) {
        ++step;
        along += loop.length[(i + n - 1) % n];
        const vertex_descriptor v = loop.vertices[i];
        const auto& pv = get(vpm, v);
        double mine = std::numeric_limits<double>::infinity(), theirs = neighbour == Patch_loop<TriangleMesh>::mesh_border ? 0. : mine;
        for(auto h : CGAL::halfedges_around_target(halfedge(v, tm), tm)) {
          const auto f = face(h, tm);
          if(f == boost::graph_traits<TriangleMesh>::null_face()) continue;
          const std::size_t owner = cells.face_patch[get(findex, f)];
          const auto g = halfedge(f, tm);
          const double to_centroid = std::sqrt(CGAL::to_double(CGAL::squared_distance(
              pv, CGAL::centroid(get(vpm, source(g, tm)), get(vpm, target(g, tm)), get(vpm, target(next(g, tm), tm))))));
          const double d = centre_distance[get(findex, f)] + to_centroid;
          if(owner == c) mine = std::min(mine, d);
          else if(owner == neighbour) theirs = std::min(theirs, d);
        }
        const double sum = mine + theirs, middle = std::abs(along - arc.length / 2);
        if(!arc.has_mid || sum < best || (sum == best && middle < best_middle)) {
          best = sum;
          best_middle = middle;
          arc.mid = v;
          arc.has_mid = true;
          best_step = step;
        }
      }
      arc.interior = step;
      arc.near_junction = arc.has_mid && step < 4 && (best_step == 1 || best_step == step);
      arc_of_edge.emplace(smallest, arcs.size());
      cc.arc.push_back(arcs.size());
      arcs.push_back(arc);
    }
  }
  return complex;
}

/// Marks as `framed` the cells much deeper than their rim is wide (depth from
/// the border above `frame_depth` times rim length / 2 pi) whose arcs all have
/// a midpoint and a neighbour: the extremities (frame_cell.h).
template <class TriangleMesh, class VertexPointMap>
void mark_deep_cells(const TriangleMesh& tm, VertexPointMap vpm, const Segmentation<TriangleMesh>& cells, double frame_depth,
                     Cell_complex<TriangleMesh>& complex, std::vector<int>& scratch)
{
  if(frame_depth <= 0) return;
  for(std::size_t c = 0; c < cells.number_of_patches(); ++c) {
    if(complex.fallback[c] || complex.cell[c].arc.size() < 2) continue;
    bool usable = true;
    for(std::size_t a : complex.cell[c].arc) usable = usable && complex.arcs[a].has_mid && complex.arcs[a].cell[1] != Cell_complex<TriangleMesh>::none;
    if(!usable) continue;
    const auto region = make_local_region(tm, vpm, cells.patch_faces[c], complex.cell[c].loop.vertices, scratch);
    std::vector<double> depth;
    region.dijkstra(region.loop, depth);
    double deepest = 0, rim = 0;
    for(std::size_t i = 0; i < depth.size(); ++i) deepest = std::max(deepest, depth[i]);
    for(double l : complex.cell[c].loop.length) rim += l;
    complex.framed[c] = deepest > frame_depth * rim / (2 * M_PI);
  }
}

} // namespace internal
} // namespace diffuv

#endif // DIFFUV_LAYOUT_INTERNAL_CELL_COMPLEX_H
