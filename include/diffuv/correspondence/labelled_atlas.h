// diffuv: a labelled mesh made ready for correspondence — labels cleaned,
// regions cut into disc patches, every patch mapped onto its square.
//
// The paper (section 1.1.3 and its conclusion): two meshes segmented into the
// same regions are linked by giving each surface point the same
// (region, u, v). Everything between the labels and (u,v) — the cleaning, the
// cut of a non-disc region, the split of a cap, the sides and corners — depends
// only on the labels and the surface, so it lands in the same place on both.
#ifndef DIFFUV_CORRESPONDENCE_LABELLED_ATLAS_H
#define DIFFUV_CORRESPONDENCE_LABELLED_ATLAS_H

#include <diffuv/atlas/Uv_atlas.h>
#include <diffuv/core/error.h>
#include <diffuv/graph/distance_tags.h>
#include <diffuv/parameterization/parameterize_patches.h>
#include <diffuv/parameterization/repair_folds.h>
#include <diffuv/correspondence/clean_labels.h>
#include <diffuv/patches/patch_names.h>
#include <diffuv/layout/disc_patches.h>
#include <diffuv/layout/sub_patches.h>

#include <map>
#include <stdexcept>
#include <tuple>
#include <utility>
#include <vector>

namespace diffuv {

/// Options of `build_labelled_atlas()`.
struct Labelled_atlas_options {

  bool clean = true;                  ///< clean the labels first (`clean_labels()`)
  Label_cleaning_options cleaning;
  /// Cut of non-disc regions, split of caps. The regions themselves are the
  /// patches (`Patch_layout::voronoi`): the four-sided layout would cut each
  /// region into cells from seeds placed on each mesh's own tessellation, and
  /// two meshes' cells would not correspond. No flat triangle is handed to a
  /// neighbouring patch here (`hand_off_flat_triangles`), for the reason below:
  /// the two meshes' patches would differ where their tessellations differ.
  Patching_options patching = [] {
    Patching_options o;
    o.layout = Patch_layout::voronoi;
    o.hand_off_flat_triangles = false;
    return o;
  }();
  /// Move corners onto ear tips so that no triangle is flat (`region_sides()`):
  /// off here. A move can take a corner half a side away, and two
  /// tessellations have their ears in different places, so the corners (and
  /// the whole chart) would no longer agree; a flat triangle only makes point
  /// location pick its neighbour.
  bool move_corners_off_ears = false;
  /// Fold repair of each chart: off by default here. Correspondence locates
  /// points by their (u,v), and the raw diffusion coordinates are the same
  /// smooth functions of the surface on any tessellation, where a repaired
  /// chart is re-solved wherever that tessellation folded, differently on
  /// each mesh: the raw charts map closer to the truth (measured in
  /// doc/correspondence.md). Point location stays well defined on a fold (it
  /// picks one sheet by a rule that does not depend on the numbering).
  Repair_options repair{false};
  /// Split regions with three or five and more runs of neighbours into
  /// four-sided sectors (`split_regions_into_quads()`): a rule on the
  /// region's border alone, so both meshes get the same sub-patches. Off by
  /// default: measured on CGAL's meshes with Voronoi labels, the sectors'
  /// inner cuts land differently on another tessellation and cost more
  /// accuracy than the folds they remove (doc/correspondence.md), and a label
  /// missing in one mesh changes its neighbours' sectors too.
  bool sub_patches = false;
  Sub_patch_options sub_patching;
};

/// A mesh with region labels, cut into disc patches, each patch a chart.
template <class TriangleMesh>
struct Labelled_atlas {
  explicit Labelled_atlas(const TriangleMesh& tm) : atlas(tm) {}

  std::vector<int> face_labels;                       ///< #F entries: the labels after cleaning
  Label_cleaning_report cleaning;                     ///< what the cleaning changed
  Segmentation<TriangleMesh> segmentation;            ///< disc patches, each a (label, part)
  Patching_report patching;                           ///< regions cut, caps split
  Sub_patch_report sub_patching;                      ///< regions split into four-sided sectors
  /// The runs each split region was cut along, by the region's key before the
  /// split (`patch_keys()` of the disc patches): what another mesh follows.
  std::map<std::tuple<int, int, int>, std::vector<Run_key>> split_runs;
  std::vector<Patch_result<TriangleMesh>> patches;    ///< #P entries: each patch's chart (or why it has none)
  Uv_atlas<TriangleMesh> atlas;                       ///< one chart per mapped patch

