// diffuv benchmark: accuracy of the (region, u, v) correspondence where the
// truth is known.
//
// Mesh A is one of CGAL's closed meshes, cut into disc patches automatically
// (what `diffuv segment` does: diffusion_patches()); mesh B is the same surface tessellated another
// way:
//   fine      isotropic remeshing at 0.7 x A's mean edge length (3 iterations)
//   coarse    the same at 1.6 x
//   shuffled  vertices and faces in a random order (and each face's first corner
//             rotated); labels carried exactly
//   loop      one Loop subdivision step
//   noise     every vertex moved by 5 % of the mean edge length in a random direction
// B's labels come from A's by nearest face (except for `shuffled`), so they
// carry the imperfections the label cleaning has to absorb.
//
// The true image of a vertex of A is its closest point on B (for `shuffled`:
// the vertex itself). The error is the exact geodesic distance on B
// (CGAL::Surface_mesh_shortest_path, on a local piece of B that provably holds
// the shortest path; see `Geodesic_distance`) from the mapped point to the
// true point, over sqrt(area of B). Also measured: the round trip A -> B -> A,
// the seam continuity (a vertex on a patch border mapped from each of its
// charts), and the time of the mapping apart from the two parameterizations.
// Both atlases are built as the `correspond` tool builds them with
// --transfer-labels (build_labelled_atlas_pair()): B's atlas follows A's
// sub-patches and corners (`atlas_to_follow()`) unless --no-follow is given,
// and a region B loses joins its neighbour on both meshes unless --no-join.
//
// Usage: diffuv_correspondence_bench [--meshes cow,man,elephant,hand]
//          [--pairs fine,coarse,shuffled,loop,noise] [--runs 3] [--output DIR]
//          [--distance fmm|graph|exact] [--no-follow] [--no-join] [--sub-patches]
//          [--labels quads|voronoi] [--self-check]
// Writes DIR/table.md, DIR/curves.csv, DIR/correspondence_<mesh>.png and
// DIR/diagnostics.md (where the errors are); prints the table on stdout and
// progress on stderr. Exit code: 0 if every pair meets the targets,
// 1 if one does not (or the self-check fails), 4 on an error.
//
// Files (bench/correspondence/, compiled as one unity file): main.cpp the
// options and the run over meshes and pairs, variants.cpp the meshes B,
// pairs.cpp one pair (atlases, mapping, errors, verdict), diagnostics.cpp
// where the errors are, geodesic_distance.h the local exact geodesics,
// self_check.cpp --self-check, report.cpp the statistics and the table;
// bench/common.h what the benchmarks share.
#include "correspondence/correspondence_bench.h"

#include "correspondence/geodesic_distance.h"
#include "plot_png.h"

#include <diffuv/layout/disc_patches.h>
#include <diffuv/parameterization/diffusion_patches.h>

#include <CGAL/Polygon_mesh_processing/measure.h>

#include <fstream>
#include <iostream>

