// diffuv bench: what the benchmark programs share. The mesh types, CGAL's
// data meshes by name, timing and medians, number formatting, the options
// every bench takes (--meshes, --runs, -o) and the exit code on an error.
#ifndef DIFFUV_BENCH_COMMON_H
#define DIFFUV_BENCH_COMMON_H

#include <diffuv/io/read_mesh.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

// Where CGAL's data set was extracted (bench/CMakeLists.txt sets it).
#ifndef DIFFUV_DEFAULT_DATA_DIR
#define DIFFUV_DEFAULT_DATA_DIR "data"
#endif

namespace diffuv_bench {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point_2 = Kernel::Point_2;
using Point_3 = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point_3>;
using vertex_descriptor = Mesh::Vertex_index;
using halfedge_descriptor = Mesh::Halfedge_index;
using face_descriptor = Mesh::Face_index;
using Clock = std::chrono::steady_clock;

constexpr double infinity = std::numeric_limits<double>::infinity();

// ---------------------------------------------------------------------------
// Meshes: CGAL's data set by name

/// The file of a mesh named on the command line: a name of CGAL's data set
/// (cow = <data>/meshes/cow.off), or a path (anything with '/' or '.').
inline std::string mesh_path(const std::string& name)
{
  if(name.find('/') != std::string::npos || name.find('.') != std::string::npos) return name;
  return std::string(DIFFUV_DEFAULT_DATA_DIR) + "/meshes/" + name + ".off";
}

/// The name the tables give a mesh: its file name without folder and extension.
inline std::string mesh_name(const std::string& path) { return std::filesystem::path(path).stem().string(); }

/// Reads the triangle mesh named on the command line (see mesh_path()) into
/// `mesh`; returns its name (mesh_name()). Throws on a file it cannot read.
inline std::string read_named_mesh(const std::string& name_or_path, Mesh& mesh)
{
  const std::string path = mesh_path(name_or_path);
  diffuv::read_triangle_mesh(path, mesh);
  return mesh_name(path);
}

// ---------------------------------------------------------------------------
// Time

inline double ms_since(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

/// The median; NaN for no values.
inline double median(std::vector<double> v)
{
  if(v.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/// The median time of `runs` calls of `f` (ms), after one untimed call.
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

// ---------------------------------------------------------------------------
// Output

/// `x` printed with the printf format `f` ("%.3g"); "inf" for an infinity.
inline std::string format(const char* f, double x)
{
  if(std::isinf(x)) return "inf";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, f, x);
  return buffer;
}

// ---------------------------------------------------------------------------
// The command line

/// --meshes: a comma-separated list of names of CGAL's data set or paths.
inline void add_meshes_option(CLI::App& app, std::vector<std::string>& meshes, const std::string& which)
{
  app.add_option("--meshes", meshes, which + ": names in CGAL's data set (cow = <data>/meshes/cow.off) or paths")
      ->delimiter(',')
      ->capture_default_str();
}

/// --runs: how many runs a time is the median of.
inline void add_runs_option(CLI::App& app, int& runs, const std::string& description)
{
  app.add_option("--runs", runs, description)->check(CLI::PositiveNumber)->capture_default_str();
}

/// -o, --output: the folder the tables, CSV files and plots go to.
inline void add_output_option(CLI::App& app, std::string& output)
{
  app.add_option("-o,--output", output, "Output folder")->capture_default_str();
}

/// Runs the bench's body; an exception is an error: "error: ..." on stderr, exit code 4.
template <class F>
int exit_code_of(F&& body)
{
  try {
    return body();
  } catch(const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 4;
  }
}

} // namespace diffuv_bench

#endif // DIFFUV_BENCH_COMMON_H
