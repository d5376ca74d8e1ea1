// diffuv benchmark: speed and memory (issue #11).
//
// For each mesh (CGAL's cow.off and man.off, closed, cut into patches by
// `disc_patches()`; a disc mesh, one patch) and its Loop-subdivided copies
// (CGAL::Subdivision_method_3::Loop_subdivision, one more iteration per size
// until the copy has at least --sizes vertices), it measures, single thread,
// medians of --runs runs:
//   (a) one multi-source Dijkstra per heap (Fibonacci, pairing, binomial,
//       4-ary): the whole mesh, from side u1 of its largest patch; plus a
//       bench-local reference (lazy-deletion binary heap on a CSR graph, not
//       library code), one run on the largest patch (Face_filtered_graph,
//       Fibonacci) and one fast-marching run on the whole mesh;
//   (b) the whole parameterization from given patches (parameterize_patches():
//       sides, four passes per patch, repair, atlas with kd-trees; file IO and
//       the segmentation excluded), for the paper's method (graph distances,
//       no repair) and the default (fmm distances + repair); and the automatic
//       patches (disc_patches() without labels) on their own;
//   (c) the atlas and kd-tree build, nearest-vertex queries and point
//       locations per second (uniform random (u,v) in a random chart);
//   (d) CGAL's Tutte (barycentric) and mean value parameterizers on the same
//       patches with the same corners (cgal_parameterize_patch(); sum over
//       patches of CGAL's parameterize() call), and the ratio to ours;
//   (e) peak memory per vertex of the parameterization.
//
// Segmentation of a subdivided copy: the labels of the parent patches are
// carried to the child faces (each face of the parent mesh is split into four
// faces of the child, which keep its patch), which gives the same patches
// without running the automatic segmentation again; the automatic
// segmentation is timed on its own in column "auto".
//
// Every (mesh, size) runs in a child process of its own (fork + exec of this
// program with --worker), so that memory high-water marks and allocator state
// do not carry over from one size to the next. Peak memory: the child
// releases free heap memory (malloc_trim), resets its high-water mark
// (writing 5 to /proc/self/clear_refs), runs the pipeline once and reads
// VmHWM; "peak" is that high-water mark (mesh, segmentation and pipeline),
// "extra" is what the pipeline added to the resident set.
//
// Usage: diffuv_performance_bench [--meshes cow,man,lion-head] [--sizes 1000000]
//          [--max-vertices N] [--first-level L] [--runs 5] [--parts abcde] [--quick]
//          [--profile] [-o DIR]   (--help lists the rest)
// Writes DIR/results.csv (every column; rewritten after each size, so an
// interrupted run keeps what it measured), DIR/table.md (with --profile, a
// table of the pipeline's stages too), DIR/scaling.png, DIR/heaps.png and
// DIR/time_<mesh>.png; prints the tables on stdout and progress on stderr.
// Exit code: 0, 1 if a size failed or timed out (--timeout), 4 on an error.
//
// Profiling: --perf-loop paper|default|auto --mesh NAME --level L --repeat N
// runs only the pipeline (or the automatic patches) N times after building the
// mesh, for perf record (scripts/perf_stages.py sums the samples by stage).
#include "plot_png.h"

#include <diffuv/atlas/Uv_atlas.h>
#include "compare/cgal_parameterizers.h"
#include <diffuv/core/error.h>
#include <diffuv/graph/distance_tags.h>
#include <diffuv/graph/edge_length_map.h>
#include <diffuv/graph/fast_marching.h>
#include <diffuv/graph/heap_tags.h>
#include <diffuv/graph/multi_source_dijkstra.h>
#include <diffuv/io/read_mesh.h>
#include <diffuv/parameterization/diffusion_coordinates.h>
#include <diffuv/parameterization/parameterize_patches.h>
#include <diffuv/parameterization/repair_folds.h>
#include <diffuv/layout/disc_patches.h>
#include <diffuv/patches/region_sides.h>
#include <diffuv/patches/segmentation.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Kd_tree.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_2.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Face_filtered_graph.h>
#include <CGAL/subdivision_method_3.h>

#include <boost/heap/fibonacci_heap.hpp>
#include <boost/pool/pool_alloc.hpp>
#include <boost/property_map/property_map.hpp>

#include <CLI/CLI.hpp>

#include <malloc.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <numeric>
#include <queue>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <type_traits>
#include <utility>
#include <vector>

#ifndef DIFFUV_DEFAULT_DATA_DIR
#define DIFFUV_DEFAULT_DATA_DIR "data"
#endif

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point_3 = Kernel::Point_3;
using Point_2 = Kernel::Point_2;
using Mesh = CGAL::Surface_mesh<Point_3>;
using vertex_descriptor = Mesh::Vertex_index;
using halfedge_descriptor = Mesh::Halfedge_index;
using face_descriptor = Mesh::Face_index;
using Patch = CGAL::Face_filtered_graph<Mesh>;
using Seg = diffuv::Segmentation<Mesh>;
using Sides = diffuv::Four_sides<vertex_descriptor>;
using Atlas = diffuv::Uv_atlas<Mesh>;
using Clock = std::chrono::steady_clock;

constexpr double infinity = std::numeric_limits<double>::infinity();
volatile std::size_t sink = 0; // results of loops that are only timed

