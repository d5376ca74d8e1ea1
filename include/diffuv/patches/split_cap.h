// diffuv: caps split in two.
//
// The paper (section 2.7) splits the ends of extremities (hands, feet) in two
// before mapping them: a cap has one neighbour all around, so its boundary has
// no natural corner, and its edges "overly stretch" when the whole cap is
// mapped onto a square.
#ifndef DIFFUV_PATCHES_SPLIT_CAP_H
#define DIFFUV_PATCHES_SPLIT_CAP_H

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

/// Whether patch `p` is a cap: one boundary loop with the same neighbouring
/// region label all around (not the mesh border). Labels, not patches, so that
/// a cap stays one when the region around it was cut into several pieces.
template <class TriangleMesh, class VertexPointMap>
bool is_cap(const TriangleMesh& tm, VertexPointMap vpm, const Segmentation<TriangleMesh>& seg, std::size_t p)
{
  const auto loops = patch_loops(tm, vpm, seg, p);
  if(loops.size() != 1) return false;
  const auto& n = loops.front().neighbour;
  constexpr std::size_t border = Patch_loop<TriangleMesh>::mesh_border;
  if(n.front() == border || seg.patch_label[n.front()] == seg.patch_label[p]) return false;
  return std::all_of(n.begin(), n.end(),
                     [&](std::size_t q) { return q != border && seg.patch_label[q] == seg.patch_label[n.front()]; });
}

/// Splits cap `p` in two along an edge path through its tip: the tip is the
/// vertex farthest from the cap's boundary; the cut runs from the boundary
/// vertex nearest to the tip, through the tip, to the boundary vertex halfway
/// around the loop (by arc length), along shortest edge paths. Every choice is
/// intrinsic, so the same cap on another mesh is split the same way. Part 1 is
/// the half whose boundary starts counter-clockwise at the first cut vertex.
///
/// \returns false (and leaves `seg` unchanged) if the cut does not give two disc
///          patches with at least four boundary vertices each
template <class TriangleMesh, class VertexPointMap>
bool split_cap(const TriangleMesh& tm, VertexPointMap vpm, Segmentation<TriangleMesh>& seg, std::size_t p)
{
  using Patch = CGAL::Face_filtered_graph<TriangleMesh>;
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  const auto loops = patch_loops(tm, vpm, seg, p);
  if(loops.size() != 1) return false;
  const auto& loop = loops.front();
  const std::size_t n = loop.vertices.size();

  const Patch graph(tm, seg.patch_faces[p]);
  auto pindex = get(boost::vertex_index, graph);
  const auto lengths = edge_length_map(tm, vpm); // the same point map as the cut
  Multi_source_dijkstra<Patch> dijkstra(graph);
  std::vector<double> from_border(num_vertices(graph)), from_tip(num_vertices(graph));
  dijkstra.run(loop.vertices, lengths, boost::make_iterator_property_map(from_border.begin(), pindex));
  vertex_descriptor tip = loop.vertices.front();
  for(vertex_descriptor v : vertices(graph))
    if(from_border[get(pindex, v)] > from_border[get(pindex, tip)]) tip = v;
  if(from_border[get(pindex, tip)] == 0.) return false; // no interior vertex
  dijkstra.run(std::vector<vertex_descriptor>{tip}, lengths, boost::make_iterator_property_map(from_tip.begin(), pindex));

  std::size_t first = 0;
  for(std::size_t i = 1; i < n; ++i)
    if(from_tip[get(pindex, loop.vertices[i])] < from_tip[get(pindex, loop.vertices[first])]) first = i;
  std::vector<double> at(n + 1, 0.);
  for(std::size_t i = 0; i < n; ++i) at[(i + 1)] = at[i] + loop.length[(first + i) % n];
  std::size_t half = 1;
  for(std::size_t i = 1; i < n; ++i)
    if(std::abs(at[i] - at[n] / 2) < std::abs(at[half] - at[n] / 2)) half = i;
  const vertex_descriptor ends[2] = {loop.vertices[first], loop.vertices[(first + half) % n]};

  // Shortest path from the tip to each end, walked back from the end, cut at
  // the first boundary vertex met from the tip.
  std::set<vertex_descriptor> on_loop(loop.vertices.begin(), loop.vertices.end());
  auto eindex = get(boost::edge_index, tm);
  std::set<std::size_t> cut;
  for(vertex_descriptor end : ends) {
    // chain[k] -- path[k] -- chain[k+1], from the end back to the tip.
    std::vector<vertex_descriptor> chain = {end};
    std::set<vertex_descriptor> in_chain = {end};
    std::vector<typename boost::graph_traits<TriangleMesh>::edge_descriptor> path;
    while(chain.back() != tip) {
      const vertex_descriptor x = chain.back();
      bool stepped = false;
      for(auto h : CGAL::halfedges_around_target(halfedge(x, graph), graph)) {
        const vertex_descriptor y = source(h, graph);
        // Across a zero-length edge the distance does not decrease: without
        // the check the walk went back and forth forever (found by fuzzing).
        if(from_tip[get(pindex, y)] + get(lengths, edge(h, graph)) == from_tip[get(pindex, x)] &&
           in_chain.insert(y).second) {
          path.push_back(edge(h, graph));
          chain.push_back(y);
          stepped = true;
          break;
        }
      }
      if(!stepped) return false;
    }
    // From the tip outwards, up to the first boundary vertex met.
    for(std::size_t k = path.size(); k-- > 0;) {
      cut.insert(get(eindex, path[k]));
      if(on_loop.count(chain[k])) break;
    }
  }

  auto pieces = internal::components_across(tm, seg.patch_faces[p], cut);
  if(pieces.size() != 2) return false;
  // Part 1: the piece holding the loop edge that leaves the first cut vertex.
  const auto f1 = face(loop.halfedges[first], tm);
  if(std::find(pieces[0].begin(), pieces[0].end(), f1) == pieces[0].end()) std::swap(pieces[0], pieces[1]);

  Segmentation<TriangleMesh> trial = seg;
  trial.split(p, pieces, get(boost::face_index, tm));
  for(std::size_t k = 0; k < 2; ++k) {
    if(!check_patch_disc(tm, trial, p + k)) return false;
    const auto piece_loops = patch_loops(tm, vpm, trial, p + k);
    if(piece_loops.size() != 1 || piece_loops.front().vertices.size() < 4) return false;
  }
  seg = std::move(trial);
  return true;
}

} // namespace diffuv

#endif // DIFFUV_PATCHES_SPLIT_CAP_H
