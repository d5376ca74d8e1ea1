// diffuv: judging a layout of patches by the diffusion map each patch gets.
//
// The four-sided layout (layout/quad_layout.h) is refined until the raw
// diffusion map is good: a patch whose map folds, squashes its
// triangles or stretches them too much asks for its cell to be split. This
// judge maps every patch the way the default pipeline does (fast marching,
// here without the fold repair) and measures it on the patch's own
// rectangle, as its chart is written.
#ifndef DIFFUV_PARAMETERIZATION_LAYOUT_JUDGE_H
#define DIFFUV_PARAMETERIZATION_LAYOUT_JUDGE_H

#include <diffuv/atlas/Uv_atlas.h>
#include <diffuv/internal/index_list_hash.h>
#include <diffuv/graph/distance_tags.h>
#include <diffuv/graph/edge_length_map.h>
#include <diffuv/graph/heap_tags.h>
#include <diffuv/parameterization/chart_rectangle.h>
#include <diffuv/parameterization/diffusion_coordinates.h>
#include <diffuv/parameterization/known_charts.h>
#include <diffuv/metrics/distortion.h>
#include <diffuv/parameterization/parameterize_patches.h>
#include <diffuv/patches/patch_mesh.h>
#include <diffuv/patches/segmentation.h>

#include <CGAL/Kernel/global_functions.h>


#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <numeric>
#include <tuple>
#include <unordered_map>
#include <vector>

