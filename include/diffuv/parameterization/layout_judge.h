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
#include <diffuv/metrics/distortion.h>
#include <diffuv/parameterization/parameterize_patches.h>
#include <diffuv/patches/segmentation.h>

#include <CGAL/Kernel/global_functions.h>

#include <algorithm>
#include <array>
#include <cstddef>
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
};

/// Chooses the four corners of each patch that has none (the layout's
/// fallback patches, whose sides `region_sides()` would make by merging or
/// splitting runs of neighbours) by the map they give: among the 4-subsets of
/// a pool of loop vertices (the junctions first, the sharpest first, then the
/// sharpest other vertices), the one whose map (as the default pipeline makes
/// it: fast marching and the repair) has the lowest L2 stretch on its
/// rectangle, if it is lower than the rule's by `min_gain`. Only patches whose
/// map by the rule has an L2 above `min_stretch` are tried. The corners found
/// go into `seg.patch_corners`; such a patch's sides no longer follow its runs
/// of neighbours (a fallback patch is not conforming anyway), so this is for
/// automatic atlases, not for correspondence, whose corners must be found again
/// on another mesh. Every candidate is mapped; the choice does not depend on
/// the number of threads.
/// \returns the number of patches whose corners were set
template <class TriangleMesh, class VertexPointMap>
std::size_t choose_fallback_corners(const TriangleMesh& tm, VertexPointMap vpm, Segmentation<TriangleMesh>& seg,
                                    const Fallback_corner_options& options = Fallback_corner_options())
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
    const auto results = parameterize_patches<Fmm_distance_tag>(tm, vpm, trial, atlas, Patch_parameterization_options{Repair_options(), nullptr, true, options.threads});
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
  for(std::size_t p = 0; p < n; ++p)
    if(!seg.corners(p) && !seg.patch_faces[p].empty()) fallback.push_back(p);
  if(fallback.empty()) return 0;
  const auto by_rule = score(fallback, std::vector<Corners>(fallback.size(), Segmentation<TriangleMesh>::no_corners()));
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
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return std::make_tuple(!junction(a), angle[a], a) < std::make_tuple(!junction(b), angle[b], b);
    });
    order.resize(std::min(order.size(), options.pool));
    std::sort(order.begin(), order.end());  // loop order: counter-clockwise
    std::vector<Corners> choices;
    const std::size_t k = order.size();
    for(std::size_t a = 0; a < k; ++a)
      for(std::size_t b = a + 1; b < k; ++b)
        for(std::size_t c = b + 1; c < k; ++c)
          for(std::size_t d = c + 1; d < k; ++d)
            choices.push_back({loop.vertices[order[a]], loop.vertices[order[b]], loop.vertices[order[c]], loop.vertices[order[d]]});
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
      if(scored[t] < by_rule_score[i] * (1. - options.min_gain) && scored[t] < best[i]) {
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
    const auto results = parameterize_patches<Fmm_distance_tag>(*tm_, vpm_, to_map, atlas, Patch_parameterization_options{Repair_options{false}, nullptr, true, options_.threads});
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

  /// The corners of the patches that have none, by their maps
  /// (`choose_fallback_corners()`, with this judge's threads); called by
  /// `disc_patches()` last. \returns the number of patches given corners
  std::size_t choose_corners(Segmentation<TriangleMesh>& seg) const
  {
    Fallback_corner_options o;
    o.threads = options_.threads;
    return choose_fallback_corners(*tm_, vpm_, seg, o);
  }

private:
  // A patch by its faces (in order) and corners.
  std::vector<std::size_t> key_of(const Segmentation<TriangleMesh>& layout, std::size_t p) const
  {
    std::vector<std::size_t> key;
    key.reserve(layout.patch_faces[p].size() + 4);
    for(auto f : layout.patch_faces[p]) key.push_back(get(get(boost::face_index, *tm_), f));
    for(auto v : layout.patch_corners[p]) key.push_back(get(get(boost::vertex_index, *tm_), v));
    return key;
  }
  using Verdicts = std::unordered_map<std::vector<std::size_t>, bool, internal::Index_list_hash>;

  const TriangleMesh* tm_;
  VertexPointMap vpm_;
  Raw_map_judge_options options_;
  std::shared_ptr<Verdicts> verdicts_;  // true: to refine
};

} // namespace diffuv

#endif // DIFFUV_PARAMETERIZATION_LAYOUT_JUDGE_H
