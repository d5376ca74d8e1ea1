// diffuv: from a mesh (and perhaps region labels) to disc patches ready to map.
#ifndef DIFFUV_PATCHES_DISC_PATCHES_H
#define DIFFUV_PATCHES_DISC_PATCHES_H

#include <diffuv/error.h>
#include <diffuv/patches/disc_topology.h>
#include <diffuv/patches/flat_faces.h>
#include <diffuv/patches/segmentation.h>
#include <diffuv/patches/split_patches.h>

#include <CGAL/Polygon_mesh_processing/connected_components.h>

#include <string>
#include <vector>

namespace diffuv {

/// Options of `disc_patches()`.
struct Patching_options {
  bool split_caps = true;        ///< split caps (one neighbour all around) in two, as the paper recommends
  bool strict = false;           ///< report a labelled region that is not a disc instead of cutting it
  /// hand a face left flat by its patch's four sides to a neighbouring patch
  /// (`hand_flat_faces_to_neighbours()`)
  bool hand_off_flat_faces = true;
  Voronoi_options automatic;     ///< automatic patches: how many to start from
};

/// What `disc_patches()` did.
struct Patching_report {
  bool automatic = false;          ///< no labels were given: patches were made automatically
  std::size_t components = 1;      ///< connected components of the mesh (counted when no labels were given)
  std::size_t whole_components = 0;  ///< components that were discs, kept as one patch each
  std::size_t merged = 0;          ///< patches with fewer than four boundary vertices merged into a neighbour
  std::size_t cut = 0;             ///< non-disc patches cut into discs
  std::size_t caps_split = 0;      ///< caps split in two
  std::size_t flat_faces_handed = 0;  ///< faces flat on one side of their patch, handed to a neighbouring patch
  std::vector<std::size_t> not_discs;  ///< patches left that are not discs (none unless `strict` or a cut failed)
};

/// Cuts `tm` into disc patches.
///
/// With `face_labels` (#F entries), each connected component of a label is a
/// patch; patches with fewer than four boundary vertices are merged into a
/// neighbour; a patch that is not a disc is cut into discs (or, with `strict`,
/// reported); caps are split in two. Without labels (empty vector), each
/// connected component that is a disc is one patch and any other component is
/// cut automatically (`voronoi_discs()`). Last, a face that the patch's four
/// sides would leave flat is handed to a neighbouring patch
/// (`hand_flat_faces_to_neighbours()`, `hand_off_flat_faces`).
///
/// \returns `not_a_disc` (detail: the first bad patch) if a patch that is not a
///          disc is left, `ok` otherwise; `seg` is filled in both cases
template <class TriangleMesh, class VertexPointMap>
Status disc_patches(const TriangleMesh& tm, std::vector<int> face_labels, VertexPointMap vpm,
                    Segmentation<TriangleMesh>& seg, const Patching_options& options = Patching_options(),
                    Patching_report* report = nullptr)
{
  Patching_report local;
  Patching_report& r = report ? *report : local;
  r = Patching_report();
  auto findex = get(boost::face_index, tm);
  // `strict` is about the given regions: automatic patches are ours to cut
  // further (voronoi_discs() may stop at max_patches with a non-disc left).
  const bool labelled = !face_labels.empty();

  if(face_labels.empty()) {
    face_labels.assign(num_faces(tm), 0);
    if(!check_disc(tm)) {
      // Component by component: a component that is a disc stays whole (one
      // patch), any other one is cut automatically.
      std::vector<std::size_t> component(num_faces(tm));
      r.components = CGAL::Polygon_mesh_processing::connected_components(
          tm, boost::make_iterator_property_map(component.begin(), findex));
      std::vector<int> component_labels(component.begin(), component.end());
      const Segmentation<TriangleMesh> by_component = patches_from_labels(tm, component_labels, vpm);
      int next_label = 0;
      for(std::size_t c = 0; c < by_component.number_of_patches(); ++c) {
        const auto& part = by_component.patch_faces[c];
        if(check_patch_disc(tm, by_component, c)) {
          for(auto f : part) face_labels[get(findex, f)] = next_label;
          ++next_label;
          ++r.whole_components;
          continue;
        }
        r.automatic = true;
        voronoi_discs(tm, part, vpm, face_labels, next_label, options.automatic);
        for(auto f : part) next_label = (std::max)(next_label, face_labels[get(findex, f)] + 1);
      }
    } else {
      r.whole_components = 1;
    }
  }

  seg = patches_from_labels(tm, face_labels, vpm);
  r.merged = merge_small_patches(tm, face_labels, seg, vpm);

  for(std::size_t p = 0; p < seg.number_of_patches(); ++p) {
    if(check_patch_disc(tm, seg, p)) continue;
    if(options.strict && labelled) { r.not_discs.push_back(p); continue; }
    const std::size_t pieces = cut_into_discs(tm, seg, p, vpm, options.automatic);
    if(pieces > 1) {
      ++r.cut;
      p += pieces - 1;
    } else {
      r.not_discs.push_back(p);
    }
  }
  if(options.split_caps) {
    // Caps are found first, then split: splitting one cap must not change
    // whether its neighbour counts as one (two caps side by side both split).
    std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor> caps;
    for(std::size_t p = 0; p < seg.number_of_patches(); ++p)
      if(is_cap(tm, seg, p, vpm)) caps.push_back(seg.patch_faces[p].front());
    for(auto f : caps)
      if(split_cap(tm, seg, seg.face_patch[get(findex, f)], vpm)) ++r.caps_split;
  }
  if(options.hand_off_flat_faces) r.flat_faces_handed = hand_flat_faces_to_neighbours(tm, seg, vpm);
  // Indices of the bad patches may have moved with the splits: recompute them.
  r.not_discs.clear();
  for(std::size_t p = 0; p < seg.number_of_patches(); ++p)
    if(!check_patch_disc(tm, seg, p)) r.not_discs.push_back(p);
  if(!r.not_discs.empty())
    return check_patch_disc(tm, seg, r.not_discs.front());
  return Status();
}

} // namespace diffuv

#endif // DIFFUV_PATCHES_DISC_PATCHES_H
