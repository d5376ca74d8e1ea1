// diffuv benchmark: speed and memory (issue #11). What the files of the
// performance bench share: its options, the row of results of one
// (mesh, size), the mesh with its given patches, the pipeline run, and the
// measurements each file makes. How it measures: main.cpp.
#ifndef DIFFUV_BENCH_PERFORMANCE_BENCH_H
#define DIFFUV_BENCH_PERFORMANCE_BENCH_H

#include "common.h"

#include <diffuv/atlas/Uv_atlas.h>
#include <diffuv/core/four_sides.h>
#include <diffuv/graph/distance_tags.h>
#include <diffuv/graph/heap_tags.h>
#include <diffuv/parameterization/parameterize_patches.h>
#include <diffuv/patches/segmentation.h>

#include <CGAL/boost/graph/Face_filtered_graph.h>

#include <cstdlib>
#include <iostream>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace diffuv_bench {

using Patch = CGAL::Face_filtered_graph<Mesh>;
using Seg = diffuv::Segmentation<Mesh>;
using Sides = diffuv::Four_sides<vertex_descriptor>;
using Atlas = diffuv::Uv_atlas<Mesh>;

/// Progress, on stderr.
inline void progress(const std::string& what) { std::cerr << what << std::endl; }

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
  std::string parts = "abcde";     // which measurements (letters of main.cpp's header comment)
  bool no_fork = false;
  std::string output = "bench-out/performance";
  // worker / perf loop
  std::string worker_mesh;
  int worker_level = 0;
  std::string result_file;
  std::string perf_loop;
  int repeat = 20;
};

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

// report.cpp: the row files between worker and parent, the tables, the CSV file, the plots.
void write_row(const Row& row, const std::string& path);
Row read_row(const std::string& path);
/// The value of `key` printed with `f`, or the text stored ("-" if none).
std::string cell(const Row& r, const std::string& key, const char* f = "%.3g");
std::string tables(const std::vector<Row>& rows, const Options& o);
void write_csv(const std::vector<Row>& rows, const std::string& path);
void write_plots(const std::vector<Row>& rows, const std::vector<std::string>& names, const std::string& dir);

// ---------------------------------------------------------------------------
// The meshes (case.cpp)

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

/// The mesh `name_or_path` after `level` Loop subdivision steps, with the
/// patches of the base mesh carried to it.
Case make_case(const std::string& name_or_path, int level);

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
  // The paper's method (no repair) draws its charts on plain rectangles: the
  // warps of the default pipeline's charts are the atlas's, not the method's.
  diffuv::Chart_drawing_options drawing;
  if(!repair) drawing.pieces = 0;
  const auto results = diffuv::parameterize_patches<DistanceTag, HeapTag>(c.mesh, c.mesh.points(), c.seg, *r.atlas, diffuv::Patch_parameterization_options{diffuv::Repair_options{repair}, nullptr, true, threads, drawing});
  r.ms = ms_since(t0);
  for(const auto& p : results) {
    if(!p.status) ++r.failed;
    r.moved += p.repair.moved_vertices;
    r.whole_patch += p.repair.whole_patch;
  }
  return r;
}

// ---------------------------------------------------------------------------
// The measurements of one (mesh, size), each into `row`; `tag` starts their
// progress lines. `runs`: how many runs each median is of.

/// (a) Dijkstra per heap, the bench-local CSR references, fast marching (dijkstra.cpp).
void measure_dijkstra(const Case& c, int runs, const std::string& tag, Row& row);
/// (c) the atlas and its kd-trees, nearest-vertex queries, point locations (atlas_queries.cpp).
void measure_atlas_queries(const Case& c, const Atlas& atlas, int runs, std::size_t queries, const std::string& tag,
                           Row& row);
/// --profile: the pipeline's stages (stages.cpp).
void measure_stages(const Case& c, int runs, const std::string& tag, Row& row);

/// Everything for one (mesh, level), in this process (worker.cpp).
Row run_worker(const Options& o, const std::string& mesh, int level);
/// --perf-loop: the pipeline or the automatic patches, --repeat times (worker.cpp).
int perf_loop(const Options& o);
/// One child process per (mesh, level), the tables and plots (parent.cpp).
int run_parent(const Options& o);

} // namespace diffuv_bench

#endif // DIFFUV_BENCH_PERFORMANCE_BENCH_H
