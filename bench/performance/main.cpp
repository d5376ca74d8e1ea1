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
//
// Files (bench/performance/, compiled as one unity file): main.cpp the
// options, case.cpp the meshes, worker.cpp one (mesh, size) with (b), (d),
// (e), dijkstra.cpp (a), atlas_queries.cpp (c), stages.cpp --profile,
// parent.cpp the child processes, report.cpp the tables, CSV and plots;
// bench/common.h what the benchmarks share.
#include "performance/performance_bench.h"

#include <algorithm>

int main(int argc, char** argv)
{
  using namespace diffuv_bench;
  Options o;
  CLI::App app{"diffuv performance benchmark (issue #11): Dijkstra per heap, the whole parameterization, atlas "
               "queries, CGAL's fixed-border parameterizers on the same patches, peak memory; CGAL's meshes and "
               "their Loop-subdivided copies"};
  add_meshes_option(app, o.meshes, "Meshes");
  app.add_option("--sizes", o.sizes, "Largest size: each mesh is Loop-subdivided until it has at least this many vertices")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  app.add_option("--max-vertices", o.max_vertices, "No copy above this many vertices (0: no cap)")
      ->capture_default_str();
  app.add_option("--first-level", o.first_level, "Start at this many subdivision steps")->capture_default_str();
  add_runs_option(app, o.runs, "Runs to take the median of");
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
  add_output_option(app, o.output);
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
  return exit_code_of([&] {
    if(!o.perf_loop.empty()) return perf_loop(o);
    if(!o.result_file.empty()) {
      write_row(run_worker(o, o.worker_mesh, o.worker_level), o.result_file);
      return 0;
    }
    return run_parent(o);
  });
}
