// diffuv performance bench, (a): one multi-source Dijkstra per heap on the
// whole mesh, from side u1 of its largest patch; bench-local references on a
// compressed-row (CSR) graph (not library code, see doc/performance.md); one
// run on the largest patch; one fast-marching run on the whole mesh.
#include "performance/performance_bench.h"

#include <diffuv/graph/edge_length_map.h>
#include <diffuv/graph/fast_marching.h>
#include <diffuv/graph/multi_source_dijkstra.h>
#include <diffuv/internal/lazy_dijkstra.h>

#include <boost/heap/fibonacci_heap.hpp>
#include <boost/pool/pool_alloc.hpp>
#include <boost/property_map/property_map.hpp>

#include <cstdint>
#include <limits>

namespace diffuv_bench {

namespace {

// Bench-local reference, not library code: the graph in compressed rows.
struct Csr_graph {
  std::vector<std::uint32_t> begin, target;
  std::vector<double> weight;
};

Csr_graph make_csr(const Mesh& m, const diffuv::Edge_length_map<Mesh>& lengths)
{
  Csr_graph g;
  const std::size_t n = m.number_of_vertices();
  g.begin.assign(n + 1, 0);
  for(vertex_descriptor v : m.vertices()) {
    g.begin[v.idx()] = static_cast<std::uint32_t>(g.target.size());
    if(m.halfedge(v) == Mesh::null_halfedge()) continue;
    for(halfedge_descriptor h : CGAL::halfedges_around_target(v, m)) {
      g.target.push_back(static_cast<std::uint32_t>(m.source(h).idx()));
      g.weight.push_back(get(lengths, m.edge(h)));
    }
  }
  g.begin[n] = static_cast<std::uint32_t>(g.target.size());
  return g;
}

// A binary heap without decrease-key (std::priority_queue): a vertex is
// pushed again when its distance drops, stale entries are skipped when popped.
void csr_dijkstra(const Csr_graph& g, const std::vector<std::uint32_t>& sources, std::vector<double>& dist)
{
  std::fill(dist.begin(), dist.end(), infinity);
  diffuv::internal::lazy_dijkstra(sources, dist, [&g](std::uint32_t a, auto&& relax) {
    for(std::uint32_t k = g.begin[a]; k < g.begin[a + 1]; ++k) relax(g.target[k], g.weight[k]);
  });
}

// The library's algorithm (decrease-key through handles, a vertex pushed when
// first reached) on the CSR graph, with any Boost.Heap mutable heap.
template <class Heap>
struct Csr_mutable_dijkstra {
  using Node = diffuv::internal::Distance_node<std::uint32_t>;
  Heap heap;
  std::vector<typename Heap::handle_type> handles;
  std::vector<std::uint8_t> state;

