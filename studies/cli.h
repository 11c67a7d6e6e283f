// camopt's command line as a function: parses argv, runs the subcommand, prints its messages and
// returns the exit code (0 done, 2 the user can fix it, 3 results written but not what was
// asked, 1 a camopt defect; 130 on SIGINT/SIGTERM, which end the process). See studies/cli.cc.
#pragma once

namespace camopt::studies {

int CliMain(int argc, char** argv);

}  // namespace camopt::studies
