// How the benchmark executables answer their command line: a mistake is named with the usage on
// stderr (exit 2); --help or -h prints the usage on stdout (exit 0).
#pragma once

#include <cstdlib>
#include <iostream>
#include <string>

namespace roomba_rrt::bench {

/// Exits with `usage` ("usage: tool [--flag N] ..."): after "<tool>: <error>" on stderr with
/// code 2, or, when `error` is empty (--help), alone on stdout with code 0.
[[noreturn]] inline void exitWithUsage(const std::string& tool, const std::string& error,
                                       const std::string& usage) {
  if (error.empty()) {
    std::cout << usage;
    std::exit(0);
  }
  std::cerr << tool << ": " << error << "\n" << usage;
  std::exit(2);
}

/// Whether `arg` asks for the usage.
inline bool isHelp(const std::string& arg) { return arg == "--help" || arg == "-h"; }

}  // namespace roomba_rrt::bench
