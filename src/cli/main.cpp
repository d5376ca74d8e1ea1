// diffuv tool: entry point. Parses the command line, runs one subcommand and
// turns every error into one line on stderr and an exit code.
#include "commands.h"

#include <diffuv/core/error.h>

#include <cstring>
#include <exception>
#include <iostream>
#include <string>

int main(int argc, char** argv)
{
  CLI::App app{"diffuv: diffusion-based surface parameterization (CGAL)\n"
               "Each vertex of a disc patch gets u = d_u1/(d_u1+d_u2), v = d_v1/(d_v1+d_v2) from its\n"
               "distances to the four sides of the patch; folds are then repaired."};
  app.set_version_flag("--version", "diffuv " DIFFUV_VERSION);
  app.require_subcommand(1);
  diffuv_cli::add_param_command(app);
  diffuv_cli::add_render_command(app);
  diffuv_cli::add_segment_command(app);
  diffuv_cli::add_compare_command(app);
  diffuv_cli::add_correspond_command(app);
  diffuv_cli::add_measure_command(app);
  diffuv_cli::add_bake_command(app);
  diffuv_cli::add_serve_command(app);

  // CLI11 reports an unknown command as a missing one; say what it is.
  if(argc > 1 && argv[1][0] != '-') {
    bool known = false;
    for(const CLI::App* sub : app.get_subcommands({})) known = known || sub->get_name() == argv[1];
    if(!known) {
      std::cerr << "diffuv: error: unknown command '" << argv[1] << "' (commands: param, render, segment, compare, correspond, measure, bake, serve; see diffuv --help)\n";
      return diffuv_cli::exit_usage;
    }
  }

  try {
    app.parse(argc, argv);
  } catch(const CLI::Success& e) { // --help, --version
    return app.exit(e);
  } catch(const CLI::ParseError& e) {
    // Point at the help of the command that was given, if any.
    const std::string help = argc > 1 && argv[1][0] != '-' ? std::string("diffuv ") + argv[1] + " --help" : "diffuv --help";
    std::cerr << "diffuv: error: " << e.what() << " (see " << help << ")\n";
    return diffuv_cli::exit_usage;
  } catch(const diffuv::Input_error& e) {
    std::cerr << "diffuv: error: " << e.what() << '\n';
    return diffuv_cli::exit_bad_input;
  } catch(const diffuv::Output_error& e) {
    std::cerr << "diffuv: error: cannot write " << e.what() << '\n';
    return diffuv_cli::exit_output;
  } catch(const std::exception& e) {
    std::cerr << "diffuv: internal error: " << e.what() << '\n';
    return diffuv_cli::exit_internal;
  }
  return diffuv_cli::exit_ok;
}
