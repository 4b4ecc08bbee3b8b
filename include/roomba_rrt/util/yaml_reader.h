// Reading YAML the way every file of the package is read: yaml-cpp, plus the check it leaves out.
// A key given twice in one mapping is valid YAML to yaml-cpp, which keeps the first value and
// says nothing; so a world file with `robot:` twice (the second with a misspelt `radious:`)
// would run with the first and hide the mistake from the "unknown keys are errors" rule.
// Anchors (&name) and aliases (*name) are refused before the text becomes nodes: none of our
// files needs them, and an alias makes a node graph, not a tree, so a recursive alias
// (`room: &r {self: *r}`) or a few lines of aliases of aliases (a billion leaves) would keep
// anything that walks the nodes busy for hours or recurse until the stack is gone.
#pragma once

#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/yaml.h>

#include <map>
#include <sstream>
#include <string>

#include "roomba_rrt/util/invalid_input.h"

namespace roomba_rrt::util {

/// Throws InvalidInput "line L, column C: an anchor (&name) or alias (*name) is not read; write
/// the value out" at the first anchor or alias in `text`'s first document, reading it as a stream
/// of events (in time linear in its length, whatever the aliases would expand to). A syntax error
/// is InvalidInput "not valid YAML: ...".
inline void rejectAnchorsAndAliases(const std::string& text) {
  class Refuser : public YAML::EventHandler {
   public:
    void OnDocumentStart(const YAML::Mark&) override {}
    void OnDocumentEnd() override {}
    void OnNull(const YAML::Mark& mark, YAML::anchor_t anchor) override { check(mark, anchor); }
    void OnAlias(const YAML::Mark& mark, YAML::anchor_t) override { refuse(mark); }
    void OnScalar(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                  const std::string&) override {
      check(mark, anchor);
    }
    void OnSequenceStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                         YAML::EmitterStyle::value) override {
      check(mark, anchor);
    }
    void OnSequenceEnd() override {}
    void OnMapStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                    YAML::EmitterStyle::value) override {
      check(mark, anchor);
    }
    void OnMapEnd() override {}
    void OnAnchor(const YAML::Mark& mark, const std::string&) override { refuse(mark); }

   private:
    static void check(const YAML::Mark& mark, YAML::anchor_t anchor) {
      if (anchor != YAML::NullAnchor) refuse(mark);
    }
    [[noreturn]] static void refuse(const YAML::Mark& mark) {
      throw InvalidInput("", "line " + std::to_string(mark.line + 1) + ", column " +
                                 std::to_string(mark.column + 1) +
                                 ": an anchor (&name) or alias (*name) is not read; write the "
                                 "value out");
    }
  };
  std::istringstream in(text);
  Refuser refuser;
  try {
    // The first document, the one YAML::Load reads. (Looping to the end is no option: on a
    // stray token such as a leading ',' yaml-cpp hands out empty documents without moving on.)
    YAML::Parser parser(in);
    parser.HandleNextDocument(refuser);
  } catch (const YAML::Exception& e) {
    throw InvalidInput("", std::string("not valid YAML: ") + e.what());
  }
}

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

/// rejectAnchorsAndAliases(), YAML::Load, then rejectDuplicateKeys(). A syntax error is
/// InvalidInput "not valid YAML: ...".
inline YAML::Node parseYaml(const std::string& text) {
  rejectAnchorsAndAliases(text);
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
