// diffuv bench: how fast mesh files are read (issue #20's reading targets).
//
// Two meshes: mushroom.off of CGAL's data set after three Loop subdivision
// steps (about 148k vertices, a disc) and a square grid of 1050 x 1050
// vertices (1.1M). Each is written as ASCII OFF, OBJ and PLY (17 significant
// digits, as CGAL's writers and diffuv's own write them) and as binary
// little- and big-endian PLY (double coordinates), into a scratch folder; then each
// file is read with diffuv::read_triangle_mesh() (file to checked
// Surface_mesh, what `diffuv param` calls "read") and, as a reference, with
// CGAL::IO::read_polygon_soup() alone (file to points and polygons, no
// checks, no mesh). Times are medians of --runs reads after one untimed read.
//
// A second table measures the repairs of reading (issue #21: "repair costs
// less than reading"): each mesh of --repair-meshes written as OFF as it is,
// with every other face turned over, and as a triangle soup (three points
// of its own per face, the unwelded STL case). For each file: the whole
// read_triangle_mesh(), and the repair alone (internal::repair_polygon_soup()
// on the parsed soup), whose target is to cost less than the rest of the read.
//
// Usage: diffuv_reading_bench [--runs 5] [--meshes mushroom3,grid1m]
//                             [--repair-meshes bunny00] [-o DIR]
// Prints the tables with MB/s and each target (>= 100 MB/s ASCII, >= 500 MB/s
// binary PLY; repair < rest of the read) next to its measurement; writes
// DIR/reading.md.
#include "common.h"

#include <diffuv/io/read_mesh.h>

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/IO/PLY.h>
#include <CGAL/Subdivision_method_3/subdivision_methods_3.h>
#include <CGAL/boost/graph/IO/OFF.h>
#include <CGAL/boost/graph/IO/OBJ.h>
#include <CGAL/boost/graph/IO/PLY.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <array>
#include <iomanip>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace diffuv_bench;
namespace fs = std::filesystem;

// The mesh a name stands for.
Mesh make_mesh(const std::string& name)
{
  Mesh m;
  if(name == "mushroom3") {
    read_named_mesh("mushroom", m);
    CGAL::Subdivision_method_3::Loop_subdivision(m, CGAL::parameters::number_of_iterations(3));
  } else if(name == "grid1m") {
    const int n = 1050;
    std::vector<Mesh::Vertex_index> v;
    v.reserve(static_cast<std::size_t>(n) * n);
    for(int j = 0; j < n; ++j)
      for(int i = 0; i < n; ++i)
        v.push_back(m.add_vertex(Point_3(i / double(n - 1), j / double(n - 1), 0.1 * std::sin(0.01 * i * j))));
    for(int j = 0; j + 1 < n; ++j)
      for(int i = 0; i + 1 < n; ++i) {
        const auto a = v[j * n + i], b = v[j * n + i + 1], c = v[(j + 1) * n + i + 1], d = v[(j + 1) * n + i];
        m.add_face(a, b, c);
        m.add_face(a, c, d);
      }
  } else {
    read_named_mesh(name, m);
  }
  return m;
}

struct File { std::string format, path; bool binary = false; };

// A big-endian copy of the little-endian PLY file `little` that CGAL's writer
// wrote (it writes no other binary): the same header but for the format
// line, then every value of "double x, y, z" and "list uchar int" with its
// bytes reversed.
void write_big_endian_copy(const std::string& little, const std::string& big)
{
  std::ifstream in(little, std::ios::binary);
  std::ofstream out(big, std::ios::binary);
  std::size_t vertices = 0, faces = 0;
  for(std::string line; std::getline(in, line);) {
    std::istringstream words(line);
    std::string keyword, name;
    std::size_t count = 0;
    if(words >> keyword && keyword == "element" && words >> name >> count)
      (name == "vertex" ? vertices : faces) = count;
    out << (keyword == "format" ? "format binary_big_endian 1.0" : line) << '\n';
    if(keyword == "end_header")
      break;
  }
  auto copy_reversed = [&](std::size_t size) {
    char b[8];
    in.read(b, static_cast<std::streamsize>(size));
    std::reverse(b, b + size);
    out.write(b, static_cast<std::streamsize>(size));
  };
  for(std::size_t i = 0; i < 3 * vertices; ++i)
    copy_reversed(sizeof(double));
  for(std::size_t j = 0; j < faces; ++j) {
    const int n = in.peek();
    copy_reversed(1);
    for(int c = 0; c < n; ++c)
      copy_reversed(sizeof(std::int32_t));
  }
}

