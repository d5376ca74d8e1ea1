// diffuv: a disc region of a mesh split into sectors by a fan of edge paths
// from one centre vertex to given vertices of its border.
//
// This is the operation the four-sided layout is built from
// (layout/quad_layout.h): a cell is fanned from its centre to the midpoints
// of its arcs, then the region around each junction is fanned from its own
// centre to the midpoints on its border. Each cut follows the straight
// segment from the centre to its target in a mean value flattening of the
// region (Floater 2003: an embedding, so the segments do not cross), snapped
// to an edge path; the cuts are vertex-disjoint but for the centre and have no
// chord (an edge between two of their vertices that are not consecutive), so
// no triangle of a sector has its three vertices on one cut.
#ifndef DIFFUV_LAYOUT_FAN_SPLIT_H
#define DIFFUV_LAYOUT_FAN_SPLIT_H

#include <diffuv/internal/index_list_hash.h>
#include <diffuv/layout/internal/local_region.h>

#include <boost/graph/graph_traits.hpp>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#endif

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <queue>
#include <unordered_map>
#include <utility>
#include <vector>

namespace diffuv {
namespace internal {

/// What a fan split found.
struct Fan {
  int centre = -1;                      ///< local id of the centre
  std::vector<std::vector<int>> cuts;   ///< cut a: centre ... targets[a], local ids
  std::vector<int> sector_of_face;      ///< #F_r entries: sector s lies between cut s and cut s+1 (counter-clockwise)
  std::vector<double> opening;          ///< sector s's angle at the centre (radians, in 3D, a third of the way out)
};

/// Why a fan split failed.
enum class Fan_failure { none, no_centre, no_cuts, sectors };

/// Splits a disc region by vertex-disjoint edge paths ("cuts") from one
/// interior centre vertex to each of `targets` (local ids on the loop, in
/// counter-clockwise order, at least two).
///
/// The centre is chosen among interior vertices with room for every cut
/// (valence at least #targets) near the least-squares centre of the targets
/// (sum of squared edge-path distances within `centre_tolerance` of the
/// smallest), the one whose ring best matches the directions of the cuts.
///
/// Cuts are traced one after the other, from `first_target` (an index into
/// `targets`) or, if it is -1, from the target with the smallest id. Local ids
/// follow the points' coordinates, so a caller who can name a first target by
/// a rule of its own (`split_regions_into_quads()`: the run of the smallest
/// neighbour key) makes the split the same on a rotated or scaled copy too.
template <class TriangleMesh>
Fan_failure fan_split(const Local_region<TriangleMesh>& r, const std::vector<int>& given_targets, Fan& fan,
                      double centre_tolerance = 1.5, int forced_centre = -1, int first_target = -1)
{
  const std::size_t nv = r.verts.size(), k = given_targets.size();
  fan = Fan();
  if(k < 2) return Fan_failure::no_cuts;
  // Cuts are traced one after the other, each avoiding the earlier ones: start
  // from the target with the smallest id so that the order, and so the result,
  // does not depend on where the caller's list starts. `shift` maps back.
  const std::size_t shift =
      first_target >= 0 && static_cast<std::size_t>(first_target) < k
          ? static_cast<std::size_t>(first_target)
          : static_cast<std::size_t>(std::min_element(given_targets.begin(), given_targets.end()) - given_targets.begin());
  std::vector<int> targets(k);
  for(std::size_t a = 0; a < k; ++a) targets[a] = given_targets[(a + shift) % k];
  std::vector<std::vector<double>> target_distance(k);
  for(std::size_t a = 0; a < k; ++a) r.dijkstra({targets[a]}, target_distance[a]);
  std::vector<double> spread(nv, std::numeric_limits<double>::infinity());
  double least = std::numeric_limits<double>::infinity();
  for(std::size_t i = 0; i < nv; ++i) {
    if(r.on_border[i]) continue;
    double sum = 0;
    for(std::size_t a = 0; a < k; ++a) sum += target_distance[a][i] * target_distance[a][i];
    spread[i] = sum;
    least = std::min(least, sum);
  }
  std::vector<int> candidates;
  for(std::size_t i = 0; i < nv; ++i)
    if(!r.on_border[i] && r.neighbours[i].size() >= k && spread[i] <= centre_tolerance * least)
      candidates.push_back(static_cast<int>(i));
  std::sort(candidates.begin(), candidates.end(), [&](int a, int b) { return spread[a] < spread[b]; });
  if(candidates.size() > 16) candidates.resize(16);
  if(forced_centre >= 0) {
    candidates.clear();
    if(!r.on_border[forced_centre] && r.neighbours[forced_centre].size() >= k) candidates.push_back(forced_centre);
    least = spread[forced_centre];
  }
  if(candidates.empty()) return Fan_failure::no_centre;

  std::vector<double> X, Y;
  if(!flatten_region(r, X, Y)) return Fan_failure::no_cuts;
  // A cut's edges cost their flattened length, more the farther they stray
  // from the straight segment, and more again next to another cut or the border.
  constexpr double stray_cost = 10.0, crowd_cost = 1.0, centre_cost = 100.0;
  // Flattened edge lengths, by vertex and position in its neighbour list:
  // every centre tried traces its cuts over the same edges.
  std::vector<std::vector<double>> flat_length(nv);
  for(std::size_t i = 0; i < nv; ++i)
    for(int j : r.neighbours[i]) flat_length[i].push_back(std::hypot(X[i] - X[j], Y[i] - Y[j]));

  // Where the cuts from centre zc leave its ring (`first`), and the ring
  // vertices kept for one cut (`reserved`: vertex, cut); `score` says how
  // well the ring fits the cuts' directions. Cheap: no cut is traced.
  struct Plan {
    int centre = -1;
    double score = 0;
    std::vector<int> first;
    std::vector<std::pair<int, int>> reserved;
  };
  auto plan_centre = [&](int zc, Plan& plan) -> bool {
    auto angle = [&](int i) { return std::atan2(Y[i] - Y[zc], X[i] - X[zc]); };
    std::vector<int> ring = r.neighbours[zc];
    const std::size_t d = ring.size();
    std::sort(ring.begin(), ring.end(), [&](int a, int b) { return angle(a) < angle(b); });
    std::vector<double> ring_angle(d), direction(k);
    for(std::size_t j = 0; j < d; ++j) ring_angle[j] = angle(ring[j]);
    for(std::size_t a = 0; a < k; ++a) direction[a] = angle(targets[a]);
    // Each cut leaves through its own ring vertex, in the targets' cyclic
    // order, as close as possible to its direction (cyclic dynamic programming).
    auto deviation = [&](std::size_t a, std::size_t j) {
      if(r.on_border[ring[j]]) return std::numeric_limits<double>::infinity();
      const double g = ccw_gap(ring_angle[j], direction[a]);
      const double dev = std::min(g, 2 * M_PI - g);
      return dev * dev;
    };
    double best = std::numeric_limits<double>::infinity();
    std::vector<std::size_t> assignment;
    for(std::size_t j0 = 0; j0 < d; ++j0) {
      std::vector<std::vector<double>> cost(k, std::vector<double>(d, std::numeric_limits<double>::infinity()));
      std::vector<std::vector<std::size_t>> from(k, std::vector<std::size_t>(d, 0));
      cost[0][0] = deviation(0, j0);
      for(std::size_t a = 1; a < k; ++a)
        for(std::size_t t = a; t + (k - a) <= d; ++t)
          for(std::size_t u = a - 1; u < t; ++u) {
            const double c = cost[a - 1][u] + deviation(a, (j0 + t) % d);
            if(c < cost[a][t]) {
              cost[a][t] = c;
              from[a][t] = u;
            }
          }
      for(std::size_t t = k - 1; t < d; ++t)
        if(cost[k - 1][t] < best) {
          best = cost[k - 1][t];
          assignment.assign(k, 0);
          std::size_t tb = t;
          for(std::size_t a = k; a-- > 0;) {
            assignment[a] = (j0 + tb) % d;
            if(a > 0) tb = from[a][tb];
          }
        }
    }
    if(assignment.empty() || !(best < std::numeric_limits<double>::infinity())) return false;
    plan.centre = zc;
    plan.score = best;
    plan.first.assign(k, -1);
    plan.reserved.clear();
    auto reserved_by = [&](int i) {
      for(const auto& [v, a] : plan.reserved)
        if(v == i) return a;
      return -1;
    };
    for(std::size_t a = 0; a < k; ++a) {
      plan.first[a] = ring[assignment[a]];
      if(plan.first[a] == targets[a]) return false; // a cut of one edge: its sectors would be slivers
      plan.reserved.emplace_back(plan.first[a], static_cast<int>(a));
    }
    // A target with a single interior neighbour: that neighbour is its cut's.
    for(std::size_t a = 0; a < k; ++a) {
      int only = -1, count = 0;
      for(int j : r.neighbours[targets[a]])
        if(!r.on_border[j]) {
          only = j;
          ++count;
        }
      if(count == 0 || only == zc) return false;
      if(count == 1) {
        const int holder = reserved_by(only);
        if(holder >= 0 && holder != static_cast<int>(a)) return false;
        if(holder < 0) plan.reserved.emplace_back(only, static_cast<int>(a));
      }
    }
    return true;
  };

  // The cuts of a plan, traced one after the other; false if one cannot be.
  auto trace_cuts = [&](const Plan& plan, std::vector<std::vector<int>>& cuts) -> bool {
    const int zc = plan.centre;
    const std::vector<int>& first = plan.first;
    std::vector<int> reserved_for(nv, -1);
    for(const auto& [v, a] : plan.reserved) reserved_for[v] = a;
    std::vector<char> on_cut(nv, 0), crowded(nv, 0);
    on_cut[zc] = 1;
    for(std::size_t i = 0; i < nv; ++i)
      if(r.on_border[i])
        for(int j : r.neighbours[i]) crowded[j] = 1;
    cuts.assign(k, {});
    // Shortest cut first (in the flattening), so that the order, and so the
    // fan, is the same on a copy with its faces turned the other way round
    // (the targets' counter-clockwise order runs backwards there).
    std::vector<std::size_t> trace_order(k);
    std::vector<double> reach(k);
    for(std::size_t a = 0; a < k; ++a) {
      trace_order[a] = a;
      reach[a] = std::hypot(X[targets[a]] - X[zc], Y[targets[a]] - Y[zc]);
    }
    std::stable_sort(trace_order.begin(), trace_order.end(), [&](std::size_t a, std::size_t b) { return reach[a] < reach[b]; });
    for(std::size_t a : trace_order) {
      const int target = targets[a];
      const double sx = X[target] - X[zc], sy = Y[target] - Y[zc];
      const double squared_length = sx * sx + sy * sy;
      if(!(squared_length > 0)) return false;
      std::vector<double> stray_of(nv, -1.);  // each vertex's, once per cut
      auto stray = [&](int i) {
        double& known = stray_of[static_cast<std::size_t>(i)];
        if(known < 0) {
          const double px = X[i] - X[zc], py = Y[i] - Y[zc];
          const double t = std::clamp((px * sx + py * sy) / squared_length, 0.0, 1.0);
          known = std::hypot(px - t * sx, py - t * sy) / std::sqrt(squared_length);
        }
        return known;
      };
      auto usable = [&](int i) {
        if(i == target) return true;
        if(r.on_border[i] || on_cut[i]) return false;
        return reserved_for[i] < 0 || reserved_for[i] == static_cast<int>(a);
      };
      std::vector<double> dist(nv, std::numeric_limits<double>::infinity());
      std::vector<int> prev(nv, -1);
      using Entry = std::pair<double, int>;
      std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
      dist[first[a]] = 0;
      prev[first[a]] = zc;
      queue.emplace(0., first[a]);
      while(!queue.empty()) {
        const auto [dd, i] = queue.top();
        queue.pop();
        if(dd > dist[i]) continue;
        if(i == target) break;
        for(std::size_t n = 0; n < r.neighbours[i].size(); ++n) {
          const int j = r.neighbours[i][n];
          if(!usable(j) || j == first[a]) continue;
          const double len = flat_length[static_cast<std::size_t>(i)][n];
          double w = len * (1 + stray_cost * stray(j));
          if(j != target && crowded[j]) w += crowd_cost * len;
          if(dd + w < dist[j]) {
            dist[j] = dd + w;
            prev[j] = i;
            queue.emplace(dd + w, j);
          }
        }
      }
      if(prev[target] < 0) return false;
      std::vector<int> path;
      for(int i = target; i != zc; i = prev[i]) path.push_back(i);
      path.push_back(zc);
      std::reverse(path.begin(), path.end());
      // No chord: shortcut an edge between two path vertices that are not consecutive.
      for(bool changed = true; changed;) {
        changed = false;
        for(std::size_t s = 0; s + 2 < path.size() && !changed; ++s)
          for(std::size_t t = path.size() - 1; t > s + 1 && !changed; --t)
            if(r.adjacent(path[s], path[t]) && !(s == 0 && t == path.size() - 1)) {
              path.erase(path.begin() + static_cast<std::ptrdiff_t>(s + 1), path.begin() + static_cast<std::ptrdiff_t>(t));
              changed = true;
            }
      }
      if(path.size() < 3) return false; // the shortcut made a one-edge cut
      for(int i : path) {
        on_cut[i] = 1;
        for(int j : r.neighbours[i]) crowded[j] = 1;
      }
      cuts[a] = std::move(path);
    }
    return true;
  };

  // The centre of least score whose cuts can all be traced (the first in the
  // candidates' order among equal scores). A score is known before any cut is
  // traced, so centres are tried best first and the first that works is it:
  // most regions trace one centre's cuts instead of up to 16.
  std::vector<Plan> plans;
  for(int zc : candidates) {
    Plan plan;
    if(!plan_centre(zc, plan)) continue;
    plan.score += centre_cost * (spread[zc] / least - 1.0);
    if(plan.score < std::numeric_limits<double>::infinity()) plans.push_back(std::move(plan));
  }
  std::stable_sort(plans.begin(), plans.end(), [](const Plan& a, const Plan& b) { return a.score < b.score; });
  for(const Plan& plan : plans) {
    std::vector<std::vector<int>> cuts;
    if(!trace_cuts(plan, cuts)) continue;
    fan.centre = plan.centre;
    fan.cuts = std::move(cuts);
    break;
  }
  if(fan.centre < 0) return Fan_failure::no_cuts;

  // Sectors: faces flooded without crossing a cut edge.
  auto key = [](int x, int y) { return (static_cast<long long>(std::min(x, y)) << 32) | static_cast<long long>(std::max(x, y)); };
  std::unordered_map<long long, char> cut_edge;
  for(const auto& cut : fan.cuts)
    for(std::size_t s = 0; s + 1 < cut.size(); ++s) cut_edge[key(cut[s], cut[s + 1])] = 1;
  std::unordered_map<long long, std::array<int, 2>> faces_of_edge;
  const std::size_t nf = r.face_verts.size();
  for(std::size_t f = 0; f < nf; ++f)
    for(int e = 0; e < 3; ++e) {
      auto it = faces_of_edge.emplace(key(r.face_verts[f][e], r.face_verts[f][(e + 1) % 3]), std::array<int, 2>{-1, -1}).first;
      (it->second[0] < 0 ? it->second[0] : it->second[1]) = static_cast<int>(f);
    }
  std::vector<int> component(nf, -1);
  std::size_t components = 0;
  for(std::size_t start = 0; start < nf; ++start) {
    if(component[start] >= 0) continue;
    std::vector<int> queue = {static_cast<int>(start)};
    component[start] = static_cast<int>(components);
    for(std::size_t q = 0; q < queue.size(); ++q)
      for(int e = 0; e < 3; ++e) {
        const long long edge_key = key(r.face_verts[queue[q]][e], r.face_verts[queue[q]][(e + 1) % 3]);
        if(cut_edge.count(edge_key)) continue;
        for(int g : faces_of_edge[edge_key])
          if(g >= 0 && component[g] < 0) {
            component[g] = static_cast<int>(components);
            queue.push_back(g);
          }
      }
    ++components;
  }
  if(components != k) return Fan_failure::sectors;
  // Sector a starts counter-clockwise after cut a: it holds the face whose
  // corners run centre -> (cut a's first vertex) in the faces' orientation.
  std::vector<int> sector_of_component(k, -1);
  for(std::size_t f = 0; f < nf; ++f)
    for(int e = 0; e < 3; ++e)
      if(r.face_verts[f][e] == fan.centre)
        for(std::size_t a = 0; a < k; ++a)
          if(r.face_verts[f][(e + 1) % 3] == fan.cuts[a][1]) sector_of_component[component[f]] = static_cast<int>(a);
  for(int s : sector_of_component)
    if(s < 0) return Fan_failure::sectors;
  fan.sector_of_face.resize(nf);
  for(std::size_t f = 0; f < nf; ++f)
    fan.sector_of_face[f] = static_cast<int>((static_cast<std::size_t>(sector_of_component[component[f]]) + shift) % k);

  // Opening of each sector at the centre, a third of the way along the shorter cut.
  auto point_along = [&](std::size_t a, double d) {
    double s = 0;
    for(std::size_t i = 1; i < fan.cuts[a].size(); ++i) {
      s += r.length(fan.cuts[a][i - 1], fan.cuts[a][i]);
      if(s >= d) return r.points[fan.cuts[a][i]];
    }
    return r.points[fan.cuts[a].back()];
  };
  std::vector<double> cut_length(k, 0.);
  for(std::size_t a = 0; a < k; ++a)
    for(std::size_t i = 1; i < fan.cuts[a].size(); ++i) cut_length[a] += r.length(fan.cuts[a][i - 1], fan.cuts[a][i]);
  const auto& pc = r.points[fan.centre];
  fan.opening.assign(k, 0.);
  for(std::size_t a = 0; a < k; ++a) {
    const std::size_t b = (a + 1) % k;
    const double d = std::min(cut_length[a], cut_length[b]) / 3;
    const auto pa = point_along(a, d), pb = point_along(b, d);
    const double ux = pa[0] - pc[0], uy = pa[1] - pc[1], uz = pa[2] - pc[2];
    const double vx = pb[0] - pc[0], vy = pb[1] - pc[1], vz = pb[2] - pc[2];
    const double c = (ux * vx + uy * vy + uz * vz) / std::sqrt((ux * ux + uy * uy + uz * uz) * (vx * vx + vy * vy + vz * vz));
    fan.opening[a] = std::acos(std::clamp(c, -1., 1.));
  }
  std::rotate(fan.cuts.rbegin(), fan.cuts.rbegin() + static_cast<std::ptrdiff_t>(shift), fan.cuts.rend());
  std::rotate(fan.opening.rbegin(), fan.opening.rbegin() + static_cast<std::ptrdiff_t>(shift), fan.opening.rend());
  return Fan_failure::none;
}

/// Fans already made, by what they were made from. `quad_layout()` builds the
/// quads again after each refinement round, and a seed added in one place
/// leaves most cells and dual regions as they were: their fans are looked up
/// instead of flattened and traced again. The key is the whole input (faces in
/// order, border loop, target vertices), so a hit gives exactly the fan that
/// `fan_split()` would.
template <class TriangleMesh>
class Fan_memo {
public:
  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;

