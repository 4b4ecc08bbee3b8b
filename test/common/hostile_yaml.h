// YAML that an attacker who can write one file the robot reads would try (issue 44): aliases
// that make the nodes a cycle or a tree of a billion leaves from a few lines. Every reader
// (world files, behaviour configs, map YAMLs, scenario files) refuses both at once.
#pragma once

#include <string>

namespace roomba_rrt::test {

/// 45 bytes: a mapping that contains itself.
inline const std::string kRecursiveAlias = "room: &r {width: 6.4, height: 4.8, self: *r}\n";

/// `levels` lines, each a list of ten aliases of the line before: 10^levels leaves, about 1 KB
/// of text for 9 levels.
inline std::string aliasBomb(int levels = 9) {
  std::string text = "a0: &a0 [x, x, x, x, x, x, x, x, x, x]\n";
  for (int level = 1; level < levels; ++level) {
    const std::string before = "*a" + std::to_string(level - 1);
    text += "a" + std::to_string(level) + ": &a" + std::to_string(level) + " [";
    for (int i = 0; i < 10; ++i) text += (i ? ", " : "") + before;
    text += "]\n";
  }
  return text;
}

/// What every reader says of an anchor or alias, at that line and column.
inline std::string aliasRefusal(int line, int column) {
  return "line " + std::to_string(line) + ", column " + std::to_string(column) +
         ": an anchor (&name) or alias (*name) is not read; write the value out";
}

}  // namespace roomba_rrt::test