std::vector<File> write_files(const Mesh& m, const std::string& name, const fs::path& folder)
{
  std::vector<File> files;
  const auto precision = CGAL::parameters::stream_precision(17);
  auto path = [&](const std::string& suffix) { return (folder / (name + suffix)).string(); };
  files.push_back({"OFF", path(".off")});
  CGAL::IO::write_OFF(files.back().path, m, precision);
  files.push_back({"OBJ", path(".obj")});
  CGAL::IO::write_OBJ(files.back().path, m, precision);
  files.push_back({"PLY ascii", path(".ascii.ply")});
  CGAL::IO::write_PLY(files.back().path, m, precision.use_binary_mode(false));
  files.push_back({"PLY binary", path(".binary.ply"), true});
  CGAL::IO::write_PLY(files.back().path, m, CGAL::parameters::use_binary_mode(true));
  files.push_back({"PLY binary BE", path(".big_endian.ply"), true});
  write_big_endian_copy(files[files.size() - 2].path, files.back().path);
  return files;
}

// `m` written as OFF three ways: as it is, with every other face turned
// over, and with three points of its own per face.
std::vector<File> write_damaged_files(const Mesh& m, const std::string& name, const fs::path& folder)
{
  std::vector<Point_3> points(m.points().begin(), m.points().end());
  std::vector<std::array<std::size_t, 3>> triangles;
  for(Mesh::Face_index f : m.faces()) {
    std::array<std::size_t, 3> t{};
    std::size_t c = 0;
    for(Mesh::Vertex_index v : m.vertices_around_face(m.halfedge(f))) t[c++] = v;
    triangles.push_back(t);
  }
  const auto write = [&](const std::string& kind, bool turn, bool soup) {
    const std::string path = (folder / (name + "-" + kind + ".off")).string();
    std::ofstream out(path);
    out << std::setprecision(17) << "OFF\n" << (soup ? 3 * triangles.size() : points.size()) << ' '
        << triangles.size() << " 0\n";
    if(soup) {
      for(const auto& t : triangles)
        for(std::size_t v : t) out << points[v] << '\n';
    } else {
      for(const Point_3& p : points) out << p << '\n';
    }
    for(std::size_t j = 0; j < triangles.size(); ++j) {
      std::array<std::size_t, 3> t = soup ? std::array<std::size_t, 3>{3 * j, 3 * j + 1, 3 * j + 2} : triangles[j];
      if(turn && j % 2 == 1) std::swap(t[1], t[2]);
      out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
    }
    return File{kind, path};
  };
  return {write("as it is", false, false), write("every other face turned", true, false),
          write("triangle soup", false, true)};
}

// The repairs' table (see the top of this file); false if a target is missed.
bool measure_repairs(const std::vector<std::string>& meshes, int runs, const fs::path& scratch, std::ostream& table)
{
  table << "\n| mesh | OFF file | MB | read_triangle_mesh ms | repair alone ms | rest of the read ms | what was repaired | repair < rest |\n"
        << "|---|---|---:|---:|---:|---:|---|---|\n";
  bool all_met = true;
  for(const std::string& name : meshes) {
    Mesh m;
    read_named_mesh(name, m);
    for(const File& f : write_damaged_files(m, name, scratch)) {
      Mesh read;
      diffuv::Mesh_repair_report repaired;
      const double ms = median_time(runs, [&] { repaired = diffuv::read_triangle_mesh(f.path, read).repair; });
      std::vector<Point_3> file_points;
      std::vector<std::vector<std::size_t>> file_polygons;
      CGAL::IO::read_polygon_soup(f.path, file_points, file_polygons, CGAL::parameters::verbose(false));
      std::vector<double> times;
      for(int r = 0; r < runs; ++r) {
        std::vector<Point_3> points = file_points;
        std::vector<std::vector<std::size_t>> polygons = file_polygons;
        diffuv::internal::Line_locator locate([] { return diffuv::internal::Text_mesh_scan(); });
        diffuv::Mesh_repair_report report;
        const auto t0 = Clock::now();
        diffuv::internal::repair_polygon_soup(f.path, points, polygons, locate, report);
        times.push_back(ms_since(t0));
      }
      const double repair_ms = median(times), rest_ms = ms - repair_ms;
      std::string what = repaired.faces_reoriented ? std::to_string(repaired.faces_reoriented) + " faces turned"
                         : repaired.points_merged ? std::to_string(repaired.points_merged) + " points merged"
                                                  : "nothing";
      const bool met = !repaired.any() || repair_ms < rest_ms;
      all_met = all_met && met;
      table << "| " << name << " | " << f.format << " | "
            << format("%.1f", static_cast<double>(fs::file_size(f.path)) / 1e6) << " | " << format("%.0f", ms) << " | "
            << format("%.1f", repair_ms) << " | " << format("%.0f", rest_ms) << " | " << what << " | "
            << (met ? "yes" : "no") << " |\n";
      std::cerr << "  " << name << ", " << f.format << ": " << format("%.0f", ms) << " ms, repair "
                << format("%.1f", repair_ms) << " ms\n";
    }
  }
  return all_met;
}

} // namespace

