// diffuv: from a mesh (and perhaps region labels) to disc patches ready to map.
#ifndef DIFFUV_PATCHES_DISC_PATCHES_H
#define DIFFUV_PATCHES_DISC_PATCHES_H

#include <diffuv/error.h>
#include <diffuv/patches/disc_topology.h>
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
  Voronoi_options automatic;     ///< automatic patches: how many to start from
};

/// What `disc_patches()` did.
struct Patching_report {
  bool automatic = false;          ///< no labels were given: patches were made automatically
  std::size_t merged = 0;          ///< patches with fewer than four boundary vertices merged into a neighbour
  std::size_t cut = 0;             ///< non-disc patches cut into discs
  std::size_t caps_split = 0;      ///< caps split in two
  std::vector<std::size_t> not_discs;  ///< patches left that are not discs (none unless `strict` or a cut failed)
};

/// Cuts `tm` into disc patches.
///
/// With `face_labels` (#F entries), each connected component of a label is a
/// patch; patches with fewer than four boundary vertices are merged into a
/// neighbour; a patch that is not a disc is cut into discs (or, with `strict`,
/// reported); caps are split in two. Without labels (empty vector), a disc mesh
/// is one patch and any other mesh is cut automatically (`voronoi_discs()`,
/// connected component by connected component).
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

  if(face_labels.empty()) {
    face_labels.assign(num_faces(tm), 0);
    if(!check_disc(tm)) {
      r.automatic = true;
      std::vector<std::size_t> component(num_faces(tm));
      const std::size_t components = CGAL::Polygon_mesh_processing::connected_components(
          tm, boost::make_iterator_property_map(component.begin(), findex));
      std::vector<std::vector<typename boost::graph_traits<TriangleMesh>::face_descriptor>> parts(components);
      for(auto f : faces(tm)) parts[component[get(findex, f)]].push_back(f);
      int next_label = 0;
      for(const auto& part : parts) {
        voronoi_discs(tm, part, vpm, face_labels, next_label, options.automatic);
        for(auto f : part) next_label = (std::max)(next_label, face_labels[get(findex, f)] + 1);
      }
    }
  }

  seg = patches_from_labels(tm, face_labels, vpm);
  r.merged = merge_small_patches(tm, face_labels, seg, vpm);

  for(std::size_t p = 0; p < seg.number_of_patches(); ++p) {
    if(check_patch_disc(tm, seg, p)) continue;
    if(options.strict) { r.not_discs.push_back(p); continue; }
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