  /// A fan with its centre as a mesh vertex (the local ids are the region's).
  struct Entry {
    Fan_failure failure = Fan_failure::no_cuts;
    Fan fan;
    vertex_descriptor centre;
    bool prefetched = false;  // made by prefetch(), not asked for yet
  };

  /// What `fan()` is asked: a region's faces and loop (not owned) and its targets.
  struct Request {
    const std::vector<face_descriptor>* faces;
    const std::vector<vertex_descriptor>* loop;
    std::vector<vertex_descriptor> targets;
  };

  /// The fan of the region of `faces` bounded by `loop`, to `targets` (mesh
  /// vertices on the loop): `fan_split(make_local_region(...), ...)`, made once.
  template <class VertexPointMap>
  const Entry& fan(const TriangleMesh& tm, VertexPointMap vpm, const std::vector<face_descriptor>& faces,
                   const std::vector<vertex_descriptor>& loop, const std::vector<vertex_descriptor>& targets,
                   std::vector<int>& scratch)
  {
    std::vector<std::size_t> key = key_of(tm, faces, loop, targets);
    const auto found = memo_.find(key);
    if(found != memo_.end()) {
      // A fan prefetched for this request counts as made for it.
      if(found->second.prefetched) {
        found->second.prefetched = false;
        ++misses_;
      } else {
        ++hits_;
      }
      return found->second;
    }
    ++misses_;
    return memo_.emplace(std::move(key), make(tm, vpm, faces, loop, targets, scratch)).first->second;
  }

