// diffuv: a hash for lists of indices, the keys of the layout's memos.
#ifndef DIFFUV_INTERNAL_INDEX_LIST_HASH_H
#define DIFFUV_INTERNAL_INDEX_LIST_HASH_H

#include <cstddef>
#include <cstdint>
#include <vector>

namespace diffuv {
namespace internal {

/// FNV-1a over the numbers of a list (faces of a patch, vertices of a loop):
/// the memos keep the whole list as the key, so a collision costs a compare, not a wrong result.
struct Index_list_hash {
  std::size_t operator()(const std::vector<std::size_t>& key) const
  {
    std::uint64_t h = 1469598103934665603ull;
    for(std::size_t x : key) h = (h ^ static_cast<std::uint64_t>(x)) * 1099511628211ull;
    return static_cast<std::size_t>(h);
  }
};

} // namespace internal
} // namespace diffuv

#endif // DIFFUV_INTERNAL_INDEX_LIST_HASH_H
