// The `adsd` program: `adsd <command> [arguments]`, one file per command (see commands.h).

#include <csignal>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include "commands.h"

namespace {

struct Command {
  const char* name;
  const char* summary;
  int (*run)(const std::vector<std::string>& args);
};

// One line per command; `adsd --help` lists them in this order.
const Command kCommands[] = {
    {"distance", "minimum distance between two meshes: one query, or one per line of a pose file",
     adsd::app::distanceCommand},
    {"plan", "solve a motion-planning problem file (OMPL.app .cfg) with the adsd validity checker",
     adsd::app::planCommand},
    {"benchmark", "OMPL benchmark of a problem file for each checker and motion validator: log, database, plots",
     adsd::app::benchmarkCommand},
    {"srdf", "the self-collision pairs a robot needs left unchecked (adjacent, always touching), as an SRDF",
     adsd::app::srdfCommand},
    {"view", "write a self-contained HTML page showing a problem, a path, its closest points and clearance",
     adsd::app::viewCommand},
};

// The same layout as each command's help (adsd::cli::CommandLine): usage, what it does, then the list.
void printUsage(std::ostream& out) {
  out << "usage: adsd <command> [arguments]\n\n"
         "Exact distance between triangle meshes, and motion planning with it as OMPL's validity checker.\n\n"
         "commands:\n";
  for (const Command& c : kCommands) {
    std::string name = c.name;
    name.resize(12, ' ');
    out << "  " << name << c.summary << '\n';
  }
  out << "\noptions:\n"
         "  -h [ --help ]  print this help and exit\n"
         "  --version      print the version and exit\n\n"
         "adsd <command> --help describes one command.\n";
}

// Makes a standard output that could not be written the failure of what printed it (\p who): a
// full disk or a file-size limit otherwise lost the plan's report with exit status 0.
int checkOutput(int status, const std::string& who) {
  std::cout.flush();
  std::fflush(stdout);
  if (status == 0 && (!std::cout || std::ferror(stdout))) {
    std::cerr << who << ": error: cannot write the standard output\n";
    return 1;
  }
  return status;
}

}  // namespace

int main(int argc, char** argv) {
  // Past a file-size limit (ulimit -f) the kernel's SIGXFSZ killed the program without a word and
  // left a half-written page behind; ignored, the write fails instead and is reported as one.
  std::signal(SIGXFSZ, SIG_IGN);
  const std::vector<std::string> args(argv + 1, argv + argc);
  // A bad command line is one line and exit status 2, as in every command (adsd::cli).
  if (args.empty()) {
    std::cerr << "adsd: error: expected a command (adsd --help lists them)\n";
    return 2;
  }
  const std::string& name = args.front();
  if (name == "--help" || name == "-h" || name == "help") {
    printUsage(std::cout);
    return checkOutput(0, "adsd");
  }
  if (name == "--version") {
    std::cout << "adsd " << ADSD_VERSION << '\n';
    return checkOutput(0, "adsd");
  }
  for (const Command& c : kCommands) {
    if (name == c.name) {
      return checkOutput(c.run(std::vector<std::string>(args.begin() + 1, args.end())), std::string("adsd ") + c.name);
    }
  }
  std::cerr << "adsd: error: unknown command '" << name << "' (adsd --help lists the commands)\n";
  return 2;
}