  /// Makes the fans of `requests` that are not in the memo yet, in parallel
  /// with oneTBB (one after the other without it), so that the `fan()` calls
  /// that follow find them. A fan depends on its request alone, so the fans,
  /// and the counts of hits and misses, are those of asking one by one.
  template <class VertexPointMap>
  void prefetch(const TriangleMesh& tm, VertexPointMap vpm, const std::vector<Request>& requests)
  {
    std::vector<std::vector<std::size_t>> keys;
    std::vector<const Request*> missing;
    std::unordered_map<std::vector<std::size_t>, char, Index_list_hash> listed;
    for(const Request& q : requests) {
      std::vector<std::size_t> key = key_of(tm, *q.faces, *q.loop, q.targets);
      if(memo_.count(key) || !listed.emplace(key, 1).second) continue;
      keys.push_back(std::move(key));
      missing.push_back(&q);
    }
    std::vector<Entry> made(missing.size());
    auto make_range = [&](std::size_t begin, std::size_t end, std::vector<int>& scratch) {
      for(std::size_t i = begin; i < end; ++i) made[i] = make(tm, vpm, *missing[i]->faces, *missing[i]->loop, missing[i]->targets, scratch);
    };
#ifdef CGAL_LINKED_WITH_TBB
    if(missing.size() > 1) {
      tbb::enumerable_thread_specific<std::vector<int>> scratch([&] { return std::vector<int>(num_vertices(tm), -1); });
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, missing.size(), 1),
                        [&](const tbb::blocked_range<std::size_t>& r) { make_range(r.begin(), r.end(), scratch.local()); });
    } else
#endif
    {
      std::vector<int> scratch(num_vertices(tm), -1);
      make_range(0, missing.size(), scratch);
    }
    for(std::size_t i = 0; i < made.size(); ++i) {
      made[i].prefetched = true;
      memo_.emplace(std::move(keys[i]), std::move(made[i]));
    }
  }

