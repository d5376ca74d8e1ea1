// diffuv: marks on the indices of a whole mesh, cleared in O(1).
//
// Per-patch work (the disc check of every patch, again at every refinement
// step) must cost O(patch), not O(mesh): a fresh std::vector<bool> of the
// mesh's size per patch made the disc checks of a 17k-vertex mesh with 41
// patches a quarter of the whole parameterization (doc/performance.md).
#ifndef DIFFUV_INTERNAL_INDEX_MARKS_H
#define DIFFUV_INTERNAL_INDEX_MARKS_H

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace diffuv {
namespace internal {

/// A set of indices in [0, n): a stamp per index and a generation number, so
/// that emptying the set is O(1) (amortised over 2^32 uses) and the storage
/// (4 bytes per index) is reused from one patch to the next.
class Index_marks {
public:
  /// Empties the set and makes room for indices up to `n - 1`.
  void reset(std::size_t n)
  {
    if(stamp_.size() < n) stamp_.resize(n, 0);
    if(++generation_ == 0) { // wrapped around: old stamps could match again
      std::fill(stamp_.begin(), stamp_.end(), 0);
      generation_ = 1;
    }
  }
  /// Adds `i`; false if it was already there.
  bool insert(std::size_t i)
  {
    if(stamp_[i] == generation_) return false;
    stamp_[i] = generation_;
    return true;
  }
  bool contains(std::size_t i) const { return stamp_[i] == generation_; }

private:
  std::vector<std::uint32_t> stamp_;
  std::uint32_t generation_ = 0;
};

} // namespace internal
} // namespace diffuv

#endif // DIFFUV_INTERNAL_INDEX_MARKS_H
