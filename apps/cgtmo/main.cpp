// cgtmo: tone mapping for CG renders. The dispatch to one file per subcommand is dispatch.cpp.
#include <string>
#include <vector>

#include "commands.h"

int main(int argc, char** argv) { return cgtmo::cli::run_command(std::vector<std::string>(argv + 1, argv + argc)); }