namespace diffuv {

/// Options of `choose_fallback_corners()`.
struct Fallback_corner_options {
  double min_stretch = 2.0;   ///< patches whose map has a lower L2 stretch keep their corners
  std::size_t pool = 7;       ///< corners chosen among this many loop vertices (junctions, then the sharpest)
  double min_gain = 0.02;     ///< a choice replaces the rule's only if its L2 is lower by this fraction
  std::size_t threads = 0;    ///< threads mapping the patches (0: all, with oneTBB)
  /// A patch with at least this many faces has its candidates ranked by a
  /// quick estimate first (`internal::estimate_corner_choices()`), and only the
  /// best `mapped_candidates` are mapped; smaller patches map every candidate.
  std::size_t estimate_from_faces = 2000;
  std::size_t mapped_candidates = 2;  ///< candidates mapped per large patch, best estimates first
  /// Also the patches that have corners (the layout's quads): their own
  /// corners are the rule a choice must beat.
  bool patches_with_corners = false;
};

namespace internal {

// A score rounded to 9 significant digits (on a log scale), so that two
// copies of a patch whose sums ran in another order (faces turned, shuffled)
// see the same ties.
inline double rounded_score(double x)
{
  if(!(x > 0) || !std::isfinite(x)) return x;
  return std::round(std::log(x) * 1e9);
}

// Four corners' points in increasing order: a key for a choice of corners
// that does not depend on where the boundary loop starts or which way it runs.
template <class VertexPointMap, class Corners>
auto sorted_corner_points(VertexPointMap vpm, const Corners& corners)
{
  std::array<typename boost::property_traits<VertexPointMap>::value_type, 4> points;
  for(std::size_t k = 0; k < 4; ++k) points[k] = get(vpm, corners[k]);
  std::sort(points.begin(), points.end());
  return points;
}

// A quick estimate of the L2 stretch that each choice of four corners among
// `pool` (increasing positions in `loop`, a patch's boundary loop) gives the
// raw map of the patch `faces`. The pool cuts the loop into arcs, and a
// choice's sides are runs of whole arcs, so one distance run per arc serves
// all choices: a side's distance is the least of its arcs'. That is exact for
// graph distances, the default here. Fast marching is not additive that way
// (the least of two arcs' fronts is up to 2 % farther than the front of both,
// in a wedge from their common end), and the raw map's L2, dominated by its
// thinnest triangles, then moves by up to 10x; graph distances rank the
// choices as well (cow, bull, elephant: the same L2 after mapping the best 2
// or 3, measured) and cost less. No repair, no corner moved off an ear; the
// map is measured on its least-stretch rectangle. Costs |pool| distance runs
// and, per choice, a pass over the vertices and one over the faces, instead
// of four runs, the repair and the chart.
// \tparam DistanceTag the distances diffused (graph/distance_tags.h)
// \returns one L2 per choice (infinite where the map cannot be measured)
template <class DistanceTag = Graph_distance_tag, class TriangleMesh, class VertexPointMap, class FaceRange>
std::vector<double> estimate_corner_choices(const TriangleMesh& tm, VertexPointMap vpm, const FaceRange& faces,
                                            const std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& loop,
                                            const std::vector<std::size_t>& pool,
                                            const std::vector<std::array<std::size_t, 4>>& choices)
{
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  // The patch as a mesh of its own: O(patch), where a filtered graph of the
  // whole mesh and the whole mesh's edge lengths cost O(mesh) per patch.
  Patch_mesh<TriangleMesh, VertexPointMap> copy;
  if(!copy.build(tm, vpm, faces))
    return std::vector<double>(choices.size(), std::numeric_limits<double>::infinity());
  using Patch = typename Patch_mesh<TriangleMesh, VertexPointMap>::Mesh;
  const Patch& patch = copy.mesh();
  auto pindex = get(boost::vertex_index, patch);
  const std::size_t nv = num_vertices(patch), k = pool.size(), m = loop.size();
  // Arc a: from loop[pool[a]] to loop[pool[a+1]], both ends included.
  std::vector<std::vector<double>> arc_distance(k, std::vector<double>(nv));
  Distance_engine<Patch, DistanceTag, Fibonacci_heap_tag> engine(patch);
  const auto lengths = edge_length_map(patch);
  for(std::size_t a = 0; a < k; ++a) {
    std::vector<typename Patch::Vertex_index> arc;
    for(std::size_t i = pool[a];; i = (i + 1) % m) {
      arc.push_back(copy.local(tm, loop[i]));
      if(i == pool[(a + 1) % k]) break;
    }
    if(!engine.run(arc, lengths, boost::make_iterator_property_map(arc_distance[a].begin(), pindex)))
      return std::vector<double>(choices.size(), std::numeric_limits<double>::infinity());
  }
  // Per face: its vertices and 3D edges. On the rectangle (w, h) of least
  // stretch, w/h = sqrt(P/Q) with P, Q the area-weighted sums of |dx/du|^2 and
  // |dx/dv|^2, and the L2 stretch, normalised as measure_distortion() does
  // (times sqrt of the uv area over the 3D area), is sqrt(sqrt(P Q) U) / A
  // (U: uv area on the unit square, A: 3D area); see chart_rectangle.h.
  struct Face_data {
    std::array<std::size_t, 3> v;
    std::array<double, 3> dp1, dp2;
    double area;
  };
  std::vector<Face_data> face_data;
  double area_3d = 0;
  for(auto f : faces) {
    const auto h = halfedge(f, tm);
    const vertex_descriptor a = source(h, tm), b = target(h, tm), c = target(next(h, tm), tm);
    const auto pa = get(vpm, a), pb = get(vpm, b), pc = get(vpm, c);
    Face_data fd;
    fd.v = {static_cast<std::size_t>(get(pindex, copy.local(tm, a))), static_cast<std::size_t>(get(pindex, copy.local(tm, b))),
            static_cast<std::size_t>(get(pindex, copy.local(tm, c)))};
    fd.dp1 = {CGAL::to_double(pb.x() - pa.x()), CGAL::to_double(pb.y() - pa.y()), CGAL::to_double(pb.z() - pa.z())};
    fd.dp2 = {CGAL::to_double(pc.x() - pa.x()), CGAL::to_double(pc.y() - pa.y()), CGAL::to_double(pc.z() - pa.z())};
    const std::array<double, 3> n = {fd.dp1[1] * fd.dp2[2] - fd.dp1[2] * fd.dp2[1], fd.dp1[2] * fd.dp2[0] - fd.dp1[0] * fd.dp2[2],
                                     fd.dp1[0] * fd.dp2[1] - fd.dp1[1] * fd.dp2[0]};
    fd.area = 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    area_3d += fd.area;
    face_data.push_back(fd);
  }
  std::vector<double> estimate(choices.size(), std::numeric_limits<double>::infinity());
  std::array<std::vector<double>, 4> side;
  for(auto& d : side) d.resize(nv);
  std::vector<double> u(nv), v(nv);
  for(std::size_t c = 0; c < choices.size(); ++c) {
    // Side s runs from corner s to corner s+1: v1, u2, v2, u1 (core/four_sides.h).
    for(std::size_t s = 0; s < 4; ++s) {
      std::fill(side[s].begin(), side[s].end(), std::numeric_limits<double>::infinity());
      for(std::size_t a = choices[c][s]; a != choices[c][(s + 1) % 4]; a = (a + 1) % k)
        for(std::size_t i = 0; i < nv; ++i) side[s][i] = std::min(side[s][i], arc_distance[a][i]);
    }
    for(std::size_t i = 0; i < nv; ++i) {
      u[i] = diffusion_ratio(side[3][i], side[1][i]);
      v[i] = diffusion_ratio(side[0][i], side[2][i]);
    }
    double uv_area = 0;
    for(const Face_data& fd : face_data)
      uv_area += 0.5 * std::abs((u[fd.v[1]] - u[fd.v[0]]) * (v[fd.v[2]] - v[fd.v[0]]) - (u[fd.v[2]] - u[fd.v[0]]) * (v[fd.v[1]] - v[fd.v[0]]));
    double p = 0, q = 0;
    for(const Face_data& fd : face_data) {
      const double du1 = u[fd.v[1]] - u[fd.v[0]], dv1 = v[fd.v[1]] - v[fd.v[0]];
      const double du2 = u[fd.v[2]] - u[fd.v[0]], dv2 = v[fd.v[2]] - v[fd.v[0]];
      const double det = du1 * dv2 - du2 * dv1;
      if(!(0.5 * std::abs(det) > 1e-14 * uv_area)) continue;  // flat in uv: left out, as measure_distortion() does
      for(int x = 0; x < 3; ++x) {
        const double xu = (fd.dp1[x] * dv2 - fd.dp2[x] * dv1) / det, xv = (fd.dp2[x] * du1 - fd.dp1[x] * du2) / det;
        p += fd.area * xu * xu;
        q += fd.area * xv * xv;
      }
    }
    const double l2 = std::sqrt(std::sqrt(p * q) * uv_area) / area_3d;
    if(std::isfinite(l2) && p > 0 && q > 0) estimate[c] = l2;
  }
  return estimate;
}

} // namespace internal

/// Chooses the four corners of each patch that has none (the layout's
/// fallback patches, whose sides `region_sides()` would make by merging or
/// splitting runs of neighbours), and with `patches_with_corners` of the
/// others too (their own corners then the rule), by the map they give: among the 4-subsets of
/// a pool of loop vertices (the junctions first, the sharpest first, then the
/// sharpest other vertices), the one whose map (as the default pipeline makes
/// it: fast marching and the repair) has the lowest L2 stretch on its
/// rectangle, if it is lower than the rule's by `min_gain`. Only patches whose
/// map by the rule has an L2 above `min_stretch` are tried. The corners found
/// go into `seg.patch_corners`; such a patch's sides no longer follow its runs
/// of neighbours (a fallback patch is not conforming anyway), so this is for
/// automatic atlases, not for correspondence, whose corners must be found again
/// on another mesh. On a patch of fewer than `estimate_from_faces` faces every
/// candidate is mapped; on a larger one (a whole disc component), the
/// candidates are first ranked by a quick estimate of their raw maps
/// (`internal::estimate_corner_choices()`) and the best `mapped_candidates`
/// are mapped. The choice does not depend on the number of threads.
/// \returns the number of patches whose corners were set
///
/// `known_rule_score(p, score)`, if given, may supply the score of patch p's
/// map by the rule (its L2 stretch, infinite if not one-to-one), measured
/// exactly as here (fast marching, the repair, no warps), so that it is not
/// mapped again: `Raw_map_judge` has mapped the discs it kept whole.
template <class TriangleMesh, class VertexPointMap>
std::size_t choose_fallback_corners(const TriangleMesh& tm, VertexPointMap vpm, Segmentation<TriangleMesh>& seg,
                                    const Fallback_corner_options& options = Fallback_corner_options(),
                                    const std::function<bool(std::size_t, double&)>& known_rule_score = {})
{
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using Corners = std::array<vertex_descriptor, 4>;
  const std::size_t n = seg.number_of_patches();
  if(seg.patch_corners.size() != n) seg.patch_corners.assign(n, Segmentation<TriangleMesh>::no_corners());
  // Maps the patches given corners in `trial` (others emptied) and scores each
  // mapped patch: its L2 stretch, infinite if not one-to-one or not mapped.
  auto score = [&](const std::vector<std::size_t>& patches, const std::vector<Corners>& corners) {
    Segmentation<TriangleMesh> trial = seg;
    std::vector<char> wanted(n, 0);
    for(std::size_t i = 0; i < patches.size(); ++i) {
      wanted[patches[i]] = 1;
      trial.patch_corners[patches[i]] = corners[i];
    }
    for(std::size_t p = 0; p < n; ++p)
      if(!wanted[p]) trial.patch_faces[p].clear();
    Uv_atlas<TriangleMesh> atlas(tm);
    const auto results = parameterize_patches<Fmm_distance_tag>(tm, vpm, trial, atlas, Patch_parameterization_options{Repair_options(), nullptr, true, options.threads, Chart_drawing_options{0}});
    std::vector<double> scores(patches.size(), std::numeric_limits<double>::infinity());
    for(std::size_t i = 0; i < patches.size(); ++i) {
      const auto& r = results[patches[i]];
      if(!r.status) continue;
      const Distortion_summary d = measure_distortion(tm, vpm, atlas.chart(r.chart).faces, atlas.chart_texture_map(r.chart));
      if(d.injective()) scores[i] = d.stretch_l2;
    }
    return scores;
  };

  // The rule's corners, and the patches they serve badly.
  std::vector<std::size_t> fallback;
  std::vector<Corners> rule;
  for(std::size_t p = 0; p < n; ++p)
    if((options.patches_with_corners || !seg.corners(p)) && !seg.patch_faces[p].empty()) {
      fallback.push_back(p);
      rule.push_back(seg.patch_corners[p]);
    }
  if(fallback.empty()) return 0;
  // A patch's map does not depend on which other patches are mapped with it
  // (the others keep their faces' patch numbers), so those with a known score
  // are left out.
  std::vector<double> by_rule(fallback.size(), std::numeric_limits<double>::infinity());
  {
    std::vector<std::size_t> unknown, at;
    std::vector<Corners> unknown_corners;
    for(std::size_t i = 0; i < fallback.size(); ++i) {
      if(known_rule_score && known_rule_score(fallback[i], by_rule[i])) continue;
      unknown.push_back(fallback[i]);
      unknown_corners.push_back(rule[i]);
      at.push_back(i);
    }
    if(!unknown.empty()) {
      const std::vector<double> scored = score(unknown, unknown_corners);
      for(std::size_t t = 0; t < at.size(); ++t) by_rule[at[t]] = scored[t];
    }
  }
  std::vector<std::size_t> bad;
  std::vector<double> best, by_rule_score;
  std::vector<Corners> best_corners;
  std::vector<std::vector<Corners>> candidates;
  for(std::size_t i = 0; i < fallback.size(); ++i) {
    if(!(by_rule[i] > options.min_stretch)) continue;
    const auto loops = patch_loops(tm, vpm, seg, fallback[i]);
    if(loops.size() != 1 || loops.front().vertices.size() < 4) continue;
    const auto& loop = loops.front();
    const std::size_t m = loop.vertices.size();
    // The angle of the patch at each loop vertex: a corner is best where it is sharp.
    std::map<vertex_descriptor, std::size_t> position;
    for(std::size_t k = 0; k < m; ++k) position.emplace(loop.vertices[k], k);
    std::vector<double> angle(m, 0.);
    for(auto f : seg.patch_faces[fallback[i]])
      for(auto h : CGAL::halfedges_around_face(halfedge(f, tm), tm)) {
        const auto found = position.find(target(h, tm));
        if(found == position.end()) continue;
        angle[found->second] += CGAL::approximate_angle(get(vpm, source(h, tm)), get(vpm, target(h, tm)),
                                                        get(vpm, target(next(h, tm), tm)));
      }
    std::vector<std::size_t> order(m);
    std::iota(order.begin(), order.end(), 0);
    auto junction = [&](std::size_t k) { return loop.neighbour[(k + m - 1) % m] != loop.neighbour[k]; };
    // Ties (equal angles, to rounding) go to the vertex with the smaller
    // point, not the earlier one along the loop: the loop runs backwards on a
    // copy with its faces turned, and starts elsewhere on a shuffled one.
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      const double qa = internal::rounded_score(angle[a]), qb = internal::rounded_score(angle[b]);
      if(junction(a) != junction(b)) return junction(a);
      if(qa != qb) return qa < qb;
      return get(vpm, loop.vertices[a]) < get(vpm, loop.vertices[b]);
    });
    order.resize(std::min(order.size(), options.pool));
    std::sort(order.begin(), order.end());  // loop order: counter-clockwise
    std::vector<std::array<std::size_t, 4>> in_pool;  // positions in `order`
    const std::size_t k = order.size();
    for(std::size_t a = 0; a < k; ++a)
      for(std::size_t b = a + 1; b < k; ++b)
        for(std::size_t c = b + 1; c < k; ++c)
          for(std::size_t d = c + 1; d < k; ++d) in_pool.push_back({a, b, c, d});
    if(seg.patch_faces[fallback[i]].size() >= options.estimate_from_faces && in_pool.size() > options.mapped_candidates) {
      // A large patch: map only the choices estimated best (ties: the choice
      // of the smaller corner points).
      const std::vector<double> estimate =
          internal::estimate_corner_choices(tm, vpm, seg.patch_faces[fallback[i]], loop.vertices, order, in_pool);
      auto points_of = [&](const std::array<std::size_t, 4>& q) {
        return internal::sorted_corner_points(vpm, Corners{loop.vertices[order[q[0]]], loop.vertices[order[q[1]]],
                                                           loop.vertices[order[q[2]]], loop.vertices[order[q[3]]]});
      };
      std::vector<std::size_t> rank(in_pool.size());
      std::iota(rank.begin(), rank.end(), 0);
      std::vector<double> rounded(in_pool.size());
      std::vector<decltype(points_of(in_pool.front()))> points(in_pool.size());
      for(std::size_t c = 0; c < in_pool.size(); ++c) {
        rounded[c] = internal::rounded_score(estimate[c]);
        points[c] = points_of(in_pool[c]);
      }
      std::sort(rank.begin(), rank.end(), [&](std::size_t a, std::size_t b) {
        if(rounded[a] != rounded[b]) return rounded[a] < rounded[b];
        return points[a] < points[b];
      });
      std::vector<std::array<std::size_t, 4>> kept;
      for(std::size_t r = 0; r < options.mapped_candidates; ++r) kept.push_back(in_pool[rank[r]]);
      in_pool = std::move(kept);
    }
    std::vector<Corners> choices;
    for(const auto& q : in_pool)
      choices.push_back({loop.vertices[order[q[0]]], loop.vertices[order[q[1]]], loop.vertices[order[q[2]]], loop.vertices[order[q[3]]]});
    bad.push_back(fallback[i]);
    best.push_back(by_rule[i]);
    by_rule_score.push_back(by_rule[i]);
    best_corners.push_back(Segmentation<TriangleMesh>::no_corners());
    candidates.push_back(std::move(choices));
  }
  // Round j maps every bad patch's j-th candidate at once.
  std::size_t rounds = 0;
  for(const auto& c : candidates) rounds = std::max(rounds, c.size());
  for(std::size_t j = 0; j < rounds; ++j) {
    std::vector<std::size_t> patches;
    std::vector<Corners> corners;
    std::vector<std::size_t> which;
    for(std::size_t i = 0; i < bad.size(); ++i)
      if(j < candidates[i].size()) {
        patches.push_back(bad[i]);
        corners.push_back(candidates[i][j]);
        which.push_back(i);
      }
    const auto scored = score(patches, corners);
    for(std::size_t t = 0; t < patches.size(); ++t) {
      const std::size_t i = which[t];
      // Equal scores (to rounding): the choice of the smaller corner points,
      // whatever order the candidates came in.
      const double mine = internal::rounded_score(scored[t]), kept = internal::rounded_score(best[i]);
      const bool better = mine < kept || (mine == kept && best_corners[i][0] != boost::graph_traits<TriangleMesh>::null_vertex() &&
                                          internal::sorted_corner_points(vpm, corners[t]) <
                                              internal::sorted_corner_points(vpm, best_corners[i]));
      if(scored[t] < by_rule_score[i] * (1. - options.min_gain) && better) {
        best[i] = scored[t];
        best_corners[i] = corners[t];
      }
    }
  }
  std::size_t set = 0;
  for(std::size_t i = 0; i < bad.size(); ++i)
    if(best_corners[i][0] != boost::graph_traits<TriangleMesh>::null_vertex()) {
      seg.patch_corners[bad[i]] = best_corners[i];
      ++set;
    }
  return set;
}