int main(int argc, char** argv)
{
  CLI::App app{"diffuv reading bench: MB/s of read_triangle_mesh() per format"};
  std::vector<std::string> meshes = {"mushroom3", "grid1m"};
  int runs = 5;
  std::string output = "bench-out/reading";
  std::vector<std::string> repair_meshes = {"bunny00"};
  add_meshes_option(app, meshes, "Meshes (mushroom3: mushroom after 3 Loop steps; grid1m: 1050 x 1050 grid)");
  app.add_option("--repair-meshes", repair_meshes,
                 "Meshes written as OFF as they are, with every other face turned, and as a triangle soup, "
                 "to time the repairs of reading")
      ->delimiter(',');
  add_runs_option(app, runs, "Reads per file; the median is reported");
  add_output_option(app, output);
  CLI11_PARSE(app, argc, argv);

  return exit_code_of([&] {
    fs::create_directories(output);
    const fs::path scratch = fs::temp_directory_path() / ("diffuv_reading_bench_" + std::to_string(::getpid()));
    fs::create_directories(scratch);
    std::ostringstream table;
    table << "| mesh | format | MB | vertices | read_triangle_mesh ms | MB/s | target | met | CGAL soup only ms | MB/s |\n"
          << "|---|---|---:|---:|---:|---:|---:|---|---:|---:|\n";
    bool all_met = true;
    for(const std::string& name : meshes) {
      std::cerr << name << ": making the mesh\n";
      const Mesh m = make_mesh(name);
      for(const File& f : write_files(m, name, scratch)) {
        const double mb = static_cast<double>(fs::file_size(f.path)) / 1e6;
        Mesh read;
        std::size_t vertices = 0;
        const double ms = median_time(runs, [&] { vertices = diffuv::read_triangle_mesh(f.path, read).vertices; });
        std::vector<Point_3> points;
        std::vector<std::vector<std::size_t>> polygons;
        const double soup_ms = median_time(runs, [&] {
          points.clear();
          polygons.clear();
          CGAL::IO::read_polygon_soup(f.path, points, polygons, CGAL::parameters::verbose(false));
        });
        const double rate = mb / (ms / 1000), target = f.binary ? 500 : 100;
        all_met = all_met && rate >= target;
        table << "| " << name << " | " << f.format << " | " << format("%.1f", mb) << " | " << vertices << " | "
              << format("%.0f", ms) << " | " << format("%.0f", rate) << " | " << format("%.0f", target) << " | "
              << (rate >= target ? "yes" : "no") << " | " << format("%.0f", soup_ms) << " | "
              << format("%.0f", mb / (soup_ms / 1000)) << " |\n";
        std::cerr << "  " << f.format << ": " << format("%.0f", ms) << " ms\n";
      }
    }
    all_met = measure_repairs(repair_meshes, runs, scratch, table) && all_met;
    fs::remove_all(scratch);
    std::cout << table.str();
    std::ofstream(fs::path(output) / "reading.md") << table.str();
    return all_met ? 0 : 1;
  });
}
