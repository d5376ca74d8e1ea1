// diffuv tool: what `param` and `render` print after a run.
#include "report.h"

#include <diffuv/patches/patch_names.h>

#include <cstdio>
#include <iostream>
#include <string>

namespace diffuv_cli {
namespace {

// Where the patches came from when no labels were given.
std::string patch_source(const diffuv::Patching_report& r, const Patch_cli_options& o)
{
  const std::string automatic =
      o.layout == "voronoi" ? "automatic (" + std::to_string(o.patches > 0 ? o.patches : 12) + " seeds to start)" : "automatic";
  if(r.components <= 1) return r.automatic ? automatic : "the whole disc";
  std::string s = std::to_string(r.components) + " components, " + count_text(r.whole_components, "whole disc");
  if(r.automatic) s += ", the others " + automatic;
  return s;
}

std::string corner_rule(const diffuv::Side_report& r, bool given)
{
  if(given) return "given";
  if(r.chosen) return "layout";
  if(r.equal_arcs) return "arcs";
  std::string s = count_text(r.runs, "run");
  if(r.merged) s += " -" + std::to_string(r.merged);
  if(r.split) s += " +" + std::to_string(r.split);
  if(r.moved) s += " ~" + std::to_string(r.moved);
  return s;
}

void print_row(const std::string& name, const std::string& label, std::size_t vertices, std::size_t faces,
               const std::string& corners, double ms, std::size_t moved, std::size_t flat,
               const diffuv::Distortion_summary& d)
{
  std::printf("%-6s %6s %8zu %8zu %-10s %8.2f %6zu %7zu %5zu %6zu %8zu %9.4f %9.4g %9.4f %9.4g %8.4g %9.4g %9s\n",
              name.c_str(), label.c_str(), vertices, faces, corners.c_str(), ms, moved, d.flipped, d.degenerate, flat,
              d.overlapping_pairs, d.angle_mean, d.angle_max, d.area_mean, d.area_max, d.stretch_l2, d.stretch_linf,
              d.injective() ? "yes" : "no");
}

// The first lines: the mesh, then the corners or the patches.
void print_summary(const Param_run& run, const Param_options& options)
{
  const Input_mesh& in = run.in;
  const Parameterization& result = run.result;
  std::cout << (options.render_only ? "diffuv render " : "diffuv param ") << in.path << ": "
            << count_text(in.report.vertices, "vertex", "vertices") << ", " << count_text(num_faces(in.mesh), "face");
  if(in.report.polygons_triangulated > 0)
    std::cout << " (" << count_text(in.report.polygons_triangulated, "polygon") << " triangulated)";
  if(in.report.degenerate_faces > 0) std::cout << ", " << count_text(in.report.degenerate_faces, "zero-area face");
  if(in.report.isolated_vertices > 0)
    std::cout << ", " << count_text(in.report.isolated_vertices, "isolated vertex", "isolated vertices")
              << " (in no face: no (u,v))";
  std::cout << '\n';
  if(!options.corners.empty()) {
    const auto& c = result.patches.front().sides.corners;
    std::cout << "corners (0,0) (1,0) (1,1) (0,1): vertices " << c[0].idx() << ' ' << c[1].idx() << ' ' << c[2].idx()
              << ' ' << c[3].idx() << " (from " << options.corners << ")\n";
  } else {
    const auto& r = result.patching;
    std::cout << count_text(result.seg.number_of_patches(), "patch", "patches") << ", " << options.distance << " distances: "
              << (!in.label_source.empty() ? in.label_source : patch_source(r, options.patches))
              << "; " << patching_clause(r, options.patches) << "\n";
  }
}

// One row per patch, named as every command names it, then the totals;
// returns the patches' own times, summed.
double print_table(const Param_run& run, const Param_options& options)
{
  const Parameterization& result = run.result;
  const std::vector<std::string> names = diffuv::patch_names(result.seg);
  std::printf("%-6s %6s %8s %8s %-10s %8s %6s %7s %5s %6s %8s %9s %9s %9s %9s %8s %9s %9s\n", "patch", "label",
              "vertices", "faces", "corners", "time_ms", "moved", "flipped", "degen", "flat", "overlaps", "angle_avg", "angle_max", "area_avg",
              "area_max", "L2", "Linf", "injective");

  diffuv::Distortion_summary total;
  double patch_ms = 0;
  std::size_t vertex_entries = 0, moved = 0, flat = 0;
  for(std::size_t p = 0; p < result.patches.size(); ++p) {
    const auto& r = result.patches[p];
    const std::string& label = names[p];
    if(!r.status) {
      std::printf("%-6zu %6s %8s %8zu  failed: %s\n", p, label.c_str(), "-", result.seg.patch_faces[p].size(),
                  r.status.what().c_str());
      continue;
    }
    const auto& chart = result.atlas->chart(r.chart);
    const diffuv::Distortion_summary& d = run.measures[p].summary;
    const std::size_t patch_moved = r.repair.moved_vertices + r.repair.moved_border_vertices;
    print_row(std::to_string(p), label, chart.vertices.size(), chart.faces.size(),
              corner_rule(r.side_report, !options.corners.empty()), r.milliseconds, patch_moved,
              r.repair.flat_triangles, d);
    moved += patch_moved;
    flat += r.repair.flat_triangles;
    vertex_entries += chart.vertices.size();
    total = diffuv::combined(total, d);
    patch_ms += r.milliseconds;
  }
  print_row("total", "", vertex_entries, total.faces, "", run.total_ms, moved, flat, total);
  return patch_ms;
}

} // namespace

void print_param_report(const Param_run& run, const Param_options& options)
{
  print_summary(run, options);
  const double patch_ms = print_table(run, options);
  const Input_mesh& in = run.in;
  if(in.report.degenerate_faces > 0)
    std::cerr << "diffuv: warning: " << in.path << ": "
              << count_text(in.report.degenerate_faces, "face has zero area; its (u,v) triangle",
                            "faces have zero area; their (u,v) triangles")
              << " may be flat (column degen)\n";
  if(run.failed > 0)
    std::cerr << "diffuv: warning: " << run.failed << " of " << count_text(run.result.patches.size(), "patch", "patches")
              << " cannot be parameterized (see the table); their faces have no (u,v)\n";
  std::cout << "time: " << Stage_clock::duration(run.total_ms) << " to make and map the patches (median of "
            << count_text(static_cast<std::size_t>(options.runs), "run") << "); the patches' own times (column time_ms) add up to "
            << Stage_clock::duration(patch_ms) << (options.threads == 1 ? "" : " over all threads") << '\n';
  std::cout << "stages: " << run.stages.summary() << '\n';
  std::cout << "wrote";
  for(const auto& p : run.written) std::cout << ' ' << p;
  std::cout << '\n';
}

} // namespace diffuv_cli