  void run(const Csr_graph& g, const std::vector<std::uint32_t>& sources, std::vector<double>& dist)
  {
    const std::size_t n = g.begin.size() - 1;
    handles.resize(n);
    state.assign(n, 0);
    std::fill(dist.begin(), dist.end(), infinity);
    heap.clear();
    for(std::uint32_t s : sources) {
      if(state[s]) continue;
      dist[s] = 0.;
      handles[s] = heap.push(Node{0., s});
      state[s] = 1;
    }
    while(!heap.empty()) {
      const Node top = heap.top();
      heap.pop();
      state[top.vertex] = 2;
      for(std::uint32_t k = g.begin[top.vertex]; k < g.begin[top.vertex + 1]; ++k) {
        const std::uint32_t b = g.target[k];
        if(state[b] == 2) continue;
        const double candidate = top.distance + g.weight[k];
        if(candidate < dist[b]) {
          dist[b] = candidate;
          if(state[b] == 1) {
            heap.increase(handles[b], Node{candidate, b});
          } else {
            handles[b] = heap.push(Node{candidate, b});
            state[b] = 1;
          }
        }
      }
    }
  }
};

using Csr_node = diffuv::internal::Distance_node<std::uint32_t>;
using Csr_fibonacci = diffuv::internal::Min_distance_heap<diffuv::Fibonacci_heap_tag, std::uint32_t>;
using Csr_fibonacci_pool =
    boost::heap::fibonacci_heap<Csr_node, boost::heap::compare<diffuv::internal::Farther>,
                                boost::heap::allocator<boost::fast_pool_allocator<Csr_node>>>;
using Csr_quaternary = diffuv::internal::Min_distance_heap<diffuv::Quaternary_heap_tag, std::uint32_t>;

// Breadth-first renumbering from `start` (vertices not reached keep their order, at the end).
Csr_graph bfs_renumbered(const Csr_graph& g, std::uint32_t start, std::vector<std::uint32_t>& new_of_old)
{
  const std::size_t n = g.begin.size() - 1;
  constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();
  new_of_old.assign(n, none);
  std::vector<std::uint32_t> order;
  order.reserve(n);
  auto visit = [&](std::uint32_t v) {
    if(new_of_old[v] != none) return;
    new_of_old[v] = static_cast<std::uint32_t>(order.size());
    order.push_back(v);
  };
  visit(start);
  for(std::size_t q = 0; q < order.size() || order.size() < n; ++q) {
    if(q == order.size()) { // another component
      for(std::uint32_t v = 0; v < n; ++v)
        if(new_of_old[v] == none) { visit(v); break; }
    }
    const std::uint32_t a = order[q];
    for(std::uint32_t k = g.begin[a]; k < g.begin[a + 1]; ++k) visit(g.target[k]);
  }
  Csr_graph r;
  r.begin.assign(n + 1, 0);
  r.target.reserve(g.target.size());
  r.weight.reserve(g.weight.size());
  for(std::uint32_t i = 0; i < n; ++i) {
    r.begin[i] = static_cast<std::uint32_t>(r.target.size());
    const std::uint32_t a = order[i];
    for(std::uint32_t k = g.begin[a]; k < g.begin[a + 1]; ++k) {
      r.target.push_back(new_of_old[g.target[k]]);
      r.weight.push_back(g.weight[k]);
    }
  }
  r.begin[n] = static_cast<std::uint32_t>(r.target.size());
  return r;
}

template <class HeapTag>
double time_dijkstra(const Mesh& m, const std::vector<vertex_descriptor>& sources,
                     const diffuv::Edge_length_map<Mesh>& lengths, int runs, std::vector<double>& dist)
{
  diffuv::Multi_source_dijkstra<Mesh, HeapTag> dijkstra(m);
  auto dmap = boost::make_iterator_property_map(dist.begin(), get(boost::vertex_index, m));
  return median_time(runs, [&] { dijkstra.run(sources, lengths, dmap); });
}

} // namespace

void measure_dijkstra(const Case& c, int runs, const std::string& tag, Row& row)
{
  const Mesh& m = c.mesh;
  const std::size_t V = m.number_of_vertices();
  const double ElogV = static_cast<double>(m.number_of_edges()) * std::log2(static_cast<double>(V));
  const auto lengths = diffuv::edge_length_map(m, m.points());
  const std::vector<vertex_descriptor>& sources = c.sides[c.largest_patch].u1;
  row.set("sources", sources.size());
  const int druns = std::max(runs, 3);
  std::vector<double> d_fib(V), d_other(V);
  const double fib = time_dijkstra<diffuv::Fibonacci_heap_tag>(m, sources, lengths, druns, d_fib);
  const double pairing = time_dijkstra<diffuv::Pairing_heap_tag>(m, sources, lengths, druns, d_other);
  const double binomial = time_dijkstra<diffuv::Binomial_heap_tag>(m, sources, lengths, druns, d_other);
  const double quaternary = time_dijkstra<diffuv::Quaternary_heap_tag>(m, sources, lengths, druns, d_other);
  // Bench-local references on a CSR graph (see doc/performance.md).
  const Csr_graph csr = make_csr(m, lengths);
  std::vector<std::uint32_t> csr_sources;
  for(vertex_descriptor v : sources) csr_sources.push_back(static_cast<std::uint32_t>(v.idx()));
  double worst = 0;
  auto check = [&]() {
    for(std::size_t i = 0; i < V; ++i)
      if(d_fib[i] != d_other[i]) worst = std::max(worst, std::abs(d_fib[i] - d_other[i]));
  };
  const double ref_lazy = median_time(druns, [&] { csr_dijkstra(csr, csr_sources, d_other); });
  check();
  Csr_mutable_dijkstra<Csr_fibonacci> csr_fib;
  const double ref_fib = median_time(druns, [&] { csr_fib.run(csr, csr_sources, d_other); });
  check();
  Csr_mutable_dijkstra<Csr_fibonacci_pool> csr_pool;
  const double ref_pool = median_time(druns, [&] { csr_pool.run(csr, csr_sources, d_other); });
  check();
  Csr_mutable_dijkstra<Csr_quaternary> csr_4ary;
  const double ref_4ary = median_time(druns, [&] { csr_4ary.run(csr, csr_sources, d_other); });
  check();
  std::vector<std::uint32_t> new_of_old;
  const Csr_graph bfs = bfs_renumbered(csr, csr_sources.front(), new_of_old);
  std::vector<std::uint32_t> bfs_sources;
  for(std::uint32_t v : csr_sources) bfs_sources.push_back(new_of_old[v]);
  std::vector<double> d_bfs(V);
  const double ref_bfs = median_time(druns, [&] { csr_dijkstra(bfs, bfs_sources, d_bfs); });
  for(std::size_t i = 0; i < V; ++i) d_other[i] = d_bfs[new_of_old[i]];
  check();
  row.set("dij_csr_fib_ms", ref_fib);
  row.set("dij_csr_fib_pool_ms", ref_pool);
  row.set("dij_csr_4ary_ms", ref_4ary);
  row.set("dij_csr_bfs_ms", ref_bfs);
  const double ref = ref_lazy;
  row.set("dij_fib_ms", fib);
  row.set("dij_pairing_ms", pairing);
  row.set("dij_binomial_ms", binomial);
  row.set("dij_quaternary_ms", quaternary);
  row.set("dij_fib_over_best", fib / std::min({fib, pairing, binomial, quaternary}));
  row.set("dij_fib_ns_ElogV", fib * 1e6 / ElogV);
  row.set("dij_csr_ref_ms", ref);
  row.set("dij_csr_ref_maxdiff", worst);

  // One run on the largest patch through its Face_filtered_graph (Fibonacci).
  const Patch patch(m, c.seg.patch_faces[c.largest_patch]);
  std::vector<double> dp(num_vertices(patch));
  auto pmap = boost::make_iterator_property_map(dp.begin(), get(boost::vertex_index, patch));
  diffuv::Multi_source_dijkstra<Patch, diffuv::Fibonacci_heap_tag> on_patch(patch);
  row.set("dij_patch_V", static_cast<std::size_t>(num_vertices(patch)));
  row.set("dij_patch_fib_ms", median_time(druns, [&] { on_patch.run(sources, lengths, pmap); }));

  // One fast-marching run on the whole mesh (the default distance), set-up apart.
  std::vector<double> times, setup;
  for(int r = 0; r < std::max(1, runs / 2); ++r) {
    auto t0 = Clock::now();
    diffuv::Fast_marching<Mesh, diffuv::Fibonacci_heap_tag> fmm(m);
    setup.push_back(ms_since(t0));
    auto dmap = boost::make_iterator_property_map(d_other.begin(), get(boost::vertex_index, m));
    fmm.run(sources, dmap);
    for(int k = 0; k < 2; ++k) {
      t0 = Clock::now();
      fmm.run(sources, dmap);
      times.push_back(ms_since(t0));
    }
  }
  row.set("fmm_setup_ms", median(setup));
  row.set("fmm_run_ms", median(times));
  progress(tag + "Dijkstra: fibonacci " + format("%.2f", fib) + ", pairing " + format("%.2f", pairing) + ", binomial " +
           format("%.2f", binomial) + ", 4-ary " + format("%.2f", quaternary) + ", csr reference " + format("%.2f", ref) +
           " ms");
}

} // namespace diffuv_bench
