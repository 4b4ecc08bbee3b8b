// Runs a node or tool binary of this package as a child process and collects what it printed,
// for tests of start-up errors (an invalid file or parameter must stop the node with a clear
// message) and of the command-line tools.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <string>

namespace roomba_rrt::test {

struct Outcome {
  int exit_code = -1;  ///< the node's exit status; 124 when `timeout` had to stop it
  std::string output;  ///< stdout and stderr, interleaved
};

/// Path of a node built next to this test executable (catkin puts both in devel/lib/roomba_rrt).
/// Used instead of `rosrun`, which asks which binary to start when several build trees exist.
inline std::string siblingExecutable(const std::string& name) {
  std::array<char, 4096> self{};
  const ssize_t n = readlink("/proc/self/exe", self.data(), self.size() - 1);
  const std::string path(self.data(), n > 0 ? static_cast<std::size_t>(n) : 0);
  return path.substr(0, path.rfind('/') + 1) + name;
}

/// Runs a shell command and collects its stdout and stderr.
inline Outcome runCommand(const std::string& command) {
  Outcome outcome;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return outcome;
  std::array<char, 512> buffer;
  while (fgets(buffer.data(), buffer.size(), pipe)) outcome.output += buffer.data();
  const int status = pclose(pipe);
  outcome.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return outcome;
}

/// Runs node `type` as ROS node `name` with extra command-line `args` (e.g. `_param:=value`);
/// gives up after 30 s, so a node that hangs instead of exiting fails the test with code 124.
inline Outcome runNode(const std::string& type, const std::string& name, const std::string& args) {
  return runCommand("timeout 30 " + siblingExecutable(type) + " __name:=" + name + " " + args);
}

}  // namespace roomba_rrt::test
