// diffuv performance bench: the worker, everything for one (mesh, level) in
// one process: (e) peak memory, (b) the pipelines and the automatic patches,
// (d) CGAL's parameterizers on the same patches; (a), (c) and --profile are
// in files of their own. And --perf-loop, the pipeline alone for perf.
#include "performance/performance_bench.h"

#include "compare/cgal_parameterizers.h"

#include <diffuv/graph/edge_length_map.h>
#include <diffuv/graph/multi_source_dijkstra.h>
#include <diffuv/graph/patch_graph.h>
#include <diffuv/layout/disc_patches.h>

#include <boost/graph/dijkstra_shortest_paths.hpp>

#include <boost/property_map/property_map.hpp>

#include <malloc.h>

#include <array>
#include <cstring>
#include <fstream>

namespace diffuv_bench {

namespace {

// ---------------------------------------------------------------------------
// (e) Memory

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

/// Bytes per vertex, or NaN if the high-water mark could not be reset (`before` < 0).
double per_vertex(long long bytes, long long before, std::size_t V)
{
  return before >= 0 ? double(bytes) / double(V) : std::numeric_limits<double>::quiet_NaN();
}

// ---------------------------------------------------------------------------
// (b) The pipelines, alternating; the automatic patches

/// The floor of the paper's method (issue #20): four plain Dijkstra runs per
/// patch, Boost's `dijkstra_shortest_paths()` (its 4-ary heap with
/// decrease-key) from each side, on the same compressed-row graph the
/// pipeline builds (`Patch_graph`, built before the clock starts), nothing
/// else: no disc check, no sides, no ratios, no chart. Sum over the patches,
/// ms, median of `runs`. `max_difference`: the largest difference between
/// these distances and the library's (`Multi_source_dijkstra`, Fibonacci
/// heap) on the same graphs, which should be 0.
double time_dijkstra_floor(const Case& c, int runs, double& max_difference)
{
  using Graph = diffuv::Patch_graph<Mesh>::Graph;
  using Local = diffuv::Patch_graph<Mesh>::vertex_descriptor;
  const auto lengths = diffuv::edge_length_map(c.mesh, c.mesh.points());
  auto findex = get(boost::face_index, c.mesh);
  std::vector<Graph> graphs;
  std::vector<std::array<std::vector<Local>, 4>> sources;
  diffuv::Patch_graph<Mesh> builder;
  for(std::size_t p = 0; p < c.seg.number_of_patches(); ++p) {
    if(!c.patch_ok[p]) continue;
    builder.build(c.mesh, c.seg.patch_faces[p],
                  [&](face_descriptor f) { return f != Mesh::null_face() && c.seg.face_patch[get(findex, f)] == p; },
                  lengths);
    const auto sides = builder.local_sides(c.mesh, c.sides[p]);
    graphs.push_back(builder.graph());
    sources.push_back({sides.u1, sides.u2, sides.v1, sides.v2});
  }
  std::vector<double> distance, reference;
  auto four_runs = [&](std::size_t k, auto&& after_each) {
    const Graph& g = graphs[k];
    distance.resize(num_vertices(g));
    auto dmap = boost::make_iterator_property_map(distance.begin(), get(boost::vertex_index, g));
    for(const auto& side : sources[k]) {
      boost::dijkstra_shortest_paths(g, side.begin(), side.end(), boost::dummy_property_map(), dmap,
                                     get(&diffuv::Patch_graph<Mesh>::Edge::length, g), get(boost::vertex_index, g),
                                     std::less<double>(), boost::closed_plus<double>(),
                                     std::numeric_limits<double>::infinity(), 0., boost::default_dijkstra_visitor());
      after_each(side);
    }
  };
  max_difference = 0.;
  for(std::size_t k = 0; k < graphs.size(); ++k) {
    diffuv::Multi_source_dijkstra<Graph, diffuv::Fibonacci_heap_tag> library(graphs[k]);
    reference.resize(num_vertices(graphs[k]));
    auto rmap = boost::make_iterator_property_map(reference.begin(), get(boost::vertex_index, graphs[k]));
    four_runs(k, [&](const std::vector<Local>& side) {
      library.run(side, get(&diffuv::Patch_graph<Mesh>::Edge::length, graphs[k]), rmap);
      for(std::size_t i = 0; i < distance.size(); ++i)
        if(distance[i] != reference[i])  // both infinite (a vertex cut off from the side) is equal
          max_difference = (std::max)(max_difference, std::isnan(distance[i] - reference[i])
                                                          ? std::numeric_limits<double>::infinity()
                                                          : std::abs(distance[i] - reference[i]));
    });
  }
  std::vector<double> times;
  for(int r = 0; r < runs; ++r) {
    const auto t0 = Clock::now();
    for(std::size_t k = 0; k < graphs.size(); ++k) four_runs(k, [](const std::vector<Local>&) {});
    times.push_back(ms_since(t0));
  }
  return median(times);
}

void measure_pipelines(const Case& c, int runs, const std::string& tag, Row& row)
{
  const double ElogV = static_cast<double>(c.mesh.number_of_edges()) *
                       std::log2(static_cast<double>(c.mesh.number_of_vertices()));
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
  double difference = 0.;
  const double floor = time_dijkstra_floor(c, runs, difference);
  row.set("floor_ms", floor);
  row.set("floor_maxdiff", difference);
  row.set("paper_over_floor", tp / floor);
  progress(tag + "pipelines: paper " + format("%.2f", tp) + " ms, default " + format("%.2f", td) +
           " ms; floor (4 Boost Dijkstra runs per patch) " + format("%.2f", floor) + " ms" +
           (difference == 0. ? std::string(", the same distances") : ", distances differ by up to " + format("%.3g", difference)));
}

/// The time of the automatic patches (disc_patches() without labels), ms; `patches`: how many.
double time_automatic_patches(const Mesh& m, std::size_t& patches)
{
  Seg seg;
  const auto t0 = Clock::now();
  diffuv::disc_patches(m, m.points(), std::vector<int>{}, seg);
  const double ms = ms_since(t0);
  patches = seg.number_of_patches();
  return ms;
}

// ---------------------------------------------------------------------------
// (d) CGAL on the same patches with the same corners

void measure_cgal(const Case& c, int runs, const std::string& tag, Row& row)
{
  const Mesh& m = c.mesh;
  std::vector<Point_2> uv_store(m.number_of_vertices());
  auto uv_map = boost::make_iterator_property_map(uv_store.begin(), get(boost::vertex_index, m));
  const std::array<diffuv::Cgal_method, 2> methods = {diffuv::Cgal_method::tutte, diffuv::Cgal_method::mean_value};
  std::array<std::vector<double>, 2> times;
  std::array<double, 2> copy{0, 0};
  std::array<std::size_t, 2> failed{0, 0};
  for(int r = 0; r < runs; ++r)
    for(std::size_t k = 0; k < methods.size(); ++k) {
      double sum = 0, copy_sum = 0;
      std::size_t fails = 0;
      for(std::size_t p = 0; p < c.seg.number_of_patches(); ++p) {
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
  progress(tag + "CGAL: tutte " + format("%.1f", tutte) + " ms, mean value " + format("%.1f", mv) + " ms");
}

} // namespace

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
  progress(tag + "mesh ready in " + format("%.1f", c.setup_seconds) + " s: " + std::to_string(P) + " patches (" +
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

  auto part = [&](char x) { return o.parts.find(x) != std::string::npos; };
  row.set("parts", o.parts);

  // (e) memory, and the first (warm-up) run of each pipeline.
  std::unique_ptr<Atlas> atlas; // the default pipeline's atlas, for (c)
  if(part('e')) {
    const long long before = reset_peak();
    Pipeline_run d = run_pipeline<diffuv::Default_distance_tag>(c, true);
    const long long peak = peak_bytes();
    row.set("mem_method", std::string(before >= 0 ? "clear_refs" : "none"));
    row.set("mem_default_peak_Bpv", per_vertex(peak, before, V));
    row.set("mem_default_extra_Bpv", per_vertex(peak - before, before, V));
    row.set("default_failed", d.failed);
    row.set("default_moved", d.moved);
    row.set("default_whole_patch", d.whole_patch);
    atlas = std::move(d.atlas);
  }
  {
    const long long before = reset_peak();
    Pipeline_run g = run_pipeline<diffuv::Graph_distance_tag>(c, false);
    const long long peak = peak_bytes();
    row.set("mem_paper_peak_Bpv", per_vertex(peak, before, V));
    row.set("mem_paper_extra_Bpv", per_vertex(peak - before, before, V));
    row.set("paper_failed", g.failed);
  }

  // (b) the pipelines, and the automatic patches.
  if(part('b')) measure_pipelines(c, runs, tag, row);
  if(part('b') && (o.auto_max_vertices == 0 || V <= o.auto_max_vertices)) {
    std::vector<double> times;
    std::size_t patches = 0;
    const int auto_runs = large ? 1 : runs; // minutes per run on the largest copies
    row.set("auto_runs", auto_runs);
    for(int r = 0; r < auto_runs; ++r) times.push_back(time_automatic_patches(m, patches));
    row.set("auto_ms", median(times));
    row.set("auto_patches", patches);
    progress(tag + "automatic patches: " + format("%.2f", median(times)) + " ms, " + std::to_string(patches) +
             " patches");
  }

  // (a) Dijkstra, whole mesh, from side u1 of the largest patch.
  if(part('a')) measure_dijkstra(c, runs, tag, row);

  // (c) atlas, kd-trees, queries.
  if(part('c') && !atlas) atlas = run_pipeline<diffuv::Default_distance_tag>(c, true).atlas;
  if(part('c')) measure_atlas_queries(c, *atlas, runs, o.queries, tag, row);
  atlas.reset();

  // (d) CGAL on the same patches with the same corners.
  if(part('d') && (o.cgal_max_vertices == 0 || V <= o.cgal_max_vertices)) measure_cgal(c, runs, tag, row);

  // Stages of the pipeline (--profile).
  if(o.profile) measure_stages(c, runs, tag, row);
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
  std::size_t patches = 0;
  for(int r = 0; r < o.repeat; ++r) {
    if(o.perf_loop == "auto") times.push_back(time_automatic_patches(c.mesh, patches));
    else
      times.push_back(o.perf_loop == "paper" ? run_pipeline<diffuv::Graph_distance_tag>(c, false).ms
                                              : run_pipeline<diffuv::Default_distance_tag>(c, true).ms);
  }
  std::cerr << "median " << median(times) << " ms" << std::endl;
  return 0;
}

} // namespace diffuv_bench
