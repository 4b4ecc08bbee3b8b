// How every core (planning, simulation, behaviour, behavior trees) reports input it cannot use:
// one exception that names the offending field by its path, and one way to print numbers.
#pragma once

#include <cstddef>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

namespace roomba_rrt::util {

/// A number as messages print it: the shortest form std::ostream gives ("0.17", "1e+06", "-inf",
/// "nan"), so that the user recognises the value they wrote.
inline std::string show(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

/// Field paths are spelled one way in every message: a member after '.', a list entry as [i],
/// e.g. "bounds.x_min", "rectangles[2].max_x", "furniture.circles[0].radius",
/// "robots[1].initial_pose.x", "forward_speed". member("robots[1]", "name") is "robots[1].name"
/// (just "name" under an empty parent); entry("robots", 1) is "robots[1]".
inline std::string member(const std::string& parent, const std::string& name) {
  return parent.empty() ? name : parent + "." + name;
}
inline std::string entry(const std::string& list, std::size_t index) {
  return list + "[" + std::to_string(index) + "]";
}

/// Input that cannot be used: which field (its path, see member()) and what is wrong with it.
/// what() reads "field: problem", e.g. "step: must be in [1e-06, 1e+06] m, got -1", or just
/// "problem" when no single field is to blame; in(source) prefixes the file it came from:
/// "world.yaml: robot.radius: must be in (0, 10], got -1". The checks of numbers
/// (require.h) word every such message the same way: "must be <rule>, got <value>".
///
/// It is a std::invalid_argument, so callers that only need the text catch that.
class InvalidInput : public std::invalid_argument {
 public:
  InvalidInput(std::string field, std::string problem, std::string source = "")
      : std::invalid_argument(format(source, field, problem)),
        field_(std::move(field)),
        problem_(std::move(problem)),
        source_(std::move(source)) {}

  /// The same error, found in `source` (a file name, "<string>", "FILE:LINE").
  InvalidInput in(const std::string& source) const { return {field_, problem_, source}; }

  const std::string& field() const { return field_; }      ///< "" when no single field
  const std::string& problem() const { return problem_; }  ///< what is wrong, without the field
  const std::string& source() const { return source_; }    ///< "" until in() names one

 private:
  static std::string format(const std::string& source, const std::string& field,
                            const std::string& problem) {
    return (source.empty() ? "" : source + ": ") + (field.empty() ? "" : field + ": ") + problem;
  }

  std::string field_;
  std::string problem_;
  std::string source_;
};

}  // namespace roomba_rrt::util