double ms_since(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

double median(std::vector<double> v)
{
  if(v.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

std::string format(const char* f, double x)
{
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, f, x);
  return buffer;
}

// ---------------------------------------------------------------------------
// Options

struct Options {
  std::vector<std::string> meshes{"cow", "man", "lion-head"};
  std::size_t sizes = 1000000;     // subdivide until a copy has at least this many vertices
  std::size_t max_vertices = 0;    // 0: no cap; else no copy above this many vertices
  int first_level = 0;             // skip the copies below this level
  int runs = 5;
  int large_runs = 3;              // runs above large_vertices (pipelines, automatic patches, CGAL)
  std::size_t large_vertices = 300000;
  std::size_t queries = 100000;    // nearest-vertex queries and point locations per run
  std::size_t cgal_max_vertices = 0;  // 0: CGAL at every size
  std::size_t auto_max_vertices = 0;  // 0: automatic patches at every size
  double timeout = 3600.;          // seconds per (mesh, size) child
  bool quick = false;
  bool profile = false;
  std::string parts = "abcde";     // which measurements (letters of the header comment)
  bool no_fork = false;
  std::string output = "bench-out/performance";
  // worker / perf loop
  std::string worker_mesh;
  int worker_level = 0;
  std::string result_file;
  std::string perf_loop;
  int repeat = 20;
};

std::string mesh_path(const std::string& name)
{
  if(name.find('/') != std::string::npos || name.find('.') != std::string::npos) return name;
  return std::string(DIFFUV_DEFAULT_DATA_DIR) + "/meshes/" + name + ".off";
}

std::string mesh_name(const std::string& path) { return std::filesystem::path(path).stem().string(); }

// ---------------------------------------------------------------------------
// Results: ordered key = value pairs, one set per (mesh, size)

struct Row {
  std::vector<std::pair<std::string, std::string>> values;

  void set(const std::string& key, const std::string& value)
  {
    for(auto& kv : values)
      if(kv.first == key) { kv.second = value; return; }
    values.emplace_back(key, value);
  }
  void set(const std::string& key, double value)
  {
    if(std::isnan(value)) { set(key, std::string("-")); return; }
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.6g", value);
    set(key, std::string(buffer));
  }
  void set(const std::string& key, std::size_t value) { set(key, std::to_string(value)); }
  void set(const std::string& key, int value) { set(key, std::to_string(value)); }

  std::string get(const std::string& key) const
  {
    for(const auto& kv : values)
      if(kv.first == key) return kv.second;
    return "-";
  }
  double number(const std::string& key) const
  {
    const std::string s = get(key);
    char* end = nullptr;
    const double x = std::strtod(s.c_str(), &end);
    return (end && end != s.c_str()) ? x : std::numeric_limits<double>::quiet_NaN();
  }
};

void write_row(const Row& row, const std::string& path)
{
  std::ofstream f(path);
  for(const auto& kv : row.values) f << kv.first << "=" << kv.second << "\n";
}

Row read_row(const std::string& path)
{
  Row row;
  std::ifstream f(path);
  std::string line;
  while(std::getline(f, line)) {
    const auto eq = line.find('=');
    if(eq != std::string::npos) row.values.emplace_back(line.substr(0, eq), line.substr(eq + 1));
  }
  return row;
}

// ---------------------------------------------------------------------------
// Memory

long status_kb(const char* key)
{
  std::ifstream f("/proc/self/status");
  std::string line;
  const std::size_t n = std::strlen(key);
  while(std::getline(f, line))
    if(line.compare(0, n, key) == 0) return std::strtol(line.c_str() + n, nullptr, 10);
  return -1;
}

// Releases free heap memory and resets the high-water mark to the current
// resident set; returns the resident set in bytes, or -1 if the reset is not
// available (then the caller reports the process peak instead).
long long reset_peak()
{
  malloc_trim(0);
  {
    std::ofstream f("/proc/self/clear_refs");
    if(!f) return -1;
    f << "5";
    f.flush();
    if(!f) return -1;
  }
  const long rss = status_kb("VmRSS:"), hwm = status_kb("VmHWM:");
  if(rss < 0 || hwm < 0 || hwm > rss + 1024) return -1; // not reset
  return static_cast<long long>(rss) * 1024;
}

long long peak_bytes() { return static_cast<long long>(status_kb("VmHWM:")) * 1024; }

// ---------------------------------------------------------------------------
// Meshes: read, patches, Loop subdivision carrying the patches

struct Case {
  std::string name;
  Mesh mesh;
  Seg seg;                        // the given patches
  std::vector<Sides> sides;       // per patch (region_sides(), as the pipeline computes them)
  std::vector<bool> patch_ok;
  std::size_t largest_patch = 0;  // by number of faces
  std::string labels_from;        // "disc_patches" (level 0) or "parent patches"
  double setup_seconds = 0;       // reading, subdividing, patching (untimed in the results)
};

// One Loop subdivision step; `labels` (by face index) are carried from each
// parent face to its four children. The children of a face are the face
// itself (CGAL's Euler operations keep it, with its index) and the faces
// reached from it across edges joining two new (edge-midpoint) vertices:
// such an edge lies inside one parent face. Checked: every face is reached,
// each parent face has exactly four children.
std::vector<int> loop_subdivide(Mesh& m, const std::vector<int>& labels)
{
  const std::size_t v0 = m.number_of_vertices(), f0 = m.number_of_faces();
  if(m.has_garbage()) m.collect_garbage();
  CGAL::Subdivision_method_3::Loop_subdivision(m, CGAL::parameters::number_of_iterations(1));
  if(m.number_of_faces() != 4 * f0) throw std::runtime_error("Loop subdivision: face count is not 4x");
  constexpr int unset = std::numeric_limits<int>::min();
  std::vector<int> out(m.number_of_faces(), unset);
  std::vector<std::uint32_t> group(m.number_of_faces(), 0), group_size(f0, 0);
  std::vector<face_descriptor> queue;
  for(std::size_t i = 0; i < f0; ++i) {
    const face_descriptor f(static_cast<Mesh::size_type>(i));
    out[i] = labels[i];
    group[i] = static_cast<std::uint32_t>(i);
    ++group_size[i];
    queue.assign(1, f);
    for(std::size_t q = 0; q < queue.size(); ++q)
      for(halfedge_descriptor h : CGAL::halfedges_around_face(m.halfedge(queue[q]), m)) {
        if(m.source(h).idx() < v0 || m.target(h).idx() < v0) continue;
        const halfedge_descriptor o = m.opposite(h);
        if(m.is_border(o)) continue;
        const face_descriptor g = m.face(o);
        if(out[g.idx()] != unset) continue;
        out[g.idx()] = labels[i];
        group[g.idx()] = static_cast<std::uint32_t>(i);
        ++group_size[i];
        queue.push_back(g);
      }
  }
  for(std::size_t i = 0; i < out.size(); ++i)
    if(out[i] == unset) throw std::runtime_error("Loop subdivision: a face with no parent");
  for(std::size_t i = 0; i < f0; ++i)
    if(group_size[i] != 4) throw std::runtime_error("Loop subdivision: a parent face without four children");
  return out;
}

Case make_case(const std::string& name_or_path, int level)
{
  const auto t0 = Clock::now();
  Case c;
  const std::string path = mesh_path(name_or_path);
  c.name = mesh_name(path);
  diffuv::read_triangle_mesh(path, c.mesh);
  // The given patches of the base mesh: automatic (closed meshes) or the whole disc.
  Seg base;
  const diffuv::Status status = diffuv::disc_patches(c.mesh, c.mesh.points(), std::vector<int>{}, base);
  if(!status) throw std::runtime_error(c.name + ": disc_patches: " + status.what());
  if(level == 0) {
    c.seg = std::move(base);
    c.labels_from = "disc_patches";
  } else {
    std::vector<int> labels(c.mesh.number_of_faces());
    for(auto f : c.mesh.faces()) labels[f.idx()] = static_cast<int>(base.face_patch[f.idx()]);
    for(int l = 0; l < level; ++l) labels = loop_subdivide(c.mesh, labels);
    c.seg = diffuv::patches_from_labels(c.mesh, c.mesh.points(), labels);
    if(c.seg.number_of_patches() != base.number_of_patches())
      throw std::runtime_error(c.name + ": the subdivided patches differ in number from the parent's");
    c.labels_from = "parent patches";
  }
  const std::size_t P = c.seg.number_of_patches();
  c.sides.resize(P);
  c.patch_ok.assign(P, false);
  for(std::size_t p = 0; p < P; ++p) {
    diffuv::Status s = diffuv::check_patch_disc(c.mesh, c.seg, p);
    if(s) s = diffuv::region_sides(c.mesh, c.mesh.points(), c.seg, p, c.sides[p]);
    c.patch_ok[p] = static_cast<bool>(s);
    if(c.patch_ok[p] && (!c.patch_ok[c.largest_patch] ||
                         c.seg.patch_faces[p].size() > c.seg.patch_faces[c.largest_patch].size()))
      c.largest_patch = p;
  }
  c.setup_seconds = ms_since(t0) / 1000.;
  return c;
}

// ---------------------------------------------------------------------------
// (b) the pipeline

struct Pipeline_run {
  double ms = 0;
  std::size_t failed = 0, moved = 0, whole_patch = 0;
  std::unique_ptr<Atlas> atlas;
};

// threads: 1 (the single-thread figures), or 2 for the parallel speed-up.
template <class DistanceTag, class HeapTag = diffuv::Fibonacci_heap_tag>
Pipeline_run run_pipeline(const Case& c, bool repair, std::size_t threads = 1)
{
  Pipeline_run r;
  const auto t0 = Clock::now();
  r.atlas = std::make_unique<Atlas>(c.mesh);
  const auto results = diffuv::parameterize_patches<DistanceTag, HeapTag>(c.mesh, c.mesh.points(), c.seg, *r.atlas, diffuv::Patch_parameterization_options{diffuv::Repair_options{repair}, nullptr, true, threads});
  r.ms = ms_since(t0);
  for(const auto& p : results) {
    if(!p.status) ++r.failed;
    r.moved += p.repair.moved_vertices;
    r.whole_patch += p.repair.whole_patch;
  }
  return r;
}

// The same pipeline as parameterize_patches() (same calls, same order), with a
// timer per stage, and extra measurements that are not part of the pipeline
// (not in `total`): the distance engine alone (set-up, four runs) and one
// plain pass over the patch's vertices and faces through the
// Face_filtered_graph (the pipeline makes several such passes per patch).
struct Stages {
  double setup = 0, disc_check = 0, sides = 0, ffg = 0, engine = 0, distances = 0, repair = 0, chart = 0, total = 0;
  double engine_setup = 0, engine_runs = 0, scan_vertices = 0, scan_faces = 0;
};

const char* const stage_names[] = {"setup",  "disc_check", "sides",        "ffg",         "engine",
                                   "distances", "repair",  "chart",        "total",       "engine_setup",
                                   "engine_runs", "scan_vertices", "scan_faces"};

std::array<double, 13> stage_values(const Stages& s)
{
  return {s.setup, s.disc_check, s.sides, s.ffg, s.engine, s.distances, s.repair, s.chart, s.total,
          s.engine_setup, s.engine_runs, s.scan_vertices, s.scan_faces};
}

template <class DistanceTag>
Stages staged_pipeline(const Case& c, bool repair)
{
  using Heap = diffuv::Fibonacci_heap_tag;
  const Mesh& m = c.mesh;
  Stages s;
  const auto start = Clock::now();
  auto t = Clock::now();
  auto lap = [&](double& acc) {
    const auto now = Clock::now();
    acc += std::chrono::duration<double, std::milli>(now - t).count();
    t = now;
  };
  double outside = 0; // extra measurements, taken out of the total
  Atlas atlas(m);
  const auto lengths = diffuv::edge_length_map(m, m.points());
  diffuv::Patch_graph<Mesh> pgraph;
  lap(s.setup);
  for(std::size_t p = 0; p < c.seg.number_of_patches(); ++p) {
    diffuv::Patch_result<Mesh> r;
    r.status = diffuv::check_patch_disc(m, c.seg, p);
    lap(s.disc_check);
    if(r.status) r.status = diffuv::region_sides(m, m.points(), c.seg, p, r.sides, {}, &r.side_report);
    lap(s.sides);
    if(!r.status) continue;
    if(std::is_same_v<DistanceTag, diffuv::Graph_distance_tag> && !repair) {
      // The library's path for the paper's method: a compact graph per patch.
      auto findex = get(boost::face_index, m);
      pgraph.build(m, c.seg.patch_faces[p],
                   [&](face_descriptor f) { return f != Mesh::null_face() && c.seg.face_patch[get(findex, f)] == p; },
                   lengths);
      const auto ls = pgraph.local_sides(m, r.sides);
      lap(s.ffg);
      std::vector<Point_2> uv(pgraph.number_of_vertices());
      diffuv::Diffusion_coordinates<diffuv::Patch_graph<Mesh>::Graph, diffuv::Graph_distance_tag, Heap> coordinates(
          pgraph.graph());
      lap(s.engine);
      r.status = coordinates.compute(ls, pgraph.length_map(),
                                     boost::make_iterator_property_map(uv.begin(), get(boost::vertex_index, pgraph.graph())));
      lap(s.distances);
      if(!r.status) continue;
      atlas.add_chart(c.seg.patch_faces[p], pgraph.mesh_vertices(), std::move(uv));
      lap(s.chart);
      continue;
    }
    const Patch patch(m, c.seg.patch_faces[p]);
    auto pindex = get(boost::vertex_index, patch);
    lap(s.ffg);
    std::vector<Point_2> uv(num_vertices(patch));
    diffuv::Diffusion_coordinates<Patch, DistanceTag, Heap> coordinates(patch);
    lap(s.engine);
    r.status = coordinates.compute(r.sides, lengths, boost::make_iterator_property_map(uv.begin(), pindex));
    lap(s.distances);
    if(!r.status) continue;
    diffuv::repair_folds(patch, m.points(), r.sides, boost::make_iterator_property_map(uv.begin(), pindex), diffuv::Repair_options{repair},
                         &r.repair);
    lap(s.repair);
    std::vector<vertex_descriptor> chart_vertices(num_vertices(patch));
    for(vertex_descriptor v : vertices(patch)) chart_vertices[get(pindex, v)] = v;
    atlas.add_chart(c.seg.patch_faces[p], std::move(chart_vertices), std::move(uv));
    lap(s.chart);

    // Not part of the pipeline: the engine alone, and plain passes.
    const auto x0 = Clock::now();
    {
      std::vector<double> d(num_vertices(patch));
      auto dmap = boost::make_iterator_property_map(d.begin(), pindex);
      const std::array<const std::vector<vertex_descriptor>*, 4> sources = {&r.sides.u1, &r.sides.u2, &r.sides.v1,
                                                                            &r.sides.v2};
      auto e0 = Clock::now();
      if constexpr(std::is_same_v<DistanceTag, diffuv::Fmm_distance_tag>) {
        diffuv::Fast_marching<Patch, Heap> engine(patch);
        s.engine_setup += ms_since(e0);
        e0 = Clock::now();
        for(const auto* src : sources) engine.run(*src, dmap);
      } else {
        diffuv::Multi_source_dijkstra<Patch, Heap> engine(patch);
        s.engine_setup += ms_since(e0);
        e0 = Clock::now();
        for(const auto* src : sources) engine.run(*src, lengths, dmap);
      }
      s.engine_runs += ms_since(e0);
      e0 = Clock::now();
      std::size_t count = 0;
      for(vertex_descriptor v : vertices(patch)) count += v.idx() & 1u;
      s.scan_vertices += ms_since(e0);
      e0 = Clock::now();
      for(face_descriptor f : faces(patch)) count += f.idx() & 1u;
      s.scan_faces += ms_since(e0);
      sink = count; // keep the loops
    }
    outside += ms_since(x0);
    t = Clock::now();
  }
  s.total = ms_since(start) - outside;
  return s;
}

// ---------------------------------------------------------------------------
// (a) Dijkstra

// Bench-local reference, not library code: the graph in compressed rows and a
// binary heap without decrease-key (std::priority_queue, stale entries skipped).
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

// Lazy deletion: a vertex is pushed again when its distance drops, stale
// entries are skipped when popped.
void csr_dijkstra(const Csr_graph& g, const std::vector<std::uint32_t>& sources, std::vector<double>& dist)
{
  using Item = std::pair<double, std::uint32_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> heap;
  std::fill(dist.begin(), dist.end(), infinity);
  for(std::uint32_t s : sources) {
    dist[s] = 0.;
    heap.emplace(0., s);
  }
  while(!heap.empty()) {
    const auto [d, a] = heap.top();
    heap.pop();
    if(d > dist[a]) continue;
    for(std::uint32_t k = g.begin[a]; k < g.begin[a + 1]; ++k) {
      const std::uint32_t b = g.target[k];
      const double candidate = d + g.weight[k];
      if(candidate < dist[b]) {
        dist[b] = candidate;
        heap.emplace(candidate, b);
      }
    }
  }
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

template <class F>
double median_time(int runs, F&& f)
{
  f(); // warm-up
  std::vector<double> times;
  for(int r = 0; r < runs; ++r) {
    const auto t0 = Clock::now();
    f();
    times.push_back(ms_since(t0));
  }
  return median(times);
}

template <class HeapTag>
double time_dijkstra(const Mesh& m, const std::vector<vertex_descriptor>& sources,
                     const diffuv::Edge_length_map<Mesh>& lengths, int runs, std::vector<double>& dist)
{
  diffuv::Multi_source_dijkstra<Mesh, HeapTag> dijkstra(m);
  auto dmap = boost::make_iterator_property_map(dist.begin(), get(boost::vertex_index, m));
  dijkstra.run(sources, lengths, dmap); // warm-up
  std::vector<double> times;
  for(int r = 0; r < runs; ++r) {
    const auto t0 = Clock::now();
    dijkstra.run(sources, lengths, dmap);
    times.push_back(ms_since(t0));
  }
  return median(times);
}

// ---------------------------------------------------------------------------
// (c) kd-tree replica for the reference nearest-vertex query

struct Uv_ref_map {
  using key_type = std::uint32_t;
  using value_type = Point_2;
  using reference = const Point_2&;
  using category = boost::lvalue_property_map_tag;
  const Point_2* uv = nullptr;
  friend reference get(const Uv_ref_map& m, key_type i) { return m.uv[i]; }
};
using Ref_base = CGAL::Search_traits_2<Kernel>;
using Ref_traits = CGAL::Search_traits_adapter<std::uint32_t, Uv_ref_map, Ref_base>;
using Ref_distance = CGAL::Distance_adapter<std::uint32_t, Uv_ref_map, CGAL::Euclidean_distance<Ref_base>>;
using Ref_knn = CGAL::Orthogonal_k_neighbor_search<Ref_traits, Ref_distance>;
using Ref_tree = Ref_knn::Tree;

std::unique_ptr<Ref_tree> build_ref_tree(const std::vector<Point_2>& uv)
{
  std::vector<std::uint32_t> ids(uv.size());
  std::iota(ids.begin(), ids.end(), 0u);
  auto tree = std::make_unique<Ref_tree>(ids.begin(), ids.end(), Ref_tree::Splitter(), Ref_traits(Uv_ref_map{uv.data()}));
  tree->build();
  return tree;
}

// ---------------------------------------------------------------------------
// The worker: everything for one (mesh, level)

void log(const std::string& what) { std::cerr << what << std::endl; }

Row run_worker(const Options& o, const std::string& mesh, int level)
{
  Row row;
  const auto worker_start = Clock::now();
  Case c = make_case(mesh, level);
  const Mesh& m = c.mesh;
  const std::size_t V = m.number_of_vertices(), E = m.number_of_edges(), F = m.number_of_faces();
  const std::size_t P = c.seg.number_of_patches();
  const bool large = V > o.large_vertices;
  const int runs = large ? std::min(o.runs, o.large_runs) : o.runs;
  const std::string tag = "[" + c.name + " L" + std::to_string(level) + " " + std::to_string(V) + "v] ";
  log(tag + "mesh ready in " + format("%.1f", c.setup_seconds) + " s: " + std::to_string(P) + " patches (" +
      c.labels_from + ")");

  row.set("mesh", c.name);
  row.set("level", level);
  row.set("V", V);
  row.set("E", E);
  row.set("F", F);
  row.set("patches", P);
  row.set("patches_ok", static_cast<std::size_t>(std::count(c.patch_ok.begin(), c.patch_ok.end(), true)));
  row.set("labels", c.labels_from);
  row.set("runs", runs);
  const double ElogV = static_cast<double>(E) * std::log2(static_cast<double>(V));

  auto part = [&](char x) { return o.parts.find(x) != std::string::npos; };
  row.set("parts", o.parts);

  // (e) memory, and the first (warm-up) run of each pipeline.
  std::unique_ptr<Atlas> atlas; // the default pipeline's atlas, for (c)
  if(part('e')) {
    const long long before = reset_peak();
    Pipeline_run d = run_pipeline<diffuv::Default_distance_tag>(c, true);
    const long long peak = peak_bytes();
    row.set("mem_method", std::string(before >= 0 ? "clear_refs" : "none"));
    row.set("mem_default_peak_Bpv", before >= 0 ? double(peak) / double(V) : std::numeric_limits<double>::quiet_NaN());
    row.set("mem_default_extra_Bpv",
            before >= 0 ? double(peak - before) / double(V) : std::numeric_limits<double>::quiet_NaN());
    row.set("default_failed", d.failed);
    row.set("default_moved", d.moved);
    row.set("default_whole_patch", d.whole_patch);
    atlas = std::move(d.atlas);
  }
  {
    const long long before = reset_peak();
    Pipeline_run g = run_pipeline<diffuv::Graph_distance_tag>(c, false);
    const long long peak = peak_bytes();
    row.set("mem_paper_peak_Bpv", before >= 0 ? double(peak) / double(V) : std::numeric_limits<double>::quiet_NaN());
    row.set("mem_paper_extra_Bpv",
            before >= 0 ? double(peak - before) / double(V) : std::numeric_limits<double>::quiet_NaN());
    row.set("paper_failed", g.failed);
  }

  // (b) the pipelines, alternating.
  if(part('b')) {
    std::vector<double> paper, dflt, paper2, dflt2, paper4, dflt4;
    for(int r = 0; r < runs; ++r) {
      paper.push_back(run_pipeline<diffuv::Graph_distance_tag>(c, false).ms);
      dflt.push_back(run_pipeline<diffuv::Default_distance_tag>(c, true).ms);
      paper2.push_back(run_pipeline<diffuv::Graph_distance_tag>(c, false, 2).ms);
      paper4.push_back(run_pipeline<diffuv::Graph_distance_tag, diffuv::Quaternary_heap_tag>(c, false).ms);
      dflt4.push_back(run_pipeline<diffuv::Default_distance_tag, diffuv::Quaternary_heap_tag>(c, true).ms);
      dflt2.push_back(run_pipeline<diffuv::Default_distance_tag>(c, true, 2).ms);
    }
    const double tp = median(paper), td = median(dflt);
    row.set("paper_ms", tp);
    row.set("default_ms", td);
    row.set("paper_ns_ElogV", tp * 1e6 / ElogV);
    row.set("default_ns_ElogV", td * 1e6 / ElogV);
    row.set("paper_2threads_ms", median(paper2));
    row.set("paper_4ary_ms", median(paper4));
    row.set("default_4ary_ms", median(dflt4));
    row.set("default_2threads_ms", median(dflt2));
    row.set("threads2_speedup", format("%.2f", tp / median(paper2)) + " / " + format("%.2f", td / median(dflt2)));
    log(tag + "pipelines: paper " + format("%.2f", tp) + " ms, default " + format("%.2f", td) + " ms");
  }
  if(part('b') && (o.auto_max_vertices == 0 || V <= o.auto_max_vertices)) {
    std::vector<double> times;
    std::size_t patches = 0;
    const int auto_runs = large ? 1 : runs; // minutes per run on the largest copies
    row.set("auto_runs", auto_runs);
    for(int r = 0; r < auto_runs; ++r) {
      Seg seg;
      const auto t0 = Clock::now();
      diffuv::disc_patches(m, m.points(), std::vector<int>{}, seg);
      times.push_back(ms_since(t0));
      patches = seg.number_of_patches();
    }
    row.set("auto_ms", median(times));
    row.set("auto_patches", patches);
    log(tag + "automatic patches: " + format("%.2f", median(times)) + " ms, " + std::to_string(patches) + " patches");
  }

  // (a) Dijkstra, whole mesh, from side u1 of the largest patch.
  if(part('a')) {
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
    std::vector<double> times;
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
    on_patch.run(sources, lengths, pmap);
    times.clear();
    for(int r = 0; r < druns; ++r) {
      const auto t0 = Clock::now();
      on_patch.run(sources, lengths, pmap);
      times.push_back(ms_since(t0));
    }
    row.set("dij_patch_V", static_cast<std::size_t>(num_vertices(patch)));
    row.set("dij_patch_fib_ms", median(times));

    // One fast-marching run on the whole mesh (the default distance), set-up apart.
    times.clear();
    std::vector<double> setup;
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
    log(tag + "Dijkstra: fibonacci " + format("%.2f", fib) + ", pairing " + format("%.2f", pairing) + ", binomial " +
        format("%.2f", binomial) + ", 4-ary " + format("%.2f", quaternary) + ", csr reference " + format("%.2f", ref) +
        " ms");
  }

  // (c) atlas, kd-trees, queries.
  if(part('c') && !atlas) atlas = run_pipeline<diffuv::Default_distance_tag>(c, true).atlas;
  if(part('c')) {
    const std::size_t C = atlas->number_of_charts();
    std::vector<double> build, kd;
    for(int r = 0; r < runs; ++r) {
      std::vector<std::vector<face_descriptor>> fs(C);
      std::vector<std::vector<vertex_descriptor>> vs(C);
      std::vector<std::vector<Point_2>> uvs(C);
      for(std::size_t k = 0; k < C; ++k) {
        fs[k] = atlas->chart(k).faces;
        vs[k] = atlas->chart(k).vertices;
        uvs[k] = atlas->chart(k).uv;
      }
      auto t0 = Clock::now();
      {
        Atlas fresh(m);
        for(std::size_t k = 0; k < C; ++k) fresh.add_chart(std::move(fs[k]), std::move(vs[k]), std::move(uvs[k]));
        build.push_back(ms_since(t0));
      }
      t0 = Clock::now();
      std::vector<std::unique_ptr<Ref_tree>> trees;
      for(std::size_t k = 0; k < C; ++k) trees.push_back(build_ref_tree(atlas->chart(k).uv));
      kd.push_back(ms_since(t0));
    }
    row.set("charts", C);
    row.set("atlas_build_ms", median(build));
    row.set("kd_build_ms", median(kd));

    std::mt19937_64 random(12345);
    std::uniform_int_distribution<std::size_t> any_chart(0, C - 1);
    std::uniform_real_distribution<double> unit(0., 1.);
    std::vector<std::pair<std::size_t, Point_2>> queries(o.queries);
    for(auto& q : queries) q = {any_chart(random), Point_2(unit(random), unit(random))};
    std::vector<std::unique_ptr<Ref_tree>> trees;
    for(std::size_t k = 0; k < C; ++k) trees.push_back(build_ref_tree(atlas->chart(k).uv));

    std::vector<double> nn, loc, ref;
    std::size_t inside = 0, agree = 0, checked = 0;
    const int qruns = std::max(3, std::min(runs, 5));
    for(int r = 0; r < qruns; ++r) {
      std::size_t sum = 0;
      auto t0 = Clock::now();
      for(const auto& q : queries) sum += atlas->nearest_vertex(q.first, q.second);
      nn.push_back(double(queries.size()) / (ms_since(t0) / 1000.));
      t0 = Clock::now();
      std::size_t in = 0;
      for(const auto& q : queries) in += atlas->locate(q.first, q.second).inside;
      loc.push_back(double(queries.size()) / (ms_since(t0) / 1000.));
      inside = in;
      t0 = Clock::now();
      std::size_t sum_ref = 0;
      for(const auto& q : queries) {
        const std::vector<Point_2>& uv = atlas->chart(q.first).uv;
        Ref_knn search(*trees[q.first], q.second, 1, 0., true, Ref_distance(Uv_ref_map{uv.data()}));
        sum_ref += search.begin()->first;
      }
      ref.push_back(double(queries.size()) / (ms_since(t0) / 1000.));
      sink = sum + sum_ref;
    }
    // The reference returns a nearest vertex too (ties aside): compare distances.
    for(std::size_t i = 0; i < std::min<std::size_t>(queries.size(), 2000); ++i) {
      const auto& q = queries[i];
      const std::vector<Point_2>& uv = atlas->chart(q.first).uv;
      Ref_knn search(*trees[q.first], q.second, 1, 0., true, Ref_distance(Uv_ref_map{uv.data()}));
      const double a = CGAL::squared_distance(uv[atlas->nearest_vertex(q.first, q.second)], q.second);
      const double b = CGAL::squared_distance(uv[search.begin()->first], q.second);
      agree += a == b;
      ++checked;
    }
    row.set("nn_per_s", median(nn));
    row.set("locate_per_s", median(loc));
    row.set("locate_inside_pct", 100. * double(inside) / double(queries.size()));
    row.set("knn_ref_per_s", median(ref));
    row.set("knn_ref_agree_pct", 100. * double(agree) / double(checked));
    log(tag + "atlas " + format("%.2f", median(build)) + " ms (kd-trees alone " + format("%.2f", median(kd)) +
        " ms), nearest vertex " + format("%.0f", median(nn)) + "/s, locate " + format("%.0f", median(loc)) + "/s");
  }
  atlas.reset();

  // (d) CGAL on the same patches with the same corners.
  if(part('d') && (o.cgal_max_vertices == 0 || V <= o.cgal_max_vertices)) {
    std::vector<Point_2> uv_store(V);
    auto uv_map = boost::make_iterator_property_map(uv_store.begin(), get(boost::vertex_index, m));
    const std::array<diffuv::Cgal_method, 2> methods = {diffuv::Cgal_method::tutte, diffuv::Cgal_method::mean_value};
    std::array<std::vector<double>, 2> times;
    std::array<double, 2> copy{0, 0};
    std::array<std::size_t, 2> failed{0, 0};
    for(int r = 0; r < runs; ++r)
      for(std::size_t k = 0; k < methods.size(); ++k) {
        double sum = 0, copy_sum = 0;
        std::size_t fails = 0;
        for(std::size_t p = 0; p < P; ++p) {
          if(!c.patch_ok[p]) continue;
          const auto map = diffuv::cgal_parameterize_patch(m, c.seg.patch_faces[p], m.points(), c.sides[p].corners,
                                                           methods[k], uv_map);
          if(!map.ok()) ++fails;
          sum += map.milliseconds;
          copy_sum += map.extraction_milliseconds;
        }
        times[k].push_back(sum);
        copy[k] = copy_sum;
        failed[k] = fails;
      }
    const double tutte = median(times[0]), mv = median(times[1]);
    row.set("tutte_ms", tutte);
    row.set("mean_value_ms", mv);
    row.set("cgal_copy_ms", copy[0]);
    row.set("cgal_failed", failed[0] + failed[1]);
    const double best = std::min(tutte, mv);
    row.set("cgal_over_default", best / row.number("default_ms"));
    row.set("cgal_over_paper", best / row.number("paper_ms"));
    log(tag + "CGAL: tutte " + format("%.1f", tutte) + " ms, mean value " + format("%.1f", mv) + " ms");
  }

  // Stages of the pipeline (--profile).
  if(o.profile) {
    std::vector<std::array<double, 13>> paper, dflt;
    for(int r = 0; r < runs; ++r) {
      paper.push_back(stage_values(staged_pipeline<diffuv::Graph_distance_tag>(c, false)));
      dflt.push_back(stage_values(staged_pipeline<diffuv::Default_distance_tag>(c, true)));
    }
    for(std::size_t k = 0; k < 13; ++k) {
      std::vector<double> a, b;
      for(const auto& s : paper) a.push_back(s[k]);
      for(const auto& s : dflt) b.push_back(s[k]);
      row.set(std::string("prof_paper_") + stage_names[k], median(a));
      row.set(std::string("prof_default_") + stage_names[k], median(b));
    }
    log(tag + "profile: paper total " + format("%.2f", row.number("prof_paper_total")) + " ms, default total " +
        format("%.2f", row.number("prof_default_total")) + " ms");
  }
  row.set("setup_s", c.setup_seconds);
  row.set("worker_s", ms_since(worker_start) / 1000.);
  return row;
}

int perf_loop(const Options& o)
{
  const Case c = make_case(o.worker_mesh, o.worker_level);
  std::cerr << "perf loop: " << c.name << " level " << o.worker_level << ", " << c.mesh.number_of_vertices()
            << " vertices, " << c.seg.number_of_patches() << " patches; " << o.repeat << " x " << o.perf_loop
            << (o.perf_loop == "auto" ? " patches" : " pipeline") << std::endl;
  std::vector<double> times;
  for(int r = 0; r < o.repeat; ++r) {
    if(o.perf_loop == "auto") {
      Seg seg;
      const auto t0 = Clock::now();
      diffuv::disc_patches(c.mesh, c.mesh.points(), std::vector<int>{}, seg);
      times.push_back(ms_since(t0));
    } else {
      times.push_back(o.perf_loop == "paper" ? run_pipeline<diffuv::Graph_distance_tag>(c, false).ms
                                              : run_pipeline<diffuv::Default_distance_tag>(c, true).ms);
    }
  }
  std::cerr << "median " << median(times) << " ms" << std::endl;
  return 0;
}

// ---------------------------------------------------------------------------
// The parent: one child per (mesh, level)

// Runs the worker for (mesh, level) in a fresh process; returns its row, with
// "status" = ok / failed / timeout and the child's own peak (ru_maxrss).
Row spawn_worker(const Options& o, const std::string& mesh, int level, const std::string& exe)
{
  const std::string result = o.output + "/.worker_" + mesh_name(mesh_path(mesh)) + "_" + std::to_string(level) + ".txt";
  std::filesystem::remove(result);
  std::vector<std::string> args = {exe,
                                   "--worker", mesh,
                                   "--level", std::to_string(level),
                                   "--result-file", result,
                                   "--runs", std::to_string(o.runs),
                                   "--large-runs", std::to_string(o.large_runs),
                                   "--large-vertices", std::to_string(o.large_vertices),
                                   "--queries", std::to_string(o.queries),
                                   "--cgal-max-vertices", std::to_string(o.cgal_max_vertices),
                                   "--auto-max-vertices", std::to_string(o.auto_max_vertices),
                                   "--parts", o.parts,
                                   "-o", o.output};
  if(o.profile) args.push_back("--profile");
  std::vector<char*> argv;
  for(auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);

  const auto t0 = Clock::now();
  const pid_t pid = fork();
  if(pid < 0) throw std::runtime_error("fork failed");
  if(pid == 0) {
    execv(exe.c_str(), argv.data());
    std::perror("execv");
    _exit(127);
  }
  int status = 0;
  struct rusage usage {};
  bool timed_out = false;
  while(true) {
    const pid_t done = wait4(pid, &status, WNOHANG, &usage);
    if(done == pid) break;
    if(done < 0) throw std::runtime_error("wait4 failed");
    if(ms_since(t0) / 1000. > o.timeout) {
      kill(pid, SIGKILL);
      wait4(pid, &status, 0, &usage);
      timed_out = true;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  Row row;
  if(!timed_out && WIFEXITED(status) && WEXITSTATUS(status) == 0 && std::filesystem::exists(result)) {
    row = read_row(result);
    row.set("status", std::string("ok"));
  } else {
    row.set("mesh", mesh_name(mesh_path(mesh)));
    row.set("level", level);
    row.set("status", std::string(timed_out ? "timeout" : "failed"));
  }
  std::filesystem::remove(result);
  const double V = row.number("V");
  row.set("child_maxrss_Bpv", std::isnan(V) ? V : double(usage.ru_maxrss) * 1024. / V);
  row.set("wall_s", ms_since(t0) / 1000.);
  return row;
}

std::string cell(const Row& r, const std::string& key, const char* f = "%.3g")
{
  const double x = r.number(key);
  if(std::isnan(x)) return r.get(key);
  return format(f, x);
}

std::string tables(const std::vector<Row>& rows, const Options& o)
{
  std::ostringstream out;
  out << "### (a) one multi-source Dijkstra, whole mesh, from one side of the largest patch (ms)\n\n"
      << "| mesh | level | V | E | sources | fibonacci | pairing | binomial | 4-ary | fib / best | fib ns/(E log2 V) | "
         "fib on largest patch (V) | fmm run | fmm set-up |\n"
      << "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for(const Row& r : rows)
    out << "| " << r.get("mesh") << " | " << r.get("level") << " | " << r.get("V") << " | " << r.get("E") << " | "
        << r.get("sources") << " | " << cell(r, "dij_fib_ms") << " | " << cell(r, "dij_pairing_ms") << " | "
        << cell(r, "dij_binomial_ms") << " | " << cell(r, "dij_quaternary_ms") << " | "
        << cell(r, "dij_fib_over_best", "%.2f") << " | " << cell(r, "dij_fib_ns_ElogV", "%.2f") << " | "
        << cell(r, "dij_patch_fib_ms") << " (" << r.get("dij_patch_V") << ") | "
        << cell(r, "fmm_run_ms") << " | " << cell(r, "fmm_setup_ms") << " |\n";
  out << "\n### (a') the same run, bench-local references on a compressed-row (CSR) graph (ms; not library code)\n\n"
      << "| mesh | level | V | library fibonacci | CSR + fibonacci | CSR + fibonacci, pool allocator | CSR + 4-ary | "
         "CSR + binary heap, lazy deletion | same, BFS-renumbered vertices | max difference |\n"
      << "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for(const Row& r : rows)
    out << "| " << r.get("mesh") << " | " << r.get("level") << " | " << r.get("V") << " | " << cell(r, "dij_fib_ms")
        << " | " << cell(r, "dij_csr_fib_ms") << " | " << cell(r, "dij_csr_fib_pool_ms") << " | "
        << cell(r, "dij_csr_4ary_ms") << " | " << cell(r, "dij_csr_ref_ms") << " | " << cell(r, "dij_csr_bfs_ms")
        << " | " << r.get("dij_csr_ref_maxdiff") << " |\n";

  out << "\n### (b, d) the whole parameterization from given patches, and CGAL on the same patches (ms)\n\n"
      << "| mesh | level | V | patches | paper (graph, no repair) | default (fmm + repair) | same, 4-ary heap: paper / default | automatic patches (#) | "
         "paper ns/(E log2 V) | default ns/(E log2 V) | 2 threads: speed-up paper / default | CGAL tutte | CGAL mean value | "
         "min CGAL / default | min CGAL / paper | repair: moved (whole-patch solves) |\n"
      << "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for(const Row& r : rows)
    out << "| " << r.get("mesh") << " | " << r.get("level") << " | " << r.get("V") << " | " << r.get("patches")
        << " | " << cell(r, "paper_ms") << " | " << cell(r, "default_ms") << " | " << cell(r, "paper_4ary_ms") << " / "
        << cell(r, "default_4ary_ms") << " | " << cell(r, "auto_ms") << " ("
        << r.get("auto_patches") << ") | " << cell(r, "paper_ns_ElogV", "%.2f") << " | "
        << cell(r, "default_ns_ElogV", "%.2f") << " | " << r.get("threads2_speedup") << " | " << cell(r, "tutte_ms")
        << " | " << cell(r, "mean_value_ms") << " | " << cell(r, "cgal_over_default", "%.2f") << " | "
        << cell(r, "cgal_over_paper", "%.2f") << " | " << r.get("default_moved") << " (" << r.get("default_whole_patch")
        << ") |\n";

  out << "\n### (c, e) atlas queries and memory\n\n"
      << "| mesh | level | V | charts | atlas build ms | kd-trees alone ms | nearest vertex /s | locate /s "
         "(% inside) | k-NN reference /s | peak B/vertex default (extra) | peak B/vertex paper (extra) | "
         "child ru_maxrss B/vertex | status |\n"
      << "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n";
  for(const Row& r : rows)
    out << "| " << r.get("mesh") << " | " << r.get("level") << " | " << r.get("V") << " | " << r.get("charts")
        << " | " << cell(r, "atlas_build_ms") << " | " << cell(r, "kd_build_ms") << " | " << cell(r, "nn_per_s", "%.3g")
        << " | " << cell(r, "locate_per_s", "%.3g") << " (" << cell(r, "locate_inside_pct", "%.1f") << ") | "
        << cell(r, "knn_ref_per_s", "%.3g") << " | " << cell(r, "mem_default_peak_Bpv", "%.0f") << " ("
        << cell(r, "mem_default_extra_Bpv", "%.0f") << ") | " << cell(r, "mem_paper_peak_Bpv", "%.0f") << " ("
        << cell(r, "mem_paper_extra_Bpv", "%.0f") << ") | " << cell(r, "child_maxrss_Bpv", "%.0f") << " | "
        << r.get("status") << " |\n";

  if(o.profile) {
    out << "\n### pipeline stages (ms, sums over patches; --profile)\n\n"
        << "| mesh | level | V | method | total | setup | disc check | sides | patch graph | engine | distances | "
           "repair | chart + kd | engine set-up* | 4 runs* | one vertex pass* | one face pass* |\n"
        << "|---|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for(const Row& r : rows)
      for(const char* method : {"paper", "default"}) {
        const std::string p = std::string("prof_") + method + "_";
        out << "| " << r.get("mesh") << " | " << r.get("level") << " | " << r.get("V") << " | " << method;
        for(const char* s : {"total", "setup", "disc_check", "sides", "ffg", "engine", "distances", "repair", "chart",
                             "engine_setup", "engine_runs", "scan_vertices", "scan_faces"})
          out << " | " << cell(r, p + s);
        out << " |\n";
      }
    out << "\n*: measured apart, not part of the total (default method only). patch graph: the paper's method\n"
           "copies each patch into a compact graph (Patch_graph), the default walks a Face_filtered_graph.\n";
  }
  return out.str();
}

void write_csv(const std::vector<Row>& rows, const std::string& path)
{
  std::vector<std::string> keys;
  for(const Row& r : rows)
    for(const auto& kv : r.values)
      if(std::find(keys.begin(), keys.end(), kv.first) == keys.end()) keys.push_back(kv.first);
  std::ofstream f(path);
  for(std::size_t k = 0; k < keys.size(); ++k) f << (k ? "," : "") << keys[k];
  f << "\n";
  for(const Row& r : rows) {
    for(std::size_t k = 0; k < keys.size(); ++k) f << (k ? "," : "") << r.get(keys[k]);
    f << "\n";
  }
}

// Log-log plots (log10 on both axes; the plot writer is linear).
void write_plots(const std::vector<Row>& rows, const std::vector<std::string>& names, const std::string& dir)
{
  auto bounds = [](diffuv_bench::Line_plot& plot) {
    double x0 = infinity, x1 = -infinity, y0 = infinity, y1 = -infinity;
    for(const auto& s : plot.series)
      for(const auto& [x, y] : s.points) {
        x0 = std::min(x0, x); x1 = std::max(x1, x);
        y0 = std::min(y0, y); y1 = std::max(y1, y);
      }
    if(!(x1 > x0)) { x0 -= 0.5; x1 += 0.5; }
    if(!(y1 > y0)) { y0 -= 0.5; y1 += 0.5; }
    plot.x_min = std::floor(x0 * 2) / 2; plot.x_max = std::ceil(x1 * 2) / 2;
    plot.y_min = std::floor(y0 * 2) / 2; plot.y_max = std::ceil(y1 * 2) / 2;
  };
  auto series_of = [&](const std::string& mesh, const std::string& key, bool log_y) {
    std::vector<std::pair<double, double>> points;
    for(const Row& r : rows) {
      if(r.get("mesh") != mesh) continue;
      const double v = r.number("V"), y = r.number(key);
      if(std::isnan(v) || std::isnan(y) || (log_y && !(y > 0))) continue;
      points.emplace_back(std::log10(v), log_y ? std::log10(y) : y);
    }
    std::sort(points.begin(), points.end());
    return points;
  };

  // Time against size, per mesh.
  for(const std::string& mesh : names) {
    diffuv_bench::Line_plot plot;
    plot.title = mesh + ": time against size";
    plot.x_label = "log10 vertices";
    plot.y_label = "log10 ms";
    plot.legend = diffuv_bench::Line_plot::Legend::upper_left;
    const std::pair<const char*, const char*> curves[] = {{"paper (graph, raw)", "paper_ms"},
                                                          {"default (fmm + repair)", "default_ms"},
                                                          {"automatic patches", "auto_ms"},
                                                          {"cgal tutte", "tutte_ms"},
                                                          {"cgal mean value", "mean_value_ms"},
                                                          {"dijkstra (fibonacci)", "dij_fib_ms"}};
    for(const auto& [name, key] : curves) {
      diffuv_bench::Plot_series s;
      s.name = name;
      s.color = diffuv_bench::series_color(plot.series.size());
      s.points = series_of(mesh, key, true);
      if(!s.points.empty()) plot.series.push_back(std::move(s));
    }
    if(plot.series.empty()) continue;
    bounds(plot);
    diffuv_bench::write_plot_png(dir + "/time_" + mesh + ".png", plot);
  }
  // ns / (E log2 V) against size: flat = O(E log V).
  {
    diffuv_bench::Line_plot plot;
    plot.title = "time / (E log2 V)";
    plot.x_label = "log10 vertices";
    plot.y_label = "ns";
    plot.legend = diffuv_bench::Line_plot::Legend::upper_left;
    for(const std::string& mesh : names)
      for(const auto& [what, key] : {std::pair<const char*, const char*>{"paper", "paper_ns_ElogV"},
                                     std::pair<const char*, const char*>{"default", "default_ns_ElogV"}}) {
        diffuv_bench::Plot_series s;
        s.name = mesh + " " + what;
        s.color = diffuv_bench::series_color(plot.series.size());
        s.points = series_of(mesh, key, false);
        if(!s.points.empty()) plot.series.push_back(std::move(s));
      }
    if(!plot.series.empty()) {
      bounds(plot);
      plot.y_min = 0;
      plot.y_max = std::ceil(plot.y_max / 10) * 10;
      diffuv_bench::write_plot_png(dir + "/scaling.png", plot);
    }
  }
  // Heaps: Dijkstra ns / (E log2 V), all meshes by size.
  {
    diffuv_bench::Line_plot plot;
    plot.title = "one dijkstra run: ns / (E log2 V)";
    plot.x_label = "log10 vertices";
    plot.y_label = "ns";
    plot.legend = diffuv_bench::Line_plot::Legend::upper_left;
    const std::pair<const char*, const char*> heaps[] = {{"fibonacci", "dij_fib_ms"},
                                                         {"pairing", "dij_pairing_ms"},
                                                         {"binomial", "dij_binomial_ms"},
                                                         {"4-ary", "dij_quaternary_ms"},
                                                         {"csr + fibonacci (ref.)", "dij_csr_fib_ms"},
                                                         {"csr + binary heap (ref.)", "dij_csr_ref_ms"}};
    for(const auto& [name, key] : heaps) {
      diffuv_bench::Plot_series s;
      s.name = name;
      s.color = diffuv_bench::series_color(plot.series.size());
      for(const Row& r : rows) {
        const double v = r.number("V"), e = r.number("E"), t = r.number(key);
        if(std::isnan(v) || std::isnan(t)) continue;
        s.points.emplace_back(std::log10(v), t * 1e6 / (e * std::log2(v)));
      }
      std::sort(s.points.begin(), s.points.end());
      if(!s.points.empty()) plot.series.push_back(std::move(s));
    }
    if(!plot.series.empty()) {
      bounds(plot);
      plot.y_min = 0;
      diffuv_bench::write_plot_png(dir + "/heaps.png", plot);
    }
  }
}

int run_parent(const Options& o)
{
  const auto start = Clock::now();
  std::filesystem::create_directories(o.output);
  const std::string exe = std::filesystem::read_symlink("/proc/self/exe").string();
  std::vector<Row> rows;
  std::vector<std::string> names;
  for(const std::string& mesh : o.meshes) {
    names.push_back(mesh_name(mesh_path(mesh)));
    for(int level = o.first_level; level < 12; ++level) {
      Row row;
      if(o.no_fork) {
        row = run_worker(o, mesh, level);
        row.set("status", std::string("ok (no fork)"));
      } else {
        row = spawn_worker(o, mesh, level, exe);
      }
      rows.push_back(row);
      std::cerr << "[" << row.get("mesh") << " L" << level << "] " << row.get("status") << " in "
                << cell(row, "wall_s", "%.1f") << " s" << std::endl;
      write_csv(rows, o.output + "/results.csv"); // partial results survive an interruption
      const double V = row.number("V"), E = row.number("E");
      if(row.get("status").rfind("ok", 0) != 0 || std::isnan(V) || V >= double(o.sizes)) break;
      // Loop subdivision adds one vertex per edge.
      if(o.max_vertices > 0 && V + E > double(o.max_vertices)) break;
    }
  }
  const std::string md = tables(rows, o);
  std::cout << md;
  {
    std::ofstream f(o.output + "/table.md");
    f << "Command: diffuv_performance_bench --meshes ";
    for(std::size_t i = 0; i < o.meshes.size(); ++i) f << (i ? "," : "") << o.meshes[i];
    f << " --sizes " << o.sizes << " --runs " << o.runs << " --large-runs " << o.large_runs;
    if(o.max_vertices) f << " --max-vertices " << o.max_vertices;
    if(o.first_level) f << " --first-level " << o.first_level;
    f << (o.profile ? " --profile" : "") << "\n\n" << md;
  }
  write_csv(rows, o.output + "/results.csv");
  write_plots(rows, names, o.output);
  std::cerr << "wrote " << o.output << "/results.csv, table.md and plots; total "
            << format("%.1f", ms_since(start) / 1000.) << " s" << std::endl;
  for(const Row& r : rows)
    if(r.get("status").rfind("ok", 0) != 0) return 1;
  return 0;
}

} // namespace

int main(int argc, char** argv)
{
  Options o;
  CLI::App app{"diffuv performance benchmark (issue #11): Dijkstra per heap, the whole parameterization, atlas "
               "queries, CGAL's fixed-border parameterizers on the same patches, peak memory; CGAL's meshes and "
               "their Loop-subdivided copies"};
  app.add_option("--meshes", o.meshes, "Meshes: names in CGAL's data set (cow = <data>/meshes/cow.off) or paths")
      ->delimiter(',')
      ->capture_default_str();
  app.add_option("--sizes", o.sizes, "Largest size: each mesh is Loop-subdivided until it has at least this many vertices")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--max-vertices", o.max_vertices, "No copy above this many vertices (0: no cap)")
      ->capture_default_str();
  app.add_option("--first-level", o.first_level, "Start at this many subdivision steps")->capture_default_str();
  app.add_option("--runs", o.runs, "Runs to take the median of")->check(CLI::PositiveNumber)->capture_default_str();
  app.add_option("--large-runs", o.large_runs,
                 "Runs above --large-vertices (pipelines, CGAL, Dijkstra; the automatic patches run once there)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--large-vertices", o.large_vertices, "See --large-runs")->capture_default_str();
  app.add_option("--queries", o.queries, "Nearest-vertex queries and point locations per run")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--cgal-max-vertices", o.cgal_max_vertices, "Skip CGAL's parameterizers above this size (0: never)")
      ->capture_default_str();
  app.add_option("--auto-max-vertices", o.auto_max_vertices, "Skip the automatic patches above this size (0: never)")
      ->capture_default_str();
  app.add_option("--timeout", o.timeout, "Seconds per (mesh, size) before its child is killed")->capture_default_str();
  app.add_flag("--quick", o.quick, "Smoke run: sizes up to 20000 vertices, 3 runs, 20000 queries");
  app.add_option("--parts", o.parts, "Measurements to make: letters of a (Dijkstra), b (pipelines, automatic patches), "
                                     "c (atlas queries), d (CGAL), e (memory)")
      ->capture_default_str();
  app.add_flag("--profile", o.profile, "Also time each stage of the pipeline (writes a stage table)");
  app.add_flag("--no-fork", o.no_fork, "Run every size in this process (memory columns then carry over)");
  app.add_option("-o,--output", o.output, "Output folder")->capture_default_str();
  app.add_option("--worker", o.worker_mesh, "(internal) measure one mesh at --level and write --result-file")
      ->group("");
  app.add_option("--level", o.worker_level, "Loop subdivision steps of --perf-loop's mesh")->capture_default_str();
  app.add_option("--result-file", o.result_file, "(internal)")->group("");
  app.add_option("--perf-loop", o.perf_loop,
                 "Only run the pipeline (paper|default) or the automatic patches (auto) --repeat times on --mesh at --level")
      ->check(CLI::IsMember({"paper", "default", "auto"}));
  app.add_option("--mesh", o.worker_mesh, "Mesh of --perf-loop");
  app.add_option("--repeat", o.repeat, "Pipelines of --perf-loop")->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  if(o.quick) {
    o.sizes = std::min<std::size_t>(o.sizes, 20000);
    o.runs = std::min(o.runs, 3);
    o.queries = std::min<std::size_t>(o.queries, 20000);
  }
#ifndef NDEBUG
  std::cerr << "warning: built without NDEBUG (not a Release build): times are not representative" << std::endl;
#endif
  try {
    if(!o.perf_loop.empty()) return perf_loop(o);
    if(!o.result_file.empty()) {
      const Row row = run_worker(o, o.worker_mesh, o.worker_level);
      write_row(row, o.result_file);
      return 0;
    }
    return run_parent(o);
  } catch(const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 4;
  }
}
