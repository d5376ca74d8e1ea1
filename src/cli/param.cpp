// diffuv tool: `diffuv param` — parameterize a mesh patch by patch and write its uv-map.
#include "commands.h"
#include "inputs.h"

#include <diffuv/atlas/Uv_atlas.h>
#include <diffuv/io/atomic_file.h>
#include <diffuv/io/selection_file.h>
#include <diffuv/output/write_obj.h>
#include <diffuv/output/write_svg.h>
#include <diffuv/render/texture.h>
#include <diffuv/output/write_uv_table.h>
#include <diffuv/metrics/distortion.h>
#include <diffuv/parameterization/parameterize_disc.h>
#include <diffuv/parameterization/parameterize_patches.h>
#include <diffuv/render/render_mesh.h>


#include <algorithm>
#include <cmath>
#include <limits>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>
#include <thread>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace diffuv_cli {
namespace {

using vertex_descriptor = Mesh::Vertex_index;
using Atlas = diffuv::Uv_atlas<Mesh>;

struct Param_options {
  std::string mesh;
  std::string corners;
  std::string output = "diffuv-out";
  int runs = 1;
  std::string distance = "fmm";
  bool no_repair = false;
  std::string view = "iso";
  double azimuth = std::numeric_limits<double>::quiet_NaN(); // set: overrides --view
  double elevation = 20;
  std::string size = "800x600";
  int isolines = 10;
  bool svg = false;
  bool unit_squares = false; // write each chart on the unit square, not on its own rectangle
  std::string color = "patches";
  bool render_only = false; // diffuv render: the picture only
  std::size_t threads = 0;   // 0: every core (with oneTBB)
  Patch_cli_options patches;
};

// --size WxH
std::pair<int, int> parse_size(const std::string& s)
{
  const auto x = s.find('x');
  int w = 0, h = 0;
  try {
    if(x != std::string::npos) {
      w = std::stoi(s.substr(0, x));
      h = std::stoi(s.substr(x + 1));
    }
  } catch(const std::exception&) {
  }
  if(w < 16 || h < 16 || w > 8192 || h > 8192)
    throw CLI::ValidationError("--size", "expects WxH with 16 <= W, H <= 8192, e.g. 800x600, not " + s);
  return {w, h};
}

diffuv::View parse_view(const std::string& s)
{
  if(s == "front") return diffuv::View::front;
  if(s == "back") return diffuv::View::back;
  if(s == "left") return diffuv::View::left;
  if(s == "right") return diffuv::View::right;
  if(s == "top") return diffuv::View::top;
  return diffuv::View::iso;
}

// One parameterization of the whole mesh: its patches and its atlas.
struct Parameterization {
  std::unique_ptr<Atlas> atlas;
  diffuv::Segmentation<Mesh> seg;
  diffuv::Patching_report patching;
  std::vector<diffuv::Patch_result<Mesh>> patches;
  double milliseconds = 0;       // patches + map
  double patches_ms = 0;         // making the patches
};

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

// A disc mesh with four given corners: one chart.
Parameterization parameterize_with_corners(const Input_mesh& in, const std::vector<vertex_descriptor>& corners,
                                           const std::string& corner_file, const std::string& distance,
                                           const diffuv::Repair_options& repair)
{
  Parameterization result;
  result.atlas = std::make_unique<Atlas>(in.mesh);
  diffuv::Patch_result<Mesh> patch;
  const auto start = std::chrono::steady_clock::now();
  diffuv::Disc_parameterization_report<Mesh> report;
  patch.status = with_distance(distance, [&](auto tag) {
    return diffuv::parameterize_disc<decltype(tag)>(in.mesh, in.mesh.points(), corners, *result.atlas,
                                                    diffuv::Disc_parameterization_options{repair}, &report);
  });
  patch.sides = std::move(report.sides);
  patch.repair = report.repair;
  result.milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  if(!patch.status) {
    if(is_corner_problem(patch.status.code)) {
      std::string what = patch.status.what();
      if(patch.status.code == diffuv::Status_code::corner_not_on_border ||
         patch.status.code == diffuv::Status_code::corner_duplicated) {
        what += ": vertices"; // name the vertices, not only their places in the list
        for(auto c : corners) what += " " + std::to_string(c.idx());
      }
      throw diffuv::Input_error(corner_file, 1, what);
    }
    throw diffuv::Input_error(in.path, 0, patch.status.what());
  }
  patch.chart = 0;
  patch.milliseconds = result.milliseconds;
  result.seg.face_patch.assign(num_faces(in.mesh), 0);
  result.seg.patch_label = {0};
  result.seg.patch_part = {0};
  result.seg.patch_faces = {std::vector<Mesh::Face_index>(faces(in.mesh).begin(), faces(in.mesh).end())};
  result.patches.push_back(patch);
  return result;
}

// Any mesh: disc patches (from labels, or automatic), each mapped on its own.
Parameterization parameterize_by_patches(const Input_mesh& in, const Patch_cli_options& options,
                                         const std::string& distance, const diffuv::Repair_options& repair,
                                         std::size_t threads)
{
  Parameterization result;
  result.atlas = std::make_unique<Atlas>(in.mesh);
  const auto start = std::chrono::steady_clock::now();
  result.seg = make_patches(in, options, result.patching);
  result.patches_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  result.patches = with_distance(distance, [&](auto tag) {
    return diffuv::parameterize_patches<decltype(tag)>(in.mesh, in.mesh.points(), result.seg, *result.atlas,
                                                       diffuv::Patch_parameterization_options{repair, nullptr, true, threads});
  });
  result.milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return result;
}

// Where the patches came from when no labels were given.
std::string patch_source(const diffuv::Patching_report& r, const Patch_cli_options& o)
{
  const std::string automatic =
      o.layout == "voronoi" ? "automatic (" + std::to_string(o.patches > 0 ? o.patches : 12) + " seeds to start)" : "automatic";
  if(r.components <= 1) return r.automatic ? automatic : "the whole disc";
  std::string s = std::to_string(r.components) + " components, " + std::to_string(r.whole_components) +
                  (r.whole_components == 1 ? " a whole disc" : " whole discs");
  if(r.automatic) s += ", the others " + automatic;
  return s;
}

std::string corner_rule(const diffuv::Side_report& r, bool given)
{
  if(given) return "given";
  if(r.chosen) return "layout";
  if(r.equal_arcs) return "arcs";
  std::string s = std::to_string(r.runs) + " runs";
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

// The distortion of one patch's chart, face by face and in summary: measured
// once, for the table and for the heat map.
struct Chart_measure {
  diffuv::Distortion_summary summary;
  std::vector<diffuv::Triangle_distortion> per_face; // one per face of the chart, in chart order
};

// #P entries; a patch without a chart gets an empty measure.
std::vector<Chart_measure> measure_charts(const Input_mesh& in, const Parameterization& result, bool unit_squares)
{
  std::vector<Chart_measure> measures(result.patches.size());
  for(std::size_t p = 0; p < result.patches.size(); ++p) {
    const auto& r = result.patches[p];
    if(!r.status) continue;
    const auto& chart = result.atlas->chart(r.chart);
    Chart_measure& m = measures[p];
    // As the OBJ carries it: on the chart's rectangle, or on the unit square.
    if(unit_squares)
      m.summary = diffuv::measure_distortion(in.mesh, in.mesh.points(), chart.faces,
                                             result.atlas->chart_uv_map(r.chart), &m.per_face);
    else
      m.summary = diffuv::measure_distortion(in.mesh, in.mesh.points(), chart.faces,
                                             result.atlas->chart_texture_map(r.chart), &m.per_face);
  }
  return measures;
}

// The picture: the mesh with u, v isolines, faces coloured by patch or by a
// distortion measure (a heat map on a log scale, flipped faces in magenta,
// faces in no chart grey, and a colour bar).
diffuv::Image picture(const Input_mesh& in, const Parameterization& result, const std::vector<Chart_measure>& measures,
                      const Param_options& options)
{
  diffuv::Render_options look;
  std::tie(look.width, look.height) = parse_size(options.size);
  look.view = parse_view(options.view);
  if(!std::isnan(options.azimuth)) {
    look.use_angles = true;
    look.azimuth = options.azimuth;
    look.elevation = options.elevation;
  }
  look.isolines = options.isolines;
  const auto& atlas = *result.atlas;
  if(options.color == "patches")
    return diffuv::render_mesh(
        in.mesh, in.mesh.points(),
        [&](Mesh::Face_index f) { return diffuv::patch_color(result.seg.face_patch[f.idx()]); },
        atlas.corner_uv_map(), look);

  // Per-face distortion, chart by chart.
  std::vector<double> value(num_faces(in.mesh), std::numeric_limits<double>::quiet_NaN());
  std::vector<bool> flipped(num_faces(in.mesh), false);
  double largest = 1.;
  for(std::size_t p = 0; p < result.patches.size(); ++p) {
    if(!result.patches[p].status) continue;
    const auto& chart = atlas.chart(result.patches[p].chart);
    for(std::size_t k = 0; k < chart.faces.size(); ++k) {
      const auto& d = measures[p].per_face[k];
      const double v = options.color == "angle" ? d.angle : d.area;
      value[chart.faces[k].idx()] = v;
      flipped[chart.faces[k].idx()] = d.flipped;
      if(std::isfinite(v)) largest = std::max(largest, v);
    }
  }
  const double top = std::min(largest, 10.); // 1 .. 10 on a log scale; more is clamped
  diffuv::Image image = diffuv::render_mesh(
      in.mesh, in.mesh.points(),
      [&](Mesh::Face_index f) {
        const double v = value[f.idx()];
        if(flipped[f.idx()]) return diffuv::Color{230, 0, 200};
        if(std::isnan(v)) return diffuv::Color{150, 150, 150};
        return diffuv::heat_color(top > 1. ? std::log(std::max(v, 1.)) / std::log(top) : 0.);
      },
      atlas.corner_uv_map(), look);
  diffuv::draw_color_bar(image, 1., top, options.color + " distortion (log)");
  return image;
}

// How long each stage of a run took: "stages: read 120 ms, ..." at the end,
// and, for meshes over a million vertices, a line on stderr as each stage
// ends, so that a long run shows where it is.
struct Stage_clock {
  bool large = false;
  std::vector<std::pair<std::string, double>> stages;
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();

  void restart() { start = std::chrono::steady_clock::now(); }
  // 950 ms, 9.70 s: milliseconds below a second, else seconds.
  static std::string duration(double ms)
  {
    char text[32];
    if(ms < 1000.) std::snprintf(text, sizeof text, "%.3g ms", ms);
    else std::snprintf(text, sizeof text, "%.2f s", ms / 1000.);
    return text;
  }
  void add(const std::string& name, double ms, const std::string& detail = {})
  {
    stages.emplace_back(name, ms);
    if(large)
      std::cerr << "diffuv: " << name << " done in " << duration(ms) << (detail.empty() ? "" : " (" + detail + ")")
                << std::endl;
  }
  void done(const std::string& name, const std::string& detail = {})
  {
    add(name, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count(), detail);
    restart();
  }
  std::string summary() const
  {
    std::string s;
    for(std::size_t i = 0; i < stages.size(); ++i)
      s += (i ? ", " : "") + stages[i].first + ' ' + duration(stages[i].second);
    return s;
  }
};

void run_param(const Param_options& options)
{
  parse_size(options.size); // a bad --size is a usage error before any work
  if(!options.corners.empty() && (!options.patches.labels.empty()))
    throw CLI::ValidationError("--corners", "applies to a disc mesh without --labels");
  const std::string mesh_path = options.mesh.empty() ? default_mesh("cow.off") : options.mesh;
  Stage_clock stages;
  // A file this large takes seconds to read: say so before, not only after.
  std::error_code size_error;
  const auto file_size = std::filesystem::file_size(mesh_path, size_error);
  if(!size_error && file_size > 50'000'000)
    std::cerr << "diffuv: reading " << mesh_path << " (" << file_size / 1'000'000 << " MB)" << std::endl;
  const Input_mesh in = read_input(mesh_path, options.patches);
  stages.large = in.report.vertices > 1000000;
  stages.done("read", std::to_string(in.report.vertices) + " vertices");

  std::vector<vertex_descriptor> corners;
  if(!options.corners.empty())
    corners = diffuv::selection_vertices(in.mesh, diffuv::read_selection_file(options.corners), options.corners);

  // --runs repeats everything after reading and reports the median time.
  Parameterization result;
  std::vector<double> times;
  diffuv::Repair_options repair;
  repair.enabled = !options.no_repair;
  // More threads than cores gain nothing, and oneTBB would warn about them.
  const std::size_t cores = (std::max)(1u, std::thread::hardware_concurrency());
  const std::size_t threads = options.threads == 0 ? 0 : (std::min)(options.threads, cores);
  Patch_cli_options patching = options.patches;
  patching.threads = threads;
  for(int run = 0; run < options.runs; ++run) {
    result = options.corners.empty()
                 ? parameterize_by_patches(in, patching, options.distance, repair, threads)
                 : parameterize_with_corners(in, corners, options.corners, options.distance, repair);
    times.push_back(result.milliseconds);
  }
  stages.add("patches", result.patches_ms,
             std::to_string(result.seg.number_of_patches()) + (result.seg.number_of_patches() == 1 ? " patch" : " patches"));
  stages.add("map", result.milliseconds - result.patches_ms,
             options.runs > 1 ? "last of " + std::to_string(options.runs) + " runs" : std::string());
  std::sort(times.begin(), times.end());
  const double total_ms = times[times.size() / 2];
  const Atlas& atlas = *result.atlas;

  // A patch that could not be mapped: an error if every one failed or with
  // --strict (then nothing is written), else a warning and the others' results.
  std::size_t failed = 0;
  std::string first_failure;
  for(std::size_t p = 0; p < result.patches.size(); ++p)
    if(!result.patches[p].status && failed++ == 0) first_failure = result.patches[p].status.what();
  if(failed > 0 && (failed == result.patches.size() || options.patches.strict))
    throw diffuv::Input_error(in.labels_path.empty() ? in.path : in.labels_path, 0,
                              std::to_string(failed) + " of " + std::to_string(result.patches.size()) +
                                  " patches cannot be parameterized; the first: " + first_failure);

  // Everything is computed before anything is written: all files or none.
  const std::vector<std::string> inputs = {in.path, options.corners, options.patches.labels};
  stages.restart();
  const std::vector<Chart_measure> measures = measure_charts(in, result, options.unit_squares); // for the picture and the table
  stages.done("measure");
  diffuv::Output_folder out(options.output, inputs);
  if(!options.render_only) {
    // A textured OBJ: any viewer shows the map as a checkerboard on the mesh.
    const std::string texture = output_name(in.path, ".checker.png");
    if(options.unit_squares)
      diffuv::write_obj(out.open(output_name(in.path, ".obj")), in.mesh, in.mesh.points(), atlas.corner_uv_map(),
                        output_name(in.path, ".mtl"), "diffuv_checker");
    else
      diffuv::write_obj(out.open(output_name(in.path, ".obj")), in.mesh, in.mesh.points(), atlas.corner_texture_map(),
                        output_name(in.path, ".mtl"), "diffuv_checker");
    diffuv::write_mtl(out.open(output_name(in.path, ".mtl")), "diffuv_checker", texture);
    diffuv::write_png(out.open(texture), 512, 512, diffuv::checker_texture(512, 8));
    if(options.svg)
      for(std::size_t p = 0; p < result.patches.size(); ++p)
        if(result.patches[p].status)
          diffuv::write_uv_layout_svg(out.open(output_name(in.path, ".patch" + std::to_string(p) + ".svg")), atlas,
                                      result.patches[p].chart, &result.patches[p].sides);
    diffuv::write_uv_table(out.open(output_name(in.path, ".uv.csv")), atlas);
    write_polygon_patches(out.open(output_name(in.path, ".patches.txt")), in, result.seg);
  }
  diffuv::write_png(out.open(output_name(in.path, ".png")), picture(in, result, measures, options),
                    output_name(in.path, ".png"));
  out.commit();
  stages.done("write");

  // The summary.
  std::cout << (options.render_only ? "diffuv render " : "diffuv param ") << in.path << ": " << in.report.vertices << " vertices, " << num_faces(in.mesh) << " faces";
  if(in.report.polygons_triangulated > 0) std::cout << " (" << in.report.polygons_triangulated << " polygons triangulated)";
  if(in.report.degenerate_faces > 0) std::cout << ", " << in.report.degenerate_faces << " zero-area faces";
  if(in.report.isolated_vertices > 0)
    std::cout << ", " << in.report.isolated_vertices << " isolated vertices (in no face: no (u,v))";
  std::cout << '\n';
  if(!options.corners.empty()) {
    const auto& c = result.patches.front().sides.corners;
    std::cout << "corners (0,0) (1,0) (1,1) (0,1): vertices " << c[0].idx() << ' ' << c[1].idx() << ' ' << c[2].idx()
              << ' ' << c[3].idx() << " (from " << options.corners << ")\n";
  } else {
    const auto& r = result.patching;
    std::cout << result.seg.number_of_patches() << (result.seg.number_of_patches() == 1 ? " patch, " : " patches, ")
              << options.distance << " distances: "
              << (!in.label_source.empty() ? in.label_source : patch_source(r, options.patches))
              << "; " << patching_clause(r, options.patches) << "\n";
  }
  std::printf("%-6s %6s %8s %8s %-10s %8s %6s %7s %5s %6s %8s %9s %9s %9s %9s %8s %9s %9s\n", "patch", "label",
              "vertices", "faces", "corners", "time_ms", "moved", "flipped", "degen", "flat", "overlaps", "angle_avg", "angle_max", "area_avg",
              "area_max", "L2", "Linf", "injective");

  diffuv::Distortion_summary total;
  double patch_ms = 0;
  std::size_t vertex_entries = 0, moved = 0, flat = 0;
  for(std::size_t p = 0; p < result.patches.size(); ++p) {
    const auto& r = result.patches[p];
    const std::string label = std::to_string(result.seg.patch_label[p]) +
                              (result.seg.patch_part[p] ? "." + std::to_string(result.seg.patch_part[p]) : "");
    if(!r.status) {
      std::printf("%-6zu %6s %8s %8zu  failed: %s\n", p, label.c_str(), "-", result.seg.patch_faces[p].size(),
                  r.status.what().c_str());
      continue;
    }
    const auto& chart = atlas.chart(r.chart);
    const diffuv::Distortion_summary& d = measures[p].summary;
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
  print_row("total", "", vertex_entries, total.faces, "", total_ms, moved, flat, total);
  if(in.report.degenerate_faces > 0)
    std::cerr << "diffuv: warning: " << in.path << ": " << in.report.degenerate_faces
              << " faces have zero area; their (u,v) triangles may be flat (column degen)\n";
  if(failed > 0)
    std::cerr << "diffuv: warning: " << failed << " of " << result.patches.size()
              << " patches cannot be parameterized (see the table); their faces have no (u,v)\n";
  std::cout << "time: " << Stage_clock::duration(total_ms) << " to make and map the patches (median of "
            << options.runs << (options.runs == 1 ? " run" : " runs") << "); the patches' own times (column time_ms) add up to "
            << Stage_clock::duration(patch_ms) << (options.threads == 1 ? "" : " over all threads") << '\n';
  std::cout << "stages: " << stages.summary() << '\n';
  std::cout << "wrote";
  for(const auto& p : out.paths()) std::cout << ' ' << p;
  std::cout << '\n';
}

} // namespace

namespace {

// The options `param` and `render` share: what is parameterized, and how it is drawn.
void add_common_options(CLI::App* cmd, Param_options& o)
{
  cmd->add_option("--threads", o.threads,
                  "Threads mapping the patches: 0 = every core, 1 = one after the other (the results are the same; "
                  "more threads than cores are not used)")
      ->check(CLI::Range(std::size_t(0), std::size_t(1024)))
      ->capture_default_str();
  cmd->add_option("mesh", o.mesh,
                  "Triangle mesh (OFF, OBJ, PLY, STL). A disc is one patch; any other mesh is cut into disc patches. "
                  "Default: CGAL's cow.off");
  cmd->add_option("--corners", o.corners,
                  "Disc mesh only: CGAL *.selection.txt with four boundary vertex indices on its first line. The first "
                  "goes to (0,0), the others follow counter-clockwise along the boundary to (1,0), (1,1), (0,1). "
                  "Default: automatic (the sharpest boundary vertex, then equal arc lengths)");
  add_patch_options(cmd, o.patches);
  cmd->add_option("-o,--output", o.output, "Output folder (created if needed)")
      ->check(output_folder_check())
      ->capture_default_str();
  cmd->add_option("--distance", o.distance,
                  "Distance diffused from each side: fmm (fast marching through triangles), graph (edge paths, the "
                  "paper's) or exact (exact geodesics, CGAL's Surface_mesh_shortest_path; slow)")
      ->check(CLI::IsMember({"graph", "fmm", "exact"}))
      ->capture_default_str();
  cmd->add_flag("--no-repair", o.no_repair,
                "Keep the raw diffusion coordinates, folds included (the paper's method). By default every fold is "
                "repaired: the folded region is re-solved as a convex-combination map (see doc/quality.md)");
  cmd->add_option("--view", o.view, "View of the picture: front, back, left, right, top or iso")
      ->check(CLI::IsMember({"front", "back", "left", "right", "top", "iso"}))
      ->capture_default_str();
  const auto finite = CLI::Validator(
      [](std::string& text) {
        try {
          return std::isfinite(std::stod(text)) ? std::string() : std::string("must be a finite number");
        } catch(const std::exception&) {
          return std::string("must be a number");
        }
      },
      "DEGREES");
  CLI::Option* azimuth =
      cmd->add_option("--azimuth", o.azimuth,
                      "Camera azimuth in degrees around the y axis (0: looking along -z, as front); replaces --view")
          ->check(finite)
          ->check(CLI::Range(-360., 360.));
  cmd->add_option("--elevation", o.elevation, "Camera elevation in degrees (needs --azimuth)")
      ->check(finite)
      ->check(CLI::Range(-90., 90.))
      ->needs(azimuth)
      ->capture_default_str();
  cmd->add_option("--size", o.size, "Size of the picture, WxH pixels")->capture_default_str();
  cmd->add_option("--isolines", o.isolines, "u and v isolines every 1/N in the picture (0: none)")
      ->check(CLI::Range(0, 1000))
      ->capture_default_str();
  cmd->add_option("--color", o.color,
                  "Face colours of the picture: patches, angle (sigma_max/sigma_min) or area distortion, as a heat "
                  "map from 1 to 10 (log scale; flipped faces magenta)")
      ->check(CLI::IsMember({"patches", "angle", "area"}))
      ->capture_default_str();
}

const char* const exit_codes = "Exit codes: 0 ok, 1 bad input, 2 bad command line, 3 cannot write, 4 internal error.";

} // namespace

void add_param_command(CLI::App& app)
{
  auto options = std::make_shared<Param_options>();
  CLI::App* cmd = app.add_subcommand(
      "param", "Parameterize a mesh patch by patch, each onto a rectangle of its own aspect (--unit-squares: the unit "
               "square); write OBJ (vt per corner), a uv table, "
               "the patches and a picture");
  add_common_options(cmd, *options);
  cmd->add_flag("--svg", options->svg, "Also write each patch's uv layout as OUTPUT/<mesh>.patch<N>.svg (flipped "
                                      "triangles in red, the four sides in colour)");
  cmd->add_flag("--unit-squares", options->unit_squares,
                "Write every chart on the unit square (the canonical (u,v)) instead of on a rectangle of its own "
                "aspect (the aspect with the least stretch for the chart's map); the table then measures the squares");
  cmd->add_option("--runs", options->runs, "Run the parameterization N times and report the median time")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  cmd->footer(std::string("Writes OUTPUT/<mesh>.obj (v in input order, one vt per distinct (vertex, uv)), "
              "OUTPUT/<mesh>.uv.csv (vertex,patch,u,v), OUTPUT/<mesh>.mtl and <mesh>.checker.png (the OBJ's material "
              "and texture), OUTPUT/<mesh>.png (the mesh with its patches and u, v isolines) and "
              "OUTPUT/<mesh>.patches.txt (the patch of each face of the mesh file, one per "
              "line: a label file for --labels).\nA patch that cannot be mapped is listed and warned about; the others "
              "are written (with --strict, or if none can be mapped: an error).\n") + exit_codes);
  cmd->callback([options]() { run_param(*options); });
}

void add_render_command(CLI::App& app)
{
  auto options = std::make_shared<Param_options>();
  options->render_only = true;
  CLI::App* cmd = app.add_subcommand(
      "render", "Parameterize a mesh as param does and draw it: u, v isolines on patch colours or a distortion "
                "heat map (offscreen, PNG)");
  add_common_options(cmd, *options);
  cmd->footer(std::string("Writes OUTPUT/<mesh>.png only.\n") + exit_codes);
  cmd->callback([options]() { run_param(*options); });
}

} // namespace diffuv_cli
