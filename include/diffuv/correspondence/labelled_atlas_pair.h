// diffuv: two labelled meshes made ready for correspondence together. A region
// that one mesh is too coarse to keep (its cleaning or its merging of small
// patches gave its faces to a neighbour) joins that neighbour on both meshes,
// so that its vertices are mapped instead of left without a counterpart.
#ifndef DIFFUV_CORRESPONDENCE_LABELLED_ATLAS_PAIR_H
#define DIFFUV_CORRESPONDENCE_LABELLED_ATLAS_PAIR_H

#include <diffuv/core/error.h>
#include <diffuv/correspondence/labelled_atlas.h>
#include <diffuv/correspondence/internal/label_cleaning_mesh.h>
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
  /// Builds of both atlases that succeeded: 1 when nothing was lost (or
  /// `max_rounds` is 1). At `max_rounds`, B may still have lost regions:
  /// they are the correspondence's labels only in A (`Region_match_report`).
  int rounds = 0;
  Status status;   ///< of the last build (`no_labels` if a mesh has none)
};

/// The labels of A's patches that B's atlas lost, each with the label it
/// should join: the region that most of its faces in B went to (B's cleaning
/// or its merging of small patches gave them away). With B's own labels
/// (`join_labels_missing_in_b` off) only regions that touch it on A count: a
/// lost label whose faces in B all went elsewhere (a stray face of that label
/// far away on B) is left alone, since joining there would map its vertices
/// far from where they are. With `join_labels_missing_in_b` (B's labels
/// carried from A), every face counts, and a lost label that no face of B
/// carried joins the region across its longest border on A.
///
/// \param b_labels B's labels as given to `build_labelled_atlas()` (before its cleaning)
template <class TriangleMesh, class VertexPointMap>
std::map<int, int> labels_to_join(const TriangleMesh& tm_a, VertexPointMap vpm_a, const Labelled_atlas<TriangleMesh>& a,
                                  const TriangleMesh& tm_b, const std::vector<int>& b_labels,
                                  const Labelled_atlas<TriangleMesh>& b, bool join_labels_missing_in_b)
{
  const auto& seg_a = a.segmentation;
  const auto& seg_b = b.segmentation;
  const std::set<int> in_b(seg_b.patch_label.begin(), seg_b.patch_label.end());
  std::set<int> lost;
  for(int label : seg_a.patch_label)
    if(!in_b.count(label)) lost.insert(label);
  constexpr std::size_t no_patch = Segmentation<TriangleMesh>::no_patch;

  if(lost.empty()) return {};

  // The lost labels' neighbours on A that B kept. With B's own labels: the
  // regions touching each by a shared vertex (B's borders differ from A's, so
  // its faces may go to a region that only touches the lost one at a corner
  // on A). With carried labels: the length of border shared with each.
  const auto findex_a = get(boost::face_index, tm_a);
  auto label_a = [&](auto f) -> int {
    if(f == boost::graph_traits<TriangleMesh>::null_face()) return -1;
    const std::size_t p = seg_a.face_patch[get(findex_a, f)];
    return p == no_patch ? -1 : seg_a.patch_label[p];
  };
  std::map<int, std::set<int>> touching;
  std::map<int, std::map<int, double>> border;
  if(!join_labels_missing_in_b) {
    for(auto v : vertices(tm_a)) {
      if(halfedge(v, tm_a) == boost::graph_traits<TriangleMesh>::null_halfedge()) continue;  // isolated
      std::set<int> around;
      for(auto f : CGAL::faces_around_target(halfedge(v, tm_a), tm_a))
        if(const int l = label_a(f); l >= 0) around.insert(l);
      for(int gone : around)
        if(lost.count(gone))
          for(int kept : around)
            if(in_b.count(kept)) touching[gone].insert(kept);
    }
  } else {
    for(auto e : edges(tm_a)) {
      const auto h = halfedge(e, tm_a);
      const int lf = label_a(face(h, tm_a)), lg = label_a(face(opposite(h, tm_a), tm_a));
      if(lf == lg || lf < 0 || lg < 0 || in_b.count(lf) == in_b.count(lg)) continue;
      const double length =
          std::sqrt(CGAL::squared_distance(get(vpm_a, source(h, tm_a)), get(vpm_a, target(h, tm_a))));
      if(in_b.count(lg)) border[lf][lg] += length;
      else border[lg][lf] += length;
    }
  }

  // Votes: the final labels of B's faces that carried a lost label. B's own
  // labels: only regions that touch it on A count. Labels carried from A:
  // every face counts (a carried label lies where it lay on A; measured on
  // cow's coarse copy, counting only the regions that touch it put 195 of the
  // 309 vertices the joins map within 0.05 sqrt(area) of their place, against
  // 245 of 304).
  std::map<int, std::map<int, std::size_t>> votes;
  const auto findex_b = get(boost::face_index, tm_b);
  for(auto f : faces(tm_b)) {
    const std::size_t i = get(findex_b, f);
    const int label = b_labels[i];
    if(!lost.count(label) || seg_b.face_patch[i] == no_patch) continue;
    const int went_to = seg_b.patch_label[seg_b.face_patch[i]];
    if(join_labels_missing_in_b || touching[label].count(went_to)) ++votes[label][went_to];
  }
  std::map<int, int> join;
  for(const auto& [label, counts] : votes) join[label] = internal::most_common_label(counts, label);
  if(!join_labels_missing_in_b) return join;
  // Labels carried from A: one that no face of B carried joins the region
  // across its longest border.
  for(const auto& [label, lengths] : border)
    if(!join.count(label)) join[label] = internal::most_common_label(lengths, label);
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
