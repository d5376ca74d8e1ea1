// diffuv: what a patch is called — its key (region label, part, rank) and the
// one name every report of it uses ("3", "0.1", "0.1#2").
#ifndef DIFFUV_PATCHES_PATCH_NAMES_H
#define DIFFUV_PATCHES_PATCH_NAMES_H

#include <diffuv/patches/segmentation.h>

#include <cstddef>
#include <map>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace diffuv {

/// What pairs a patch of one mesh with a patch of another: (region label,
/// part, rank). The part numbers the pieces of a cut region and the halves of
/// a split cap; the rank orders the patches with the same label and part (the
/// components of one label) by decreasing area.
using Patch_key = std::tuple<int, int, int>;

/// The key of every patch of `seg`, by patch; no two are equal.
template <class TriangleMesh>
std::vector<Patch_key> patch_keys(const Segmentation<TriangleMesh>& seg)
{
  std::vector<Patch_key> keys;
  std::map<std::pair<int, int>, int> rank;
  for(std::size_t p = 0; p < seg.number_of_patches(); ++p)
    keys.emplace_back(seg.patch_label[p], seg.patch_part[p], rank[{seg.patch_label[p], seg.patch_part[p]}]++);
  return keys;
}

/// The name of the patch with key `key`: its label, then `.part` for a piece
/// of a cut region or a split cap, then `#k` for the k-th patch (k >= 2, by
/// decreasing area) with the same label and part ("3", "0.1", "0.1#2").
/// Distinct keys give distinct names.
inline std::string patch_name(const Patch_key& key)
{
  const auto& [label, part, rank] = key;
  std::string name = std::to_string(label);
  if(part != 0) name += "." + std::to_string(part);
  if(rank != 0) name += "#" + std::to_string(rank + 1);
  return name;
}

/// The name of every patch of `seg` (`patch_name()` of its key), by patch.
template <class TriangleMesh>
std::vector<std::string> patch_names(const Segmentation<TriangleMesh>& seg)
{
  std::vector<std::string> names;
  for(const Patch_key& key : patch_keys(seg)) names.push_back(patch_name(key));
  return names;
}

} // namespace diffuv

#endif // DIFFUV_PATCHES_PATCH_NAMES_H