  const TriangleMesh& mesh() const { return atlas.mesh(); }
};

/// The corners of every mapped patch of `atlas` by their regions, by patch key:
/// what another mesh's atlas follows (`build_labelled_atlas()`'s `follow`).
template <class TriangleMesh>
std::map<Patch_key, Corner_names> corner_names_by_key(const Labelled_atlas<TriangleMesh>& atlas)
{
  std::map<Patch_key, Corner_names> names;
  const std::vector<Patch_key> keys = patch_keys(atlas.segmentation);
  for(std::size_t p = 0; p < keys.size() && p < atlas.patches.size(); ++p)
    if(atlas.patches[p].status && atlas.patches[p].side_report.names.valid)
      names.emplace(keys[p], atlas.patches[p].side_report.names);
  return names;
}

/// What a second mesh's atlas follows of a first one, so that both make the
/// same choices where their tessellations could tip them apart.
struct Atlas_to_follow {
  std::map<Patch_key, Corner_names> corners;             ///< `corner_names_by_key()`
  std::map<Patch_key, std::vector<Run_key>> split_runs;  ///< `Labelled_atlas::split_runs`
};

/// The corners and the splits of `atlas`, for `build_labelled_atlas()`'s `follow`.
template <class TriangleMesh>
Atlas_to_follow atlas_to_follow(const Labelled_atlas<TriangleMesh>& atlas)
{
  return {corner_names_by_key(atlas), atlas.split_runs};
}

namespace internal {

template <class DistanceTag, class TriangleMesh, class VertexPointMap>
Status build_labelled_atlas(const TriangleMesh& tm, VertexPointMap vpm, std::vector<int> face_labels,
                            const Atlas_to_follow* follow, Labelled_atlas<TriangleMesh>& out,
                            const Labelled_atlas_options& options)
{
  if(face_labels.empty()) return Status(Status_code::no_labels);
  if(face_labels.size() != num_faces(tm))
    throw std::invalid_argument("build_labelled_atlas: face_labels must have one entry per face");
  if(options.clean) out.cleaning = clean_labels(tm, vpm, face_labels, options.cleaning);
  out.face_labels = face_labels;
  disc_patches(tm, vpm, std::move(face_labels), out.segmentation, options.patching, &out.patching);
  if(options.sub_patches) {
    const std::vector<Patch_key> region_keys = patch_keys(out.segmentation);
    std::vector<std::vector<Run_key>> followed;
    if(follow)
      for(const Patch_key& key : region_keys) {
        const auto it = follow->split_runs.find(key);
        followed.push_back(it == follow->split_runs.end() ? std::vector<Run_key>() : it->second);
      }
    out.sub_patching = split_regions_into_quads(tm, vpm, out.segmentation, options.sub_patching, follow ? &followed : nullptr);
    for(std::size_t p = 0; p < region_keys.size(); ++p)
      if(!out.sub_patching.runs[p].empty()) out.split_runs.emplace(region_keys[p], out.sub_patching.runs[p]);
  }
  std::vector<Corner_names> names;
  if(follow) {
    for(const Patch_key& key : patch_keys(out.segmentation)) {
      const auto it = follow->corners.find(key);
      names.push_back(it == follow->corners.end() ? Corner_names() : it->second);
    }
  }
  Patch_parameterization_options mapping;
  mapping.repair = options.repair;
  mapping.corner_names = follow ? &names : nullptr;
  mapping.move_corners_off_ears = options.move_corners_off_ears;
  out.patches = parameterize_patches<DistanceTag>(tm, vpm, out.segmentation, out.atlas, mapping);
  return Status();
}

} // namespace internal

/// Cleans `face_labels`, cuts the regions into disc patches and maps each
/// patch onto its square (`parameterize_patches()`).
///
/// Regions with three or five and more runs of neighbours are split into
/// four-sided sectors (`split_regions_into_quads()`, `sub_patches`).
///
/// With `follow` (`atlas_to_follow()` of another mesh's atlas), a region is
/// split only if the region with the same key was split there, along the runs
/// of the same neighbours, and a patch with the same key takes its corners at
/// the same junctions of regions as there, where they are found
/// (`region_sides()`): two meshes whose labels differ a little along borders
/// (where four regions meet at a vertex on one, three and three at two
/// vertices on the other) then agree on their sub-patches and corners.
///
/// \param face_labels #F entries (by face index); empty means "no labels"
/// \returns `no_labels` if `face_labels` is empty (a correspondence needs the
///          same regions on both meshes: automatic patches would not match);
///          otherwise `ok` — patches that are not discs or could not be mapped
///          are reported in `out.patching.not_discs` and `out.patches[p].status`
/// \throws std::invalid_argument if `face_labels` has neither 0 nor #F entries
template <class DistanceTag = Default_distance_tag, class TriangleMesh, class VertexPointMap>
Status build_labelled_atlas(const TriangleMesh& tm, VertexPointMap vpm, std::vector<int> face_labels,
                            Labelled_atlas<TriangleMesh>& out,
                            const Labelled_atlas_options& options = Labelled_atlas_options())
{
  return internal::build_labelled_atlas<DistanceTag>(tm, vpm, std::move(face_labels), nullptr, out, options);
}

/// Same as above, following another mesh's atlas (`atlas_to_follow()`).
template <class DistanceTag = Default_distance_tag, class TriangleMesh, class VertexPointMap>
Status build_labelled_atlas(const TriangleMesh& tm, VertexPointMap vpm, std::vector<int> face_labels,
                            const Atlas_to_follow& follow, Labelled_atlas<TriangleMesh>& out,
                            const Labelled_atlas_options& options = Labelled_atlas_options())
{
  return internal::build_labelled_atlas<DistanceTag>(tm, vpm, std::move(face_labels), &follow, out, options);
}

} // namespace diffuv

#endif // DIFFUV_CORRESPONDENCE_LABELLED_ATLAS_H
