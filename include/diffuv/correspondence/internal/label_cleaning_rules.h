// diffuv: the three rules of the label cleaning (clean_labels.h, where the
// rules are stated): islands absorbed, borders smoothed, pinches cut.
#ifndef DIFFUV_CORRESPONDENCE_INTERNAL_LABEL_CLEANING_RULES_H
#define DIFFUV_CORRESPONDENCE_INTERNAL_LABEL_CLEANING_RULES_H

#include <diffuv/correspondence/internal/label_cleaning_mesh.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/number_utils.h>
#include <CGAL/squared_distance_3.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <numeric>
#include <queue>
#include <stdexcept>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

namespace diffuv {

namespace internal {

/// Rule 1: absorbs islands, smallest first. Returns how many were absorbed.
inline std::size_t absorb_islands(const Label_cleaning_mesh& m, std::vector<int>& labels, double fraction,
                                  std::size_t& island_faces)
{
  constexpr std::size_t none = Label_cleaning_mesh::none;
  const std::size_t nf = m.number_of_faces();

  // Components of equal labels, by breadth-first search across edges.
  std::vector<std::size_t> component(nf, none);
  std::vector<std::vector<std::size_t>> members;
  std::vector<std::int64_t> area;
  std::vector<int> label_of;
  for(std::size_t start = 0; start < nf; ++start) {
    if(component[start] != none) continue;
    const std::size_t c = members.size();
    members.push_back({start});
    label_of.push_back(labels[start]);
    area.push_back(0);
    component[start] = c;
    for(std::size_t q = 0; q < members[c].size(); ++q) {
      const std::size_t f = members[c][q];
      area[c] += m.area[f];
      for(std::size_t k = m.adjacent_begin[f]; k < m.adjacent_begin[f + 1]; ++k) {
        const std::size_t g = m.adjacent_face[k];
        if(component[g] == none && labels[g] == label_of[c]) {
          component[g] = c;
          members[c].push_back(g);
        }
      }
    }
  }
  const std::size_t nc = members.size();

  // Thresholds are fixed for the round: a component does not become an island
  // because another component of its label grew.
  std::map<int, std::int64_t> largest;
  for(std::size_t c = 0; c < nc; ++c) largest[label_of[c]] = (std::max)(largest[label_of[c]], area[c]);
  auto is_small = [&](int label, std::int64_t a) {
    const auto it = largest.find(label);
    return it != largest.end() && static_cast<double>(a) < fraction * static_cast<double>(it->second);
  };

  std::vector<std::size_t> parent(nc);
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  auto find = [&](std::size_t c) {
    while(parent[c] != c) c = parent[c] = parent[parent[c]];
    return c;
  };
  auto unite = [&](std::size_t a, std::size_t b) { // the smaller face list moves into the larger
    a = find(a);
    b = find(b);
    if(a == b) return a;
    if(members[a].size() < members[b].size()) std::swap(a, b);
    parent[b] = a;
    members[a].insert(members[a].end(), members[b].begin(), members[b].end());
    std::vector<std::size_t>().swap(members[b]);
    area[a] += area[b];
    return a;
  };

  using Entry = std::tuple<std::int64_t, int, std::size_t>; // area, label, component
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> heap;
  std::vector<char> candidate(nc, 0);
  for(std::size_t c = 0; c < nc; ++c)
    if(is_small(label_of[c], area[c])) {
      candidate[c] = 1;
      heap.emplace(area[c], label_of[c], c);
    }

  std::size_t absorbed = 0;
  std::map<int, std::int64_t> border;
  std::vector<std::size_t> batch, join;
  std::vector<std::pair<std::size_t, int>> moves;
  while(!heap.empty()) {
    const std::int64_t a = std::get<0>(heap.top());
    const int label = std::get<1>(heap.top());
    batch.clear();
    while(!heap.empty() && std::get<0>(heap.top()) == a && std::get<1>(heap.top()) == label) {
      const std::size_t c = std::get<2>(heap.top());
      heap.pop();
      if(find(c) == c && candidate[c] && area[c] == a && label_of[c] == label) batch.push_back(c);
    }
    std::sort(batch.begin(), batch.end());
    batch.erase(std::unique(batch.begin(), batch.end()), batch.end());

    // Decide all islands of the batch from the same state: equal islands of
    // one label are never adjacent, so they do not change each other's border.
    moves.clear();
    for(std::size_t c : batch) {
      border.clear();
      for(std::size_t f : members[c])
        for(std::size_t k = m.adjacent_begin[f]; k < m.adjacent_begin[f + 1]; ++k) {
          const std::size_t d = find(component[m.adjacent_face[k]]);
          if(d != c) border[label_of[d]] += m.adjacent_length[k];
        }
      if(border.empty()) { // a whole connected part of the mesh: nothing to join
        candidate[c] = 0;
        continue;
      }
      moves.emplace_back(c, most_common_label(border, label));
    }

    for(const auto& [c, target] : moves) {
      ++absorbed;
      island_faces += members[c].size();
      for(std::size_t f : members[c]) labels[f] = target;
      // Join every neighbouring component of the new label: one label's
      // connected faces must stay one component.
      join.clear();
      for(std::size_t f : members[c])
        for(std::size_t k = m.adjacent_begin[f]; k < m.adjacent_begin[f + 1]; ++k) {
          const std::size_t d = find(component[m.adjacent_face[k]]);
          if(d != c && label_of[d] == target) join.push_back(d);
        }
      std::sort(join.begin(), join.end());
      join.erase(std::unique(join.begin(), join.end()), join.end());
      bool all_islands = true; // the result is an island only if what it joined were islands
      for(std::size_t d : join) all_islands = all_islands && candidate[d];
      std::size_t root = c;
      for(std::size_t d : join) root = unite(root, d);
      label_of[root] = target;
      candidate[root] = all_islands && is_small(target, area[root]);
      if(candidate[root]) heap.emplace(area[root], target, root);
    }
  }
  return absorbed;
}

/// Rule 2: synchronous border smoothing. Returns the number of relabellings.
inline std::size_t smooth_borders_synchronously(const Label_cleaning_mesh& m, std::vector<int>& labels,
                                                std::size_t passes)
{
  const std::size_t nf = m.number_of_faces();
  std::vector<int> proposal(nf);
  std::vector<std::int64_t> gain(nf), support(nf);
  std::vector<char> moves(nf);
  std::vector<std::size_t> accepted;
  std::map<int, int> count;
  std::size_t changed = 0;
  for(std::size_t pass = 0; pass < passes; ++pass) {
    bool any = false;
    for(std::size_t f = 0; f < nf; ++f) {
      moves[f] = 0;
      const int own = labels[f];
      count.clear();
      for(std::size_t k = m.adjacent_begin[f]; k < m.adjacent_begin[f + 1]; ++k)
        if(labels[m.adjacent_face[k]] != own) ++count[labels[m.adjacent_face[k]]];
      const int target = most_common_label(count, own);
      if(target == own || count[target] < 2) continue;
      // How much shorter the borders get: edges towards `target` become
      // interior, edges towards `own` become border.
      std::int64_t g = 0;
      for(std::size_t k = m.adjacent_begin[f]; k < m.adjacent_begin[f + 1]; ++k) {
        const int l = labels[m.adjacent_face[k]];
        if(l == target) g += m.adjacent_length[k];
        else if(l == own) g -= m.adjacent_length[k];
      }
      if(g <= 0) continue; // only a degenerate face: it would not shorten anything
      // Support: how much more of `target` than of `own` lies around its
      // corners (by area; edge-neighbours sit at two corners).
      std::int64_t around = 0;
      for(std::size_t c = m.corner_begin[f]; c < m.corner_begin[f + 1]; ++c)
        for(std::size_t r = m.ring_begin[m.corner_vertex[c]]; r < m.ring_begin[m.corner_vertex[c] + 1]; ++r) {
          const std::size_t h = m.ring_face[r];
          if(h == Label_cleaning_mesh::none || h == f) continue;
          if(labels[h] == target) around += m.area[h];
          else if(labels[h] == own) around -= m.area[h];
        }
      proposal[f] = target;
      support[f] = around;
      gain[f] = g;
      moves[f] = 1;
      any = true;
    }
    if(!any) break;

    // Neighbours moving differently: only the first by (support, gain, new
    // label, old label) moves. Then the labels around every move are those it
    // was computed from, except neighbours making the same move, and the
    // borders get shorter by at least its gain: passes cannot cycle.
    auto goes_first = [&](std::size_t f, std::size_t g) {
      if(support[f] != support[g]) return support[f] > support[g];
      if(gain[f] != gain[g]) return gain[f] > gain[g];
      if(proposal[f] != proposal[g]) return proposal[f] < proposal[g];
      return labels[f] < labels[g];
    };
    accepted.clear();
    for(std::size_t f = 0; f < nf; ++f) {
      if(!moves[f]) continue;
      bool go = true;
      for(std::size_t k = m.adjacent_begin[f]; k < m.adjacent_begin[f + 1] && go; ++k) {
        const std::size_t g = m.adjacent_face[k];
        if(moves[g] && (proposal[g] != proposal[f] || labels[g] != labels[f]) && !goes_first(f, g)) go = false;
      }
      if(go) accepted.push_back(f);
    }
    for(std::size_t f : accepted) labels[f] = proposal[f];
    changed += accepted.size();
  }
  return changed;
}

/// Rule 3: cuts the regions that touch themselves at a vertex. Returns the
/// number of (vertex, label) pairs cut; adds the faces relabelled to `pinch_faces`.
inline std::size_t cut_pinches(const Label_cleaning_mesh& m, std::vector<int>& labels, std::size_t& pinch_faces)
{
  constexpr std::size_t none = Label_cleaning_mesh::none;
  const std::size_t nf = m.number_of_faces();
  const std::size_t nv = m.ring_begin.size() - 1;
  const std::vector<int> before = labels;

  // The label a face of a removed fan takes, from the labels before this step:
  // a property of the face alone, so faces cut at two vertices agree.
  std::map<int, int> count;
  auto new_label = [&](std::size_t f) {
    const int own = before[f];
    count.clear();
    for(std::size_t k = m.adjacent_begin[f]; k < m.adjacent_begin[f + 1]; ++k)
      if(before[m.adjacent_face[k]] != own) ++count[before[m.adjacent_face[k]]];
    if(count.empty()) // no other label across its edges: look around its vertices
      for(std::size_t c = m.corner_begin[f]; c < m.corner_begin[f + 1]; ++c) {
        const std::size_t v = m.corner_vertex[c];
        for(std::size_t r = m.ring_begin[v]; r < m.ring_begin[v + 1]; ++r)
          if(m.ring_face[r] != none && before[m.ring_face[r]] != own) ++count[before[m.ring_face[r]]];
      }
    return most_common_label(count, own);
  };

  struct Fan {
    int label;
    std::size_t first, size; // positions first, first + 1, ... (mod n) in the ring
    std::int64_t area;
  };
  std::vector<char> cut(nf, 0);
  std::vector<int> decided(nf, 0), ring;
  std::vector<std::size_t> face_at, to_cut;
  std::vector<Fan> fans;
  std::map<int, std::vector<std::size_t>> fans_of;
  std::vector<int> stuck;
  std::size_t pinches = 0;
  for(std::size_t v = 0; v < nv; ++v) {
    const std::size_t b = m.ring_begin[v], n = m.ring_begin[v + 1] - b;
    if(n < 2) continue;
    face_at.assign(m.ring_face.begin() + std::ptrdiff_t(b), m.ring_face.begin() + std::ptrdiff_t(b + n));
    ring.resize(n);
    for(std::size_t i = 0; i < n; ++i) ring[i] = face_at[i] == none ? 0 : before[face_at[i]];

    // Cut one pinched label at a time: cutting one can reconnect another (a
    // saddle L, M, L, M needs one cut, not two).
    stuck.clear();
    for(std::size_t step = 0; step < n; ++step) {
      // Fans are runs of one label in the cyclic ring; walk it from a fan's
      // first face (after a border gap or a change of label), so that what
      // is found does not depend on where the mesh starts the ring.
      std::size_t start = n;
      for(std::size_t i = 0; i < n && start == n; ++i) {
        const std::size_t p = (i + n - 1) % n;
        if(face_at[i] != none && (face_at[p] == none || ring[p] != ring[i])) start = i;
      }
      if(start == n) break; // one label all around
      fans.clear();
      for(std::size_t k = 0; k < n;) {
        const std::size_t i = (start + k) % n;
        if(face_at[i] == none) { ++k; continue; }
        Fan fan{ring[i], i, 0, 0};
        for(; k < n && face_at[(start + k) % n] != none && ring[(start + k) % n] == fan.label; ++k, ++fan.size)
          fan.area += m.area[face_at[(start + k) % n]];
        fans.push_back(fan);
      }
      fans_of.clear();
      for(std::size_t k = 0; k < fans.size(); ++k) fans_of[fans[k].label].push_back(k);
      bool found = false;
      std::int64_t least = 0;
      to_cut.clear();
      for(const auto& [label, ks] : fans_of) { // increasing labels: on equal cost the smaller is cut
        if(ks.size() < 2 || std::find(stuck.begin(), stuck.end(), label) != stuck.end()) continue;
        std::int64_t largest = -1, total = 0;
        std::size_t at_largest = 0;
        for(std::size_t k : ks) {
          total += fans[k].area;
          if(fans[k].area > largest) largest = fans[k].area, at_largest = 0;
          if(fans[k].area == largest) ++at_largest;
        }
        // Keep the largest fan; if two tie, nothing can choose between them: keep none.
        const std::int64_t cost = at_largest == 1 ? total - largest : total;
        if(found && cost >= least) continue;
        found = true;
        least = cost;
        to_cut.clear();
        for(std::size_t k : ks)
          if(at_largest != 1 || fans[k].area != largest) to_cut.push_back(k);
      }
      if(!found) break;
      bool moved = false;
      for(std::size_t k : to_cut)
        for(std::size_t t = 0; t < fans[k].size; ++t) {
          const std::size_t i = (fans[k].first + t) % n;
          const std::size_t f = face_at[i];
          const int l = new_label(f);
          if(l == before[f]) continue; // no other label anywhere near: leave it
          ring[i] = l;
          decided[f] = l;
          cut[f] = 1;
          moved = true;
        }
      if(moved) ++pinches;
      else stuck.push_back(fans[to_cut.front()].label); // cannot be cut here: do not try again
    }
  }
  for(std::size_t f = 0; f < nf; ++f)
    if(cut[f]) {
      labels[f] = decided[f];
      ++pinch_faces;
    }
  return pinches;
}

} // namespace internal

} // namespace diffuv

#endif // DIFFUV_CORRESPONDENCE_INTERNAL_LABEL_CLEANING_RULES_H