namespace diffuv_bench {

namespace {

int run(const Options& o)
{
  const auto t_start = Clock::now();
  std::filesystem::create_directories(o.output);
  std::vector<Pair_result> results;
  // r in [0, 0.25], 101 samples
  std::vector<double> radii;
  for(int i = 0; i <= 100; ++i) radii.push_back(0.0025 * i);

  for(const std::string& name : o.meshes) {
    Mesh_case a;
    a.name = read_named_mesh(name, a.mesh);
    a.area = PMP::area(a.mesh);
    a.mean_edge = mean_edge_length(a.mesh);

    // A's labels: automatic disc patches, as `diffuv segment` makes them
    // (--labels quads: the four-sided layout refined until each patch's raw
    // map serves, diffusion_patches()), or the Voronoi patches of diffuv 0.1
    // (--labels voronoi: regions of three to eight runs, like painted ones).
    const auto t0 = Clock::now();
    diffuv::Segmentation<Mesh> seg;
    diffuv::Patching_report report;
    diffuv::Patching_options patching;
    if(o.labels == "voronoi") patching.layout = diffuv::Patch_layout::voronoi;
    if(o.labels == "voronoi")
      diffuv::disc_patches(a.mesh, a.mesh.points(), std::vector<int>{}, seg, patching, &report);
    else
      diffuv::diffusion_patches(a.mesh, a.mesh.points(), std::vector<int>{}, seg, patching, &report);
    a.labels.assign(a.mesh.number_of_faces(), 0);
    for(auto f : a.mesh.faces()) a.labels[f.idx()] = static_cast<int>(seg.face_patch[f.idx()]);
    a.automatic_patches = seg.number_of_patches();
    std::cerr << "[" << a.name << "] " << a.mesh.number_of_vertices() << " vertices, " << a.automatic_patches
              << " automatic patches (" << format("%.0f", ms_since(t0)) << " ms)\n";

    a.atlas = timed_atlas(a.mesh, a.labels, o.atlas, o.runs, a.param_ms);
    a.ring = seam_rings(a.mesh, *a.atlas);
    std::cerr << "[" << a.name << "] param A " << format("%.1f", a.param_ms) << " ms: "
              << a.atlas->segmentation.number_of_patches() << " patches, " << a.atlas->atlas.number_of_charts()
              << " charts, " << a.atlas->cleaning.changed_faces() << " faces relabelled by the cleaning\n";

    Geodesic_distance geodesic_a(a.mesh);
    diffuv_bench::Line_plot plot;
    plot.x_min = 0.;
    plot.x_max = 0.25;
    plot.y_min = 0.;
    plot.y_max = 100.;
    plot.x_step = 0.05;
    plot.y_step = 20.;
    plot.title = a.name + ": vertices with error <= r";
    plot.x_label = "r = geodesic error / sqrt(area)";
    plot.y_label = "% of vertices";
    for(const std::string& pair : o.pairs) {
      results.push_back(run_pair(a, pair, o.atlas, o.runs, o.follow, geodesic_a));
      const Pair_result& r = results.back();
      const Summary e = summarize(r.error);
      std::cerr << "[" << a.name << "/" << pair << "] mean " << format("%.4f", e.mean) << ", p95 "
                << format("%.4f", e.p95) << ", max " << format("%.4f", e.max) << ", "
                << format("%.1f", percent_within(r.error, 0.05)) << " % within 0.05, " << r.unmapped
                << " unmapped: " << r.verdict << "\n";
      diffuv_bench::Plot_series series;
      series.name = pair;
      series.color = diffuv_bench::series_color(plot.series.size());
      for(double x : radii) series.points.emplace_back(x, percent_within(r.error, x));
      plot.series.push_back(std::move(series));
    }
    const std::string png = o.output + "/correspondence_" + a.name + ".png";
    diffuv_bench::write_plot_png(png, plot);
    std::cerr << "[" << a.name << "] wrote " << png << "\n";
  }

  const std::string md = table(results, o);
  std::cout << md;
  {
    std::ofstream f(o.output + "/table.md");
    f << md;
  }
  {
    std::ofstream f(o.output + "/curves.csv");
    f << "r";
    for(const Pair_result& r : results) f << "," << r.mesh << "/" << r.pair;
    f << "\n";
    for(double x : radii) {
      f << format("%.4f", x);
      for(const Pair_result& r : results) f << "," << format("%.3f", percent_within(r.error, x));
      f << "\n";
    }
  }
  {
    std::ofstream f(o.output + "/diagnostics.md");
    f << "# Where the errors come from\n\nChart keys are (label, part, rank). Edges to seam: edges from the vertex to "
         "the nearest vertex of A in two or more charts.\n\n";
    for(const Pair_result& r : results) f << r.diagnostics;
  }
  std::cerr << "wrote " << o.output << "/table.md, curves.csv, diagnostics.md and " << o.meshes.size()
            << " PNG files; total " << format("%.1f", ms_since(t_start) / 1000.) << " s\n";
  for(const Pair_result& r : results)
    if(!r.passed) return 1;
  return 0;
}

} // namespace

} // namespace diffuv_bench

int main(int argc, char** argv)
{
  using namespace diffuv_bench;
  Options o;
  CLI::App app{"diffuv correspondence benchmark: pairs of one surface with different tessellations, where the true "
               "image of a vertex is its closest point"};
  add_meshes_option(app, o.meshes, "Meshes A");
  app.add_option("--pairs", o.pairs, "Meshes B: fine, coarse, shuffled, loop, noise")
      ->delimiter(',')
      ->check(CLI::IsMember({"fine", "coarse", "shuffled", "loop", "noise"}))
      ->capture_default_str();
  add_runs_option(app, o.runs, "Runs to take the median time of");
  add_output_option(app, o.output);
  app.add_option("--distance", o.distance, "Distances of the parameterizations")
      ->check(CLI::IsMember({"fmm", "graph", "exact"}))
      ->capture_default_str();
  app.add_flag("!--no-follow", o.follow,
               "Build B's atlas on its own, without following A's sub-patches and corners (atlas_to_follow())");
  bool repair = false, no_repair = false;
  auto* repair_flag = app.add_flag("--repair", repair, "Repair the folds of each chart (default: the library's default)");
  app.add_flag("--no-repair", no_repair, "Keep the raw diffusion coordinates")->excludes(repair_flag);
  app.add_option("--labels", o.labels, "A's regions: the four-sided layout's patches, or diffuv 0.1's Voronoi patches")
      ->check(CLI::IsMember({"quads", "voronoi"}))
      ->capture_default_str();
  app.add_flag("--sub-patches", o.atlas.sub_patches,
               "Split regions with three or five to nine runs of neighbours into four-sided sectors (split_regions_into_quads())");
  app.add_flag("!--no-join", o.atlas.join,
               "Leave the regions B loses (to its cleaning, its merging or the carrying of labels) unmapped, instead "
               "of joining each to its neighbour on both meshes (build_labelled_atlas_pair())");
  app.add_flag("--self-check", o.self_check,
               "Only check the local exact geodesics against Surface_mesh_shortest_path on the whole of cow.off");
  app.footer("Exit codes: 0 every target met, 1 a target missed (or the self-check failed), 4 error.");
  CLI11_PARSE(app, argc, argv);
  if(repair) o.atlas.repair = 1;
  if(no_repair) o.atlas.repair = 0;
  o.atlas.distance = o.distance == "graph" ? Distance::graph : o.distance == "exact" ? Distance::exact : Distance::fmm;
  return exit_code_of([&] {
    if(o.self_check) return self_check(mesh_path("cow")) ? 0 : 1;
    return run(o);
  });
}
