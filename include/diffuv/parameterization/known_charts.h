// diffuv: maps of patches made once and taken again.
//
// `diffusion_patches()` decides to keep a disc whole by mapping it with the
// default pipeline (fast marching and the repair); `parameterize_patches()`
// then maps the same disc, with the same corners, the same way. On a
// 1.1M-vertex disc that second map was a quarter of the whole run
// (doc/performance.md, "A disc kept whole mapped once"). The judge leaves its
// maps here, and `parameterize_patches()` takes one instead of mapping its
// patch when every input of the map is the same: the patch's faces in the
// same order, the same four sides vertex for vertex, the same distance and
// heap, the same repair options. The chart is then the one the map would
// have given, bit for bit.
#ifndef DIFFUV_PARAMETERIZATION_KNOWN_CHARTS_H
#define DIFFUV_PARAMETERIZATION_KNOWN_CHARTS_H

#include <diffuv/core/four_sides.h>
#include <diffuv/internal/index_list_hash.h>
#include <diffuv/parameterization/repair_folds.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/graph/properties.hpp>

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <mutex>
#include <typeindex>
#include <unordered_map>
#include <utility>
#include <vector>

namespace diffuv {

/// Maps of patches, each kept with everything it was computed from, so that
/// `parameterize_patches()` (`Patch_parameterization_options::known_charts`)
/// can take one instead of mapping its patch again. Filled by `Raw_map_judge`
/// (`Raw_map_judge_options::known_charts`) with the maps of the discs it keeps
/// whole. Vertices are kept by their `vertex_index`, faces by `face_index`,
/// and the key names the mesh object and its sizes, so a map is never taken
/// for another mesh; it is for the same mesh with other points, so use one
/// `Known_charts` for one mesh whose points do not change between the calls
/// (as the tool does). Adding is thread-safe; find only once nothing is being added.
class Known_charts {
public:
  /// A patch's map: its vertices (by index) and their (u,v), in the order
  /// `parameterize_patches()` gives them to the atlas, and the repair's report.
  struct Chart {
    std::vector<std::size_t> vertices;
    std::vector<std::array<double, 2>> uv;
    Repair_report repair;
  };

  /// The key of a patch: the mesh (its address and sizes), its faces in
  /// order, then its four sides in the order of `Side`, each after a separator.
  template <class TriangleMesh, class FaceRange>
  static std::vector<std::size_t> key(const TriangleMesh& tm, const FaceRange& faces,
                                      const Four_sides<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& sides)
  {
    auto findex = get(boost::face_index, tm);
    auto vindex = get(boost::vertex_index, tm);
    std::vector<std::size_t> k;
    k.reserve(faces.size() + sides.v1.size() + sides.u2.size() + sides.v2.size() + sides.u1.size() + 7);
    k.push_back(reinterpret_cast<std::uintptr_t>(&tm));
    k.push_back(static_cast<std::size_t>(num_vertices(tm)));
    k.push_back(static_cast<std::size_t>(num_faces(tm)));
    for(auto f : faces) k.push_back(static_cast<std::size_t>(get(findex, f)));
    for(Side s : all_sides) {
      k.push_back(separator);
      for(auto v : sides[s]) k.push_back(static_cast<std::size_t>(get(vindex, v)));
    }
    return k;
  }

  /// Keeps `chart`, the map of the patch of key `key` with distances of the
  /// kind `DistanceTag`, heap `HeapTag` and the repair `repair`.
  template <class DistanceTag, class HeapTag>
  void add(std::vector<std::size_t> key, const Repair_options& repair, Chart chart)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    charts_.insert_or_assign(std::move(key), Entry{typeid(DistanceTag), typeid(HeapTag), repair, std::move(chart)});
  }

  /// The map kept for `key` if it was made with the same distances, heap and
  /// repair options, else null.
  template <class DistanceTag, class HeapTag>
  const Chart* find(const std::vector<std::size_t>& key, const Repair_options& repair) const
  {
    const auto found = charts_.find(key);
    if(found == charts_.end()) return nullptr;
    const Entry& e = found->second;
    if(e.distance != std::type_index(typeid(DistanceTag)) || e.heap != std::type_index(typeid(HeapTag)) ||
       e.repair != repair)
      return nullptr;
    ++taken_;
    return &e.chart;
  }

  std::size_t size() const { return charts_.size(); }
  bool empty() const { return charts_.empty(); }
  /// How many charts `find()` has given.
  std::size_t taken() const { return taken_; }

private:
  static constexpr std::size_t separator = std::numeric_limits<std::size_t>::max();

  struct Entry {
    std::type_index distance, heap;
    Repair_options repair;
    Chart chart;
  };

  std::unordered_map<std::vector<std::size_t>, Entry, internal::Index_list_hash> charts_;
  std::mutex mutex_;
  mutable std::atomic<std::size_t> taken_{0};
};

} // namespace diffuv

#endif // DIFFUV_PARAMETERIZATION_KNOWN_CHARTS_H
