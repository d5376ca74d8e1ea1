// diffuv: judging a layout of patches by the diffusion map each patch gets.
//
// The four-sided layout (patches/quad_layout.h) is refined until the raw
// diffusion map is good (issue #18): a patch whose map folds, squashes its
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

#include <algorithm>
#include <cstddef>
#include <memory>
#include <unordered_map>
#include <vector>

namespace diffuv {

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
    const std::size_t n = layout.number_of_patches();
    std::vector<std::size_t> bad;
    // The patches to map: those without corners and those not judged before.
    // The others are emptied, not removed, so that the numbering stays and a
    // patch without corners sees the same neighbours.
    Segmentation<TriangleMesh> to_map = layout;
    std::vector<std::vector<std::size_t>> keys(n);
    std::vector<char> wanted(n, 1);
    for(std::size_t p = 0; p < n; ++p) {
      if(!layout.corners(p)) continue;
      keys[p] = key_of(layout, p);
      const auto found = verdicts_->find(keys[p]);
      if(found == verdicts_->end()) continue;
      if(found->second) bad.push_back(p);
      wanted[p] = 0;
      to_map.patch_faces[p].clear();
    }
    Uv_atlas<TriangleMesh> atlas(*tm_);
    const auto results = parameterize_patches(*tm_, to_map, vpm_, atlas, Fmm_distance_tag(), Fibonacci_heap_tag(),
                                              Repair_options{false}, nullptr, true, options_.threads);
    for(std::size_t p = 0; p < n; ++p) {
      if(!wanted[p]) continue;
      bool is_bad = !results[p].status;
      if(!is_bad) {
        const std::size_t c = results[p].chart;
        const Distortion_summary d = measure_distortion(*tm_, atlas.chart(c).faces, vpm_, atlas.chart_texture_map(c));
        is_bad = !d.injective() || d.stretch_l2 > options_.max_stretch || d.area_mean > options_.max_area;
      }
      if(is_bad) bad.push_back(p);
      if(!keys[p].empty()) verdicts_->emplace(std::move(keys[p]), is_bad);
    }
    std::sort(bad.begin(), bad.end());
    return bad;
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