/// What `Raw_map_judge` tolerates.
struct Raw_map_judge_options {
  double max_stretch = 2.0;  ///< L2 stretch of a patch's map (1 = isometric up to scale)
  double max_area = 2.5;     ///< mean area distortion of a patch's map
  std::size_t threads = 0;   ///< threads mapping the patches (0: all, with oneTBB)
  /// (`whole_patches_to_lay_out()`) the fraction of a patch's vertices that
  /// the repair may move (issue #18's target: 1 %)
  double max_moved = 0.01;
  /// (`choose_corners()`) how the corners of patches are chosen by their
  /// maps. By default the layout's quads are tried too, and every patch whose
  /// map has L2 above 1.5 (not 2): a quad too small to be split again is
  /// served by corners away from its cell's junctions (man: L2 1.51 -> 1.39).
  /// So that this costs little, the candidates are ranked by their estimate
  /// and the best 3 mapped (measured in doc/layout.md, "Corners of the quads").
  Fallback_corner_options corners = [] {
    Fallback_corner_options o;
    o.patches_with_corners = true;
    o.min_stretch = 1.5;
    o.estimate_from_faces = 0;
    o.mapped_candidates = 3;
    return o;
  }();
  /// If given, `whole_patches_to_lay_out()` leaves here the map of each disc
  /// it keeps whole, for `parameterize_patches()` to take
  /// (`Patch_parameterization_options::known_charts`) instead of mapping the
  /// disc again (the judge maps it as the default pipeline does).
  std::shared_ptr<Known_charts> known_charts;
};

