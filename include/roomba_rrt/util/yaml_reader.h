// Reading YAML the way every file of the package is read: yaml-cpp, plus the check it leaves out.
// A key given twice in one mapping is valid YAML to yaml-cpp, which keeps the first value and
// says nothing; so a world file with `robot:` twice (the second with a misspelt `radious:`)
// would run with the first and hide the mistake from the "unknown keys are errors" rule.
#pragma once

#include <yaml-cpp/yaml.h>

#include <map>
#include <string>

#include "roomba_rrt/util/invalid_input.h"

namespace roomba_rrt::util {

/// Throws InvalidInput naming the key (its path, see member()) and both lines, e.g.
/// "robot: is given twice (lines 1 and 3); a mapping holds one value per key", when a mapping
/// anywhere in `node` has a key twice.
inline void rejectDuplicateKeys(const YAML::Node& node, const std::string& path = "") {
  if (node.IsMap()) {
    std::map<std::string, int> lines;  // key -> line of its first occurrence (1-based)
    for (const auto& pair : node) {
      const std::string key = pair.first.IsScalar() ? pair.first.Scalar() : "?";
      const int line = pair.first.Mark().line + 1;
      const auto [first, fresh] = lines.emplace(key, line);
      if (!fresh) {
        throw InvalidInput(member(path, key),
                           "is given twice (lines " + std::to_string(first->second) + " and " +
                               std::to_string(line) + "); a mapping holds one value per key");
      }
      rejectDuplicateKeys(pair.second, member(path, key));
    }
  } else if (node.IsSequence()) {
    std::size_t i = 0;
    for (const auto& item : node) rejectDuplicateKeys(item, entry(path, i++));
  }
}

/// YAML::Load, then rejectDuplicateKeys(). A syntax error is InvalidInput "not valid YAML: ...".
inline YAML::Node parseYaml(const std::string& text) {
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw InvalidInput("", std::string("not valid YAML: ") + e.what());
  }
  rejectDuplicateKeys(root);
  return root;
}

}  // namespace roomba_rrt::util