  std::size_t hits() const { return hits_; }
  std::size_t misses() const { return misses_; }

private:
  static std::vector<std::size_t> key_of(const TriangleMesh& tm, const std::vector<face_descriptor>& faces,
                                         const std::vector<vertex_descriptor>& loop, const std::vector<vertex_descriptor>& targets)
  {
    auto vindex = get(boost::vertex_index, tm);
    auto findex = get(boost::face_index, tm);
    std::vector<std::size_t> key;
    key.reserve(faces.size() + loop.size() + targets.size() + 2);
    for(face_descriptor f : faces) key.push_back(get(findex, f));
    key.push_back(separator);
    for(vertex_descriptor v : loop) key.push_back(get(vindex, v));
    key.push_back(separator);
    for(vertex_descriptor v : targets) key.push_back(get(vindex, v));
    return key;
  }

  template <class VertexPointMap>
  static Entry make(const TriangleMesh& tm, VertexPointMap vpm, const std::vector<face_descriptor>& faces,
                    const std::vector<vertex_descriptor>& loop, const std::vector<vertex_descriptor>& targets, std::vector<int>& scratch)
  {
    auto vindex = get(boost::vertex_index, tm);
    const auto region = make_local_region(tm, vpm, faces, loop, scratch);
    std::vector<int> local_targets;
    for(vertex_descriptor v : targets) local_targets.push_back(region.local(get(vindex, v)));
    Entry entry;
    entry.failure = fan_split(region, local_targets, entry.fan);
    if(entry.failure == Fan_failure::none) entry.centre = region.verts[entry.fan.centre];
    return entry;
  }

  static constexpr std::size_t separator = std::numeric_limits<std::size_t>::max();
  std::unordered_map<std::vector<std::size_t>, Entry, Index_list_hash> memo_;
  std::size_t hits_ = 0, misses_ = 0;
};

} // namespace internal
} // namespace diffuv

#endif // DIFFUV_LAYOUT_FAN_SPLIT_H