/// Judges a layout by the raw diffusion map of each patch (fast marching, no
/// repair) on its own rectangle: the patches that fold, have a degenerate
/// triangle, or exceed `max_stretch` or `max_area`, or that cannot be mapped.
/// A callable for `quad_layout()` and `disc_patches()`.
///
/// `quad_layout()` asks again after each refinement round, and most quads come
/// back unchanged: the verdict on a patch with corners (its map depends on its
/// faces and corners alone) is kept, by faces and corners, and shared by the
/// copies of a judge. Patches without corners take their sides from their
/// neighbours (`region_sides()`), so they are mapped every time.
template <class TriangleMesh, class VertexPointMap>
class Raw_map_judge {
public:
  Raw_map_judge(const TriangleMesh& tm, VertexPointMap vpm, const Raw_map_judge_options& options = Raw_map_judge_options())
    : tm_(&tm), vpm_(vpm), options_(options), verdicts_(std::make_shared<Verdicts>()) {}

  /// \returns the positions of the patches of `layout` to refine, in increasing order
  std::vector<std::size_t> operator()(const Segmentation<TriangleMesh>& layout) const
  {
    return (*this)(layout, std::vector<char>(layout.number_of_patches(), 1));
  }

  /// The same, for the patches flagged in `candidates` only (#patches
  /// entries): the others are neither mapped nor returned.
  std::vector<std::size_t> operator()(const Segmentation<TriangleMesh>& layout, const std::vector<char>& candidates) const
  {
    const std::size_t n = layout.number_of_patches();
    std::vector<std::size_t> bad;
    // The patches to map: the candidates without corners and those not judged
    // before. The others are emptied, not removed, so that the numbering stays
    // and a patch without corners sees the same neighbours.
    Segmentation<TriangleMesh> to_map = layout;
    std::vector<std::vector<std::size_t>> keys(n);
    std::vector<char> wanted(n, 1);
    for(std::size_t p = 0; p < n; ++p) {
      if(p >= candidates.size() || !candidates[p]) {
        wanted[p] = 0;
        to_map.patch_faces[p].clear();
        continue;
      }
      if(!layout.corners(p)) continue;
      keys[p] = key_of(layout, p);
      const auto found = verdicts_->find(keys[p]);
      if(found == verdicts_->end()) continue;
      if(found->second) bad.push_back(p);
      wanted[p] = 0;
      to_map.patch_faces[p].clear();
    }
    Uv_atlas<TriangleMesh> atlas(*tm_);
    const auto results = parameterize_patches<Fmm_distance_tag>(*tm_, vpm_, to_map, atlas, Patch_parameterization_options{Repair_options{false}, nullptr, true, options_.threads, Chart_drawing_options{0}});
    for(std::size_t p = 0; p < n; ++p) {
      if(!wanted[p]) continue;
      bool is_bad = !results[p].status;
      if(!is_bad) {
        const std::size_t c = results[p].chart;
        const Distortion_summary d = measure_distortion(*tm_, vpm_, atlas.chart(c).faces, atlas.chart_texture_map(c));
        is_bad = !d.injective() || d.stretch_l2 > options_.max_stretch || d.area_mean > options_.max_area;
      }
      if(is_bad) bad.push_back(p);
      if(!keys[p].empty()) verdicts_->emplace(std::move(keys[p]), is_bad);
    }
    std::sort(bad.begin(), bad.end());
    return bad;
  }

