#include "roomba_rrt/planning/planner_options.h"

#include <array>
#include <utility>

namespace roomba_rrt::planning {
namespace {

// One table per enum: the single place where names and values meet.
constexpr std::array<std::pair<const char*, Algorithm>, 4> kAlgorithms{{
    {"rrt", Algorithm::kRrt},
    {"rrt_connect", Algorithm::kRrtConnect},
    {"rrt_star", Algorithm::kRrtStar},
    {"region_astar", Algorithm::kRegionAStar},
}};
constexpr std::array<std::pair<const char*, CollisionCheck>, 2> kCollisionChecks{{
    {"points", CollisionCheck::kPoints},
    {"segments", CollisionCheck::kSegments},
}};
constexpr std::array<std::pair<const char*, NearestSearch>, 2> kNearestSearches{{
    {"index", NearestSearch::kIndex},
    {"brute_force", NearestSearch::kBruteForce},
}};
constexpr std::array<std::pair<const char*, RandomStream>, 2> kRandomStreams{{
    {"matlab", RandomStream::kMatlab},
    {"fast", RandomStream::kFast},
}};

template <typename Enum, std::size_t N>
std::optional<Enum> parse(const std::array<std::pair<const char*, Enum>, N>& table,
                          const std::string& name) {
  for (const auto& [text, value] : table) {
    if (name == text) return value;
  }
  return std::nullopt;
}

template <typename Enum, std::size_t N>
std::string name(const std::array<std::pair<const char*, Enum>, N>& table, Enum value) {
  for (const auto& [text, v] : table) {
    if (v == value) return text;
  }
  return "unknown";
}

}  // namespace

std::optional<Algorithm> parseAlgorithm(const std::string& name) {
  return parse(kAlgorithms, name);
}
std::optional<CollisionCheck> parseCollisionCheck(const std::string& name) {
  return parse(kCollisionChecks, name);
}
std::optional<NearestSearch> parseNearestSearch(const std::string& name) {
  return parse(kNearestSearches, name);
}
std::optional<RandomStream> parseRandomStream(const std::string& name) {
  return parse(kRandomStreams, name);
}
std::string toString(Algorithm algorithm) { return name(kAlgorithms, algorithm); }
std::string toString(CollisionCheck collision) { return name(kCollisionChecks, collision); }
std::string toString(NearestSearch nearest) { return name(kNearestSearches, nearest); }
std::string toString(RandomStream stream) { return name(kRandomStreams, stream); }

}  // namespace roomba_rrt::planning
