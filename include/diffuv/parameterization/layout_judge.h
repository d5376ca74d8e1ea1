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
#include <diffuv/graph/distance_tags.h>
#include <diffuv/metrics/distortion.h>
#include <diffuv/parameterization/parameterize_patches.h>
#include <diffuv/patches/segmentation.h>

#include <cstddef>
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
template <class TriangleMesh, class VertexPointMap>
class Raw_map_judge {
public:
  Raw_map_judge(const TriangleMesh& tm, VertexPointMap vpm, const Raw_map_judge_options& options = Raw_map_judge_options())
    : tm_(&tm), vpm_(vpm), options_(options) {}

  /// \returns the positions of the patches of `layout` to refine
  std::vector<std::size_t> operator()(const Segmentation<TriangleMesh>& layout) const
  {
    Uv_atlas<TriangleMesh> atlas(*tm_);
    const auto results = parameterize_patches(*tm_, layout, vpm_, atlas, Fmm_distance_tag(), Fibonacci_heap_tag(),
                                              Repair_options{false}, nullptr, true, options_.threads);
    std::vector<std::size_t> bad;
    for(std::size_t p = 0; p < results.size(); ++p) {
      if(!results[p].status) {
        bad.push_back(p);
        continue;
      }
      const std::size_t c = results[p].chart;
      const Distortion_summary d = measure_distortion(*tm_, atlas.chart(c).faces, vpm_, atlas.chart_texture_map(c));
      if(!d.injective() || d.stretch_l2 > options_.max_stretch || d.area_mean > options_.max_area) bad.push_back(p);
    }
    return bad;
  }

private:
  const TriangleMesh* tm_;
  VertexPointMap vpm_;
  Raw_map_judge_options options_;
};

} // namespace diffuv

#endif // DIFFUV_PARAMETERIZATION_LAYOUT_JUDGE_H