  /// The patches flagged in `candidates` (#patches entries) that should not
  /// stay one patch: their map by the default pipeline (fast marching and
  /// the repair, corners by the rule) is not one-to-one, exceeds
  /// `max_stretch` or `max_area`, or had more than `max_moved` of its
  /// vertices moved by the repair (a patch that cannot be mapped at all is
  /// not returned: a layout would not help it). Called by `disc_patches()` about the
  /// components that are discs: a disc whose raw map folds a little but whose
  /// repaired map is good (a cylinder locally refined: 22 of 8,000 vertices
  /// moved, L2 1.007) stays whole. The candidates must be whole components
  /// (no neighbouring patch): each one's score is kept, by its faces, for
  /// `choose_corners()`, which then does not map it again.
  /// \returns positions, in increasing order
  std::vector<std::size_t> whole_patches_to_lay_out(const Segmentation<TriangleMesh>& seg, const std::vector<char>& candidates) const
  {
    const std::size_t n = seg.number_of_patches();
    Segmentation<TriangleMesh> to_map = seg;
    for(std::size_t p = 0; p < n; ++p)
      if(p >= candidates.size() || !candidates[p]) to_map.patch_faces[p].clear();
    Uv_atlas<TriangleMesh> atlas(*tm_);
    const Repair_options whole_map_repair;
    const auto results = parameterize_patches<Fmm_distance_tag, Fibonacci_heap_tag>(
        *tm_, vpm_, to_map, atlas, Patch_parameterization_options{whole_map_repair, nullptr, true, options_.threads, Chart_drawing_options{0}});
    std::vector<std::size_t> bad;
    for(std::size_t p = 0; p < n; ++p) {
      // A patch that cannot be mapped at all (a lone triangle: fewer than
      // four border vertices) gains nothing from a layout: it stays, and the
      // pipeline reports it.
      if(p >= candidates.size() || !candidates[p] || !results[p].status) continue;
      const std::size_t c = results[p].chart;
      const Distortion_summary d = measure_distortion(*tm_, vpm_, atlas.chart(c).faces, atlas.chart_texture_map(c));
      // The corner search (choose_corners()) would map this disc by the rule
      // again, exactly so: keep its score.
      whole_scores_->insert_or_assign(faces_key(seg, p), d.injective() ? d.stretch_l2 : std::numeric_limits<double>::infinity());
      const double moved = static_cast<double>(results[p].repair.moved_vertices + results[p].repair.moved_border_vertices);
      if(!d.injective() || d.stretch_l2 > options_.max_stretch || d.area_mean > options_.max_area ||
         moved > options_.max_moved * static_cast<double>(atlas.chart(c).vertices.size())) {
        bad.push_back(p);
      } else if(options_.known_charts) {
        // Kept whole: the pipeline would map it again, exactly so.
        Known_charts::Chart known;
        const auto vindex = get(boost::vertex_index, *tm_);
        known.vertices.reserve(atlas.chart(c).vertices.size());
        for(auto v : atlas.chart(c).vertices) known.vertices.push_back(static_cast<std::size_t>(get(vindex, v)));
        known.uv.reserve(atlas.chart(c).uv.size());
        for(const auto& q : atlas.chart(c).uv) known.uv.push_back({{q.x(), q.y()}});
        known.repair = results[p].repair;
        options_.known_charts->add<Fmm_distance_tag, Fibonacci_heap_tag>(Known_charts::key(*tm_, seg.patch_faces[p], results[p].sides),
                                                                         whole_map_repair, std::move(known));
      }
    }
    return bad;
  }

