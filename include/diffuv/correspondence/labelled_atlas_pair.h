// diffuv: two labelled meshes made ready for correspondence together. A region
// that one mesh is too coarse to keep (its cleaning or its merging of small
// patches gave its faces to a neighbour) joins that neighbour on both meshes,
// so that its vertices are mapped instead of left without a counterpart.
#ifndef DIFFUV_CORRESPONDENCE_LABELLED_ATLAS_PAIR_H
#define DIFFUV_CORRESPONDENCE_LABELLED_ATLAS_PAIR_H

#include <diffuv/core/error.h>
#include <diffuv/correspondence/labelled_atlas.h>
#include <diffuv/graph/distance_tags.h>

#include <CGAL/boost/graph/iterator.h>
#include <CGAL/squared_distance_3.h>

#include <boost/graph/graph_traits.hpp>

#include <cmath>
#include <cstddef>
#include <map>
#include <memory>
#include <set>
#include <utility>
#include <vector>

namespace diffuv {

/// Options of `build_labelled_atlas_pair()`.
struct Labelled_atlas_pair_options {
  Labelled_atlas_options atlas;  ///< both meshes' atlases
  /// B follows A's sub-patches and corners (`atlas_to_follow()`).
  bool follow = true;
  /// A label of A that no face of B carries joins, on A, the region next to
  /// it with which it shares the longest border. Meant for B's labels carried
  /// from A (`nearest_face_labels()`), where such a label is a region too thin
  /// for B's faces, lost in the carrying. Off, such a label is B's choice: it
  /// stays A's alone (reported, its vertices not mapped).
  bool join_labels_missing_in_b = false;
  /// Builds of the two atlases, at most (each after a round of joins).
  int max_rounds = 4;
};

/// Two atlases built together (`build_labelled_atlas_pair()`).
template <class TriangleMesh>
struct Labelled_atlas_pair {
  std::unique_ptr<Labelled_atlas<TriangleMesh>> a, b;  ///< null if `status` is not ok
  /// Labels that joined another region on both meshes, each with the label of
  /// the region it is part of in the end.
  std::map<int, int> joined;
  int rounds = 0;  ///< builds of both atlases (1: nothing joined)
  Status status;   ///< of the last build (`no_labels` if a mesh has none)
};

/// The labels of A's patches that B's atlas lost, each with the label it
/// should join: the label that most of its faces in B took instead (B's
/// cleaning or its merging of small patches gave them away), or, with
/// `join_labels_missing_in_b` and no face of B labelled so, the label across
/// the longest border on A. Labels that B's input does not have are left
/// alone otherwise.
///
/// \param b_labels B's labels as given to `build_labelled_atlas()` (before its cleaning)
template <class TriangleMesh, class VertexPointMap>
std::map<int, int> labels_to_join(const TriangleMesh& tm_a, VertexPointMap vpm_a, const Labelled_atlas<TriangleMesh>& a,
                                  const TriangleMesh& tm_b, const std::vector<int>& b_labels,
                                  const Labelled_atlas<TriangleMesh>& b, bool join_labels_missing_in_b)
{
  const auto& seg_a = a.segmentation;
  const auto& seg_b = b.segmentation;
  const std::set<int> in_a(seg_a.patch_label.begin(), seg_a.patch_label.end());
  const std::set<int> in_b(seg_b.patch_label.begin(), seg_b.patch_label.end());
  constexpr std::size_t no_patch = Segmentation<TriangleMesh>::no_patch;

  // Votes: for each lost label, the final labels of B's faces that carried it.
  std::map<int, std::map<int, std::size_t>> votes;
  const auto findex_b = get(boost::face_index, tm_b);
  for(auto f : faces(tm_b)) {
    const std::size_t i = get(findex_b, f);
    const int label = b_labels[i];
    if(in_b.count(label) || !in_a.count(label) || seg_b.face_patch[i] == no_patch) continue;
    ++votes[label][seg_b.patch_label[seg_b.face_patch[i]]];
  }
  std::map<int, int> join;
  for(const auto& [label, counts] : votes) {
    std::size_t most = 0;
    for(const auto& [to, n] : counts)  // ties: the smaller label
      if(n > most) {
        most = n;
        join[label] = to;
      }
  }
  if(!join_labels_missing_in_b) return join;

  // Labels no face of B carried: the longest border on A to a label B kept.
  const auto findex_a = get(boost::face_index, tm_a);
  auto label_a = [&](auto f) -> int {
    const std::size_t p = seg_a.face_patch[get(findex_a, f)];
    return p == no_patch ? -1 : seg_a.patch_label[p];
  };
  std::map<int, std::map<int, double>> border;
  for(auto e : edges(tm_a)) {
    const auto h = halfedge(e, tm_a);
    const auto f = face(h, tm_a), g = face(opposite(h, tm_a), tm_a);
    if(f == boost::graph_traits<TriangleMesh>::null_face() || g == boost::graph_traits<TriangleMesh>::null_face())
      continue;
    const int lf = label_a(f), lg = label_a(g);
    if(lf == lg || lf < 0 || lg < 0) continue;
    const double length = std::sqrt(CGAL::squared_distance(get(vpm_a, source(h, tm_a)), get(vpm_a, target(h, tm_a))));
    if(!in_b.count(lf) && in_b.count(lg) && !votes.count(lf)) border[lf][lg] += length;
    if(!in_b.count(lg) && in_b.count(lf) && !votes.count(lg)) border[lg][lf] += length;
  }
  for(const auto& [label, lengths] : border) {
    double longest = 0.;
    for(const auto& [to, length] : lengths)
      if(length > longest) {
        longest = length;
        join[label] = to;
      }
  }
  return join;
}

/// Renames every label that `join` lists to the label it joins, following
/// chains (a label joined one that joined another).
inline void join_labels(std::vector<int>& labels, const std::map<int, int>& join)
{
  for(int& label : labels)
    for(std::size_t step = 0; step < join.size(); ++step) {  // a chain is never longer: no cycles
      const auto it = join.find(label);
      if(it == join.end()) break;
      label = it->second;
    }
}

/// Builds A's atlas, then B's following it (`build_labelled_atlas()`), and
/// repeats while B lost regions of A: each lost label joins its neighbour
/// (`labels_to_join()`) in both meshes' labels, and both atlases are built
/// again. On a copy of A much coarser than A, small regions lose their faces
/// to B's cleaning and merging; without the joins their vertices on A had no
/// counterpart at all (measured in doc/correspondence.md).
///
/// \param labels_a, labels_b #F entries of each mesh (by face index)
/// \returns the atlases (both null if a build failed: see `status`; only
///          `no_labels` can fail, when a label vector is empty), the joins and the rounds
/// \throws std::invalid_argument if a label vector has neither 0 nor #F entries
template <class DistanceTag = Default_distance_tag, class TriangleMesh, class VertexPointMapA, class VertexPointMapB>
Labelled_atlas_pair<TriangleMesh> build_labelled_atlas_pair(const TriangleMesh& tm_a, VertexPointMapA vpm_a,
                                                            std::vector<int> labels_a, const TriangleMesh& tm_b,
                                                            VertexPointMapB vpm_b, std::vector<int> labels_b,
                                                            const Labelled_atlas_pair_options& options =
                                                                Labelled_atlas_pair_options())
{
  Labelled_atlas_pair<TriangleMesh> out;
  for(int round = 0;; ++round) {
    auto a = std::make_unique<Labelled_atlas<TriangleMesh>>(tm_a);
    auto b = std::make_unique<Labelled_atlas<TriangleMesh>>(tm_b);
    out.status = build_labelled_atlas<DistanceTag>(tm_a, vpm_a, labels_a, *a, options.atlas);
    if(out.status)
      out.status = options.follow
                       ? build_labelled_atlas<DistanceTag>(tm_b, vpm_b, labels_b, atlas_to_follow(*a), *b, options.atlas)
                       : build_labelled_atlas<DistanceTag>(tm_b, vpm_b, labels_b, *b, options.atlas);
    if(!out.status) {
      out.a.reset();
      out.b.reset();
      return out;
    }
    out.a = std::move(a);
    out.b = std::move(b);
    out.rounds = round + 1;
    if(out.rounds >= options.max_rounds) break;
    const std::map<int, int> join =
        labels_to_join(tm_a, vpm_a, *out.a, tm_b, labels_b, *out.b, options.join_labels_missing_in_b);
    if(join.empty()) break;
    join_labels(labels_a, join);
    join_labels(labels_b, join);
    out.joined.insert(join.begin(), join.end());
  }
  // Each joined label by the region it ends in.
  for(auto& [label, to] : out.joined) {
    std::vector<int> end{to};
    join_labels(end, out.joined);
    to = end.front();
  }
  return out;
}

} // namespace diffuv

#endif // DIFFUV_CORRESPONDENCE_LABELLED_ATLAS_PAIR_H
