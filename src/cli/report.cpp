// diffuv tool: what `param` and `render` print after a run.
#include "report.h"
#include "table.h"

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

// The columns of the table: what, how wide at least, which side.
Table patch_table()
{
  return Table({{"patch", 6, Table::left},      {"label", 6, Table::right},     {"vertices", 8, Table::right},
                {"faces", 8, Table::right},     {"corners", 10, Table::left},   {"time_ms", 8, Table::right},
                {"moved", 6, Table::right},     {"flipped", 7, Table::right},   {"degen", 5, Table::right},
                {"flat", 6, Table::right},      {"overlaps", 8, Table::right},  {"angle_avg", 9, Table::right},
                {"angle_max", 9, Table::right}, {"area_avg", 9, Table::right},  {"area_max", 9, Table::right},
                {"L2", 8, Table::right},        {"Linf", 9, Table::right},      {"injective", 9, Table::right}});
}

// `d` is empty without measures (--no-measure): its columns show '-'.
void add_row(Table& table, const std::string& patch, const std::string& name, std::size_t vertices, std::size_t faces,
             const std::string& corners, double ms, std::size_t moved, std::size_t flat,
             const diffuv::Distortion_summary& d, bool measured)
{
  const auto m = [measured](const std::string& text) { return measured ? text : std::string("-"); };
  table.add_row({patch, name, std::to_string(vertices), std::to_string(faces), corners, formatted("%.2f", ms),
                 std::to_string(moved), m(std::to_string(d.flipped)), m(std::to_string(d.degenerate)),
                 std::to_string(flat), m(std::to_string(d.overlapping_pairs)), m(formatted("%.4f", d.angle_mean)),
                 m(formatted("%.4g", d.angle_max)), m(formatted("%.4f", d.area_mean)), m(formatted("%.4g", d.area_max)),
                 m(formatted("%.4g", d.stretch_l2)), m(formatted("%.4g", d.stretch_linf)),
                 m(d.injective() ? "yes" : "no")});
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
  // Points merged on reading are told on the repaired line: these are the file's own.
  const std::size_t isolated = in.report.isolated_vertices - in.report.repair.points_merged;
  if(isolated > 0)
    std::cout << ", " << count_text(isolated, "isolated vertex", "isolated vertices") << " (in no face: no (u,v))";
  std::cout << '\n';
  if(const std::string repaired = repair_line(in); !repaired.empty()) std::cout << repaired << '\n';
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
  Table table = patch_table();
  diffuv::Distortion_summary total;
  double patch_ms = 0;
  std::size_t vertex_entries = 0, moved = 0, flat = 0;
  for(std::size_t p = 0; p < result.patches.size(); ++p) {
    const auto& r = result.patches[p];
    if(!r.status) {
      table.add_row({std::to_string(p), names[p], "-", std::to_string(result.seg.patch_faces[p].size())},
                    "  failed: " + r.status.what());
      continue;
    }
    const auto& chart = result.atlas->chart(r.chart);
    const diffuv::Distortion_summary& d = run.measures[p].summary;
    const std::size_t patch_moved = r.repair.moved_vertices + r.repair.moved_border_vertices;
    add_row(table, std::to_string(p), names[p], chart.vertices.size(), chart.faces.size(),
            corner_rule(r.side_report, !options.corners.empty()), r.milliseconds, patch_moved,
            r.repair.flat_triangles, d, run.measured);
    moved += patch_moved;
    flat += r.repair.flat_triangles;
    vertex_entries += chart.vertices.size();
    total = diffuv::combined(total, d);
    patch_ms += r.milliseconds;
  }
  std::size_t faces = 0;
  for(const auto& r : result.patches)
    if(r.status) faces += result.atlas->chart(r.chart).faces.size();
  add_row(table, "total", "", vertex_entries, run.measured ? total.faces : faces, "", run.total_ms, moved, flat, total,
          run.measured);
  std::cout << table.text();
  return patch_ms;
}

} // namespace

void print_param_warnings(const Param_run& run)
{
  warn_of_zero_area_faces(run.in, " (column degen)");
  if(run.failed > 0)
    std::cerr << "diffuv: warning: " << run.failed << " of " << count_text(run.result.patches.size(), "patch", "patches")
              << " cannot be parameterized (see the table); their faces have no (u,v)\n";
}

void print_param_report(const Param_run& run, const Param_options& options)
{
  print_summary(run, options);
  const double patch_ms = print_table(run, options);
  print_param_warnings(run);
  std::cout << "time: " << Stage_clock::duration(run.total_ms) << " to make and map the patches (median of "
            << count_text(static_cast<std::size_t>(options.runs), "run") << "); the patches' own times (column time_ms) add up to "
            << Stage_clock::duration(patch_ms) << (options.threads == 1 ? "" : " over all threads") << '\n';
  if(!run.atlas_line.empty()) std::cout << run.atlas_line << '\n';
  std::cout << "stages: " << run.stages.summary() << '\n';
  std::cout << wrote_line(run.written) << '\n';
}

} // namespace diffuv_cli
