// camopt: the command line. `camopt run STUDY.json [--out DIR] [--quiet]`.
// Exit codes: 0 success, 2 bad input (study file or arguments), 3 the study ran and its outputs
// were written but the answer is not what was asked (e.g. no design fits), 1 any other failure.
#include <exception>
#include <filesystem>
#include <iostream>

#include <CLI/CLI.hpp>

#include "studies/study.h"

int main(int argc, char** argv) {
  CLI::App app{"camopt: design optimisation of cam reducers and cam mechanisms"};
  app.require_subcommand(1);
  std::string study_file, out_dir;
  bool quiet = false;
  CLI::App* run = app.add_subcommand("run", "Analyse or size the design described in a study file");
  run->add_option("study", study_file, "Study file (JSON)")->required();
  run->add_option("--out,-o", out_dir, "Output folder (default: results/<study file stem>)");
  run->add_flag("--quiet,-q", quiet, "No progress lines on stderr");
  CLI::App* kinds = app.add_subcommand("kinds", "List the study kinds this build knows");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }

  if (kinds->parsed()) {
    for (const auto& k : camopt::studies::StudyKinds()) std::cout << k << "\n";
    return 0;
  }
  if (out_dir.empty())
    out_dir = (std::filesystem::path("results") / std::filesystem::path(study_file).stem()).string();
  try {
    camopt::studies::RunContext ctx;
    ctx.quiet = quiet;
    camopt::studies::RunStudyFile(study_file, out_dir, ctx);
    if (!quiet) std::cerr << "camopt: results written to " << out_dir << "\n";
    return 0;
  } catch (const camopt::studies::StudyIncomplete& e) {
    std::cerr << "camopt: " << e.what() << "\n";
    if (!quiet) std::cerr << "camopt: results written to " << out_dir << "\n";
    return 3;
  } catch (const camopt::studies::StudyError& e) {
    std::cerr << "camopt: error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "camopt: failure: " << e.what() << "\n";
    return 1;
  }
}