  /// The corners of the patches that have none, by their maps
  /// (`choose_fallback_corners()`, with this judge's threads); called by
  /// `disc_patches()` last. \returns the number of patches given corners
  std::size_t choose_corners(Segmentation<TriangleMesh>& seg) const
  {
    Fallback_corner_options o = options_.corners;
    o.threads = options_.threads;
    // A disc kept whole (no neighbour, so its map depends on its faces alone)
    // was mapped by whole_patches_to_lay_out() as the search maps the rule.
    const auto known = [&](std::size_t p, double& score) {
      if(seg.corners(p) || whole_scores_->empty()) return false;
      const auto found = whole_scores_->find(faces_key(seg, p));
      if(found == whole_scores_->end()) return false;
      score = found->second;
      return true;
    };
    return choose_fallback_corners(*tm_, vpm_, seg, o, known);
  }

private:
  // A patch by its faces alone (in order); `extra` entries reserved after them.
  std::vector<std::size_t> faces_key(const Segmentation<TriangleMesh>& seg, std::size_t p, std::size_t extra = 0) const
  {
    std::vector<std::size_t> key;
    key.reserve(seg.patch_faces[p].size() + extra);
    for(auto f : seg.patch_faces[p]) key.push_back(get(get(boost::face_index, *tm_), f));
    return key;
  }
  // A patch by its faces (in order) and corners.
  std::vector<std::size_t> key_of(const Segmentation<TriangleMesh>& layout, std::size_t p) const
  {
    std::vector<std::size_t> key = faces_key(layout, p, 4);
    for(auto v : layout.patch_corners[p]) key.push_back(get(get(boost::vertex_index, *tm_), v));
    return key;
  }
  using Verdicts = std::unordered_map<std::vector<std::size_t>, bool, internal::Index_list_hash>;
  using Scores = std::unordered_map<std::vector<std::size_t>, double, internal::Index_list_hash>;

  const TriangleMesh* tm_;
  VertexPointMap vpm_;
  Raw_map_judge_options options_;
  std::shared_ptr<Verdicts> verdicts_;  // true: to refine
  std::shared_ptr<Scores> whole_scores_ = std::make_shared<Scores>();  // the rule's L2 of discs judged whole
};

} // namespace diffuv

#endif // DIFFUV_PARAMETERIZATION_LAYOUT_JUDGE_H
