// diffuv: the patches `diffuv param` maps, in one call.
//
// `disc_patches()` lives below the parameterization layer, so on its own it
// cannot map a patch to see whether the layout serves the diffusion map; its
// default judge refines nothing. This header joins the two: the four-sided
// layout refined by `Raw_map_judge` until the raw maps are good, with the
// fallback patches' corners chosen by their maps. Without the judge, cow's
// layout leaves about four times as many vertices for the fold repair
// (doc/layout.md, "The library's default").
#ifndef DIFFUV_PARAMETERIZATION_DIFFUSION_PATCHES_H
#define DIFFUV_PARAMETERIZATION_DIFFUSION_PATCHES_H

#include <diffuv/core/error.h>
#include <diffuv/layout/disc_patches.h>
#include <diffuv/parameterization/layout_judge.h>
#include <diffuv/patches/segmentation.h>

#include <utility>
#include <vector>

namespace diffuv {

/// Cuts `tm` into disc patches for the diffusion map, as `diffuv param` does:
/// `disc_patches()` with a `Raw_map_judge` (built on `judging`), so that the
/// four-sided layout is split further where a patch's raw map folds or
/// stretches, and the corners of patches without them are chosen by their
/// maps. Same parameters, result and status as `disc_patches()`.
template <class TriangleMesh, class VertexPointMap>
Status diffusion_patches(const TriangleMesh& tm, VertexPointMap vpm, std::vector<int> face_labels,
                         Segmentation<TriangleMesh>& seg, const Patching_options& options = Patching_options(),
                         Patching_report* report = nullptr, const Raw_map_judge_options& judging = Raw_map_judge_options())
{
  const Raw_map_judge<TriangleMesh, VertexPointMap> judge(tm, vpm, judging);
  return disc_patches(tm, vpm, std::move(face_labels), seg, options, report, judge);
}

/// The same with the mesh's own points.
template <class TriangleMesh>
Status diffusion_patches(const TriangleMesh& tm, std::vector<int> face_labels, Segmentation<TriangleMesh>& seg,
                         const Patching_options& options = Patching_options(), Patching_report* report = nullptr,
                         const Raw_map_judge_options& judging = Raw_map_judge_options())
{
  return diffusion_patches(tm, get(CGAL::vertex_point, tm), std::move(face_labels), seg, options, report, judging);
}

} // namespace diffuv

#endif // DIFFUV_PARAMETERIZATION_DIFFUSION_PATCHES_H
