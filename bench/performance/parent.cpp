// diffuv performance bench: the parent, one child process per (mesh, level)
// (fork + exec of this program with --worker), then the tables and plots.
#include "performance/performance_bench.h"

#include <signal.h>
#include <sys/resource.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <thread>

namespace diffuv_bench {

namespace {

// Runs the worker for (mesh, level) in a fresh process; returns its row, with
// "status" = ok / failed / timeout and the child's own peak (ru_maxrss).
Row spawn_worker(const Options& o, const std::string& mesh, int level, const std::string& exe)
{
  const std::string result = o.output + "/.worker_" + mesh_name(mesh_path(mesh)) + "_" + std::to_string(level) + ".txt";
  std::filesystem::remove(result);
  std::vector<std::string> args = {exe,
                                   "--worker", mesh,
                                   "--level", std::to_string(level),
                                   "--result-file", result,
                                   "--runs", std::to_string(o.runs),
                                   "--large-runs", std::to_string(o.large_runs),
                                   "--large-vertices", std::to_string(o.large_vertices),
                                   "--queries", std::to_string(o.queries),
                                   "--cgal-max-vertices", std::to_string(o.cgal_max_vertices),
                                   "--auto-max-vertices", std::to_string(o.auto_max_vertices),
                                   "--parts", o.parts,
                                   "-o", o.output};
  if(o.profile) args.push_back("--profile");
  std::vector<char*> argv;
  for(auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);

  const auto t0 = Clock::now();
  const pid_t pid = fork();
  if(pid < 0) throw std::runtime_error("fork failed");
  if(pid == 0) {
    execv(exe.c_str(), argv.data());
    std::perror("execv");
    _exit(127);
  }
  int status = 0;
  struct rusage usage {};
  bool timed_out = false;
  while(true) {
    const pid_t done = wait4(pid, &status, WNOHANG, &usage);
    if(done == pid) break;
    if(done < 0) throw std::runtime_error("wait4 failed");
    if(ms_since(t0) / 1000. > o.timeout) {
      kill(pid, SIGKILL);
      wait4(pid, &status, 0, &usage);
      timed_out = true;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  Row row;
  if(!timed_out && WIFEXITED(status) && WEXITSTATUS(status) == 0 && std::filesystem::exists(result)) {
    row = read_row(result);
    row.set("status", std::string("ok"));
  } else {
    row.set("mesh", mesh_name(mesh_path(mesh)));
    row.set("level", level);
    row.set("status", std::string(timed_out ? "timeout" : "failed"));
  }
  std::filesystem::remove(result);
  const double V = row.number("V");
  row.set("child_maxrss_Bpv", std::isnan(V) ? V : double(usage.ru_maxrss) * 1024. / V);
  row.set("wall_s", ms_since(t0) / 1000.);
  return row;
}

} // namespace

int run_parent(const Options& o)
{
  const auto start = Clock::now();
  std::filesystem::create_directories(o.output);
  const std::string exe = std::filesystem::read_symlink("/proc/self/exe").string();
  std::vector<Row> rows;
  std::vector<std::string> names;
  for(const std::string& mesh : o.meshes) {
    names.push_back(mesh_name(mesh_path(mesh)));
    for(int level = o.first_level; level < 12; ++level) {
      Row row;
      if(o.no_fork) {
        row = run_worker(o, mesh, level);
        row.set("status", std::string("ok (no fork)"));
      } else {
        row = spawn_worker(o, mesh, level, exe);
      }
      rows.push_back(row);
      std::cerr << "[" << row.get("mesh") << " L" << level << "] " << row.get("status") << " in "
                << cell(row, "wall_s", "%.1f") << " s" << std::endl;
      write_csv(rows, o.output + "/results.csv"); // partial results survive an interruption
      const double V = row.number("V"), E = row.number("E");
      if(row.get("status").rfind("ok", 0) != 0 || std::isnan(V) || V >= double(o.sizes)) break;
      // Loop subdivision adds one vertex per edge.
      if(o.max_vertices > 0 && V + E > double(o.max_vertices)) break;
    }
  }
  const std::string md = tables(rows, o);
  std::cout << md;
  {
    std::ofstream f(o.output + "/table.md");
    f << "Command: diffuv_performance_bench --meshes ";
    for(std::size_t i = 0; i < o.meshes.size(); ++i) f << (i ? "," : "") << o.meshes[i];
    f << " --sizes " << o.sizes << " --runs " << o.runs << " --large-runs " << o.large_runs;
    if(o.max_vertices) f << " --max-vertices " << o.max_vertices;
    if(o.first_level) f << " --first-level " << o.first_level;
    f << (o.profile ? " --profile" : "") << "\n\n" << md;
  }
  write_csv(rows, o.output + "/results.csv");
  write_plots(rows, names, o.output);
  std::cerr << "wrote " << o.output << "/results.csv, table.md and plots; total "
            << format("%.1f", ms_since(start) / 1000.) << " s" << std::endl;
  for(const Row& r : rows)
    if(r.get("status").rfind("ok", 0) != 0) return 1;
  return 0;
}

} // namespace diffuv_bench
