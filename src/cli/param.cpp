// diffuv tool: `diffuv param` — parameterize a disc mesh and write its uv-map.
#include "commands.h"

#include <diffuv/atlas/Uv_atlas.h>
#include <diffuv/error.h>
#include <diffuv/io/atomic_file.h>
#include <diffuv/io/read_mesh.h>
#include <diffuv/io/selection_file.h>
#include <diffuv/io/write_obj.h>
#include <diffuv/io/write_uv_table.h>
#include <diffuv/metrics/distortion.h>
#include <diffuv/parameterization/parameterize_disc.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace diffuv_cli {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using vertex_descriptor = Mesh::Vertex_index;

struct Param_options {
  std::string mesh;
  std::string corners;
  std::string output = "diffuv-out";
  int runs = 1;
};

// CGAL's data set extracted by the build, or $DIFFUV_DATA_DIR.
std::string default_mesh()
{
  const char* env = std::getenv("DIFFUV_DATA_DIR");
  const std::string dir = env ? env : DIFFUV_DEFAULT_DATA_DIR;
  return dir + "/meshes/mushroom.off";
}

// Statuses about corners are the corner file's fault when there is one.
bool is_corner_problem(diffuv::Status_code code)
{
  switch(code) {
    case diffuv::Status_code::corner_count:
    case diffuv::Status_code::corner_out_of_range:
    case diffuv::Status_code::corner_not_on_border:
    case diffuv::Status_code::corner_duplicated:
      return true;
    default:
      return false;
  }
}

void run_param(const Param_options& options)
{
  const std::string mesh_path = options.mesh.empty() ? default_mesh() : options.mesh;
  Mesh mesh;
  const diffuv::Mesh_read_report report = diffuv::read_triangle_mesh(mesh_path, mesh);

  std::vector<vertex_descriptor> corners;
  if(!options.corners.empty())
    corners = diffuv::selection_vertices(mesh, diffuv::read_selection_file(options.corners), options.corners);

  // Everything is checked and computed before anything is written.
  // --runs repeats the whole parameterization (disc check, sides, four
  // Dijkstra runs, atlas with kd-tree) and reports the median time.
  std::unique_ptr<diffuv::Uv_atlas<Mesh>> result;
  diffuv::Four_sides<vertex_descriptor> sides;
  diffuv::Status status;
  std::vector<double> times;
  for(int run = 0; run < options.runs && status.ok(); ++run) {
    auto atlas = std::make_unique<diffuv::Uv_atlas<Mesh>>(mesh);
    const auto start = std::chrono::steady_clock::now();
    status = diffuv::parameterize_disc(mesh, corners, *atlas, &sides);
    times.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    result = std::move(atlas);
  }
  std::sort(times.begin(), times.end());
  const double ms = times[times.size() / 2];
  if(!status) {
    if(!options.corners.empty() && is_corner_problem(status.code)) {
      std::string what = status.what();
      if(status.code == diffuv::Status_code::corner_not_on_border || status.code == diffuv::Status_code::corner_duplicated) {
        // Name the vertices, not only their positions in the file.
        what += ": vertices";
        for(auto c : corners) what += " " + std::to_string(c.idx());
      }
      throw diffuv::Input_error(options.corners, 1, what);
    }
    throw diffuv::Input_error(mesh_path, 0, status.what());
  }

  const diffuv::Uv_atlas<Mesh>& atlas = *result;
  const auto& chart = atlas.chart(0);
  const diffuv::Distortion_summary d =
      diffuv::measure_distortion(mesh, chart.faces, mesh.points(), atlas.chart_uv_map(0));

  const std::string stem = std::filesystem::path(mesh_path).stem().string();
  const std::string obj_path = (std::filesystem::path(options.output) / (stem + ".obj")).string();
  const std::string csv_path = (std::filesystem::path(options.output) / (stem + ".uv.csv")).string();
  diffuv::ensure_output_directory(options.output);
  diffuv::write_obj(obj_path, mesh, mesh.points(), atlas.corner_uv_map());
  diffuv::write_uv_table(csv_path, atlas);

  std::cout << "diffuv param " << mesh_path << ": " << report.vertices << " vertices, " << num_faces(mesh) << " faces";
  if(report.polygons_triangulated > 0) std::cout << " (" << report.polygons_triangulated << " polygons triangulated)";
  std::cout << "\ncorners (0,0) (1,0) (1,1) (0,1): vertices " << sides.corners[0].idx() << ' ' << sides.corners[1].idx()
            << ' ' << sides.corners[2].idx() << ' ' << sides.corners[3].idx()
            << (options.corners.empty() ? " (automatic: equal arcs)" : " (from " + options.corners + ")") << '\n';
  std::printf("%-6s %8s %8s %8s %7s %5s %8s %9s %9s %9s %9s %8s %9s %9s\n", "patch", "vertices", "faces",
              "time_ms", "flipped", "degen", "overlaps", "angle_avg", "angle_max", "area_avg", "area_max", "L2",
              "Linf", "injective");
  auto row = [&](const char* name) {
    std::printf("%-6s %8zu %8zu %8.2f %7zu %5zu %8zu %9.4f %9.4g %9.4f %9.4g %8.4g %9.4g %9s\n", name,
                chart.vertices.size(), chart.faces.size(), ms, d.flipped, d.degenerate, d.overlapping_pairs,
                d.angle_mean, d.angle_max, d.area_mean, d.area_max, d.stretch_l2, d.stretch_linf,
                d.injective() ? "yes" : "no");
  };
  row("0");
  row("total");
  std::cout << "wrote " << obj_path << " and " << csv_path << '\n';
}

} // namespace

void add_param_command(CLI::App& app)
{
  auto options = std::make_shared<Param_options>();
  CLI::App* cmd = app.add_subcommand("param", "Parameterize a disc mesh onto the unit square; write OBJ (with vt) and a uv table");
  cmd->add_option("mesh", options->mesh,
                  "Triangle mesh (OFF, OBJ, PLY, STL), a topological disc. Default: CGAL's mushroom.off");
  cmd->add_option("--corners", options->corners,
                  "CGAL *.selection.txt: four boundary vertex indices on its first line. The first goes to (0,0), "
                  "the others follow counter-clockwise along the boundary to (1,0), (1,1), (0,1). "
                  "Default: automatic (the sharpest boundary vertex, then equal arc lengths)");
  cmd->add_option("-o,--output", options->output, "Output folder (created if needed)")->capture_default_str();
  cmd->add_option("--runs", options->runs, "Run the parameterization N times and report the median time")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  cmd->footer("Writes OUTPUT/<mesh>.obj (v in input order, vt per corner) and OUTPUT/<mesh>.uv.csv "
              "(vertex,patch,u,v).\nExit codes: 0 ok, 1 bad input, 2 bad command line, 3 cannot write.");
  cmd->callback([options]() { run_param(*options); });
}

} // namespace diffuv_cli
