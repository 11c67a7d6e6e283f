// camopt: the command line (studies/cli.cc).
#include "studies/cli.h"

int main(int argc, char** argv) { return camopt::studies::CliMain(argc, argv); }
