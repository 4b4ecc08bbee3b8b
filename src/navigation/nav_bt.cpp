#include "roomba_rrt/navigation/nav_bt.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "roomba_rrt/behavior/roomba_tree.h"
#include "roomba_rrt/util/invalid_input.h"

namespace roomba_rrt::navigation {
namespace {

const std::string kIdle = "Idle";

std::shared_ptr<bt::Blackboard> makeBoard() {
  auto board = std::make_shared<bt::Blackboard>();
  board->declare<robot::Pose2D>("goal");
  board->declare<robot::Pose2D>("pose");
  return board;
}

bt::Tree buildTree(const NavLeafConfig& config, NavContext& context, const std::string& text,
                   const std::string& source, bool from_file,
                   std::shared_ptr<bt::Blackboard> board) {
  bt::TreeFactory factory;
  factory.setTickRate(config.params.rate);
  behavior::registerRoombaLeaves(factory, config.params, context);
  registerNavLeaves(factory, config, context);
  return from_file ? factory.buildFromFile(text, std::move(board))
                   : factory.buildFromText(text, source, std::move(board));
}

/// Factories that only describe leaves (their builders are never called): one with the lab's
/// leaves, one with the lab's and the navigation leaves.
struct LeafCatalogue {
  explicit LeafCatalogue(const std::vector<LeafRegistrar>& more) : context(0) {
    config.planners = [] { return std::unique_ptr<PathPlanner>(); };  // never called
    config.more_leaves = more;
    behavior::registerRoombaLeaves(lab, config.params, context);
    behavior::registerRoombaLeaves(all, config.params, context);
    registerNavLeaves(all, config, context);
  }
  NavLeafConfig config;
  NavContext context;
  bt::TreeFactory lab, all;
};

}  // namespace

std::string treeNodesModel(const std::vector<LeafRegistrar>& more) {
  return LeafCatalogue(more).all.treeNodesModel();
}

bool usesNavigationLeaves(const std::string& tree_file, const std::vector<LeafRegistrar>& more) {
  const LeafCatalogue catalogue(more);
  const std::vector<std::string> lab = catalogue.lab.registeredTypes();
  for (const std::string& type : catalogue.all.typesUsedIn(tree_file)) {
    if (!std::binary_search(lab.begin(), lab.end(), type)) {
      return true;  // a type only the navigation leaves register
    }
  }
  return false;
}

bool usesLeavesOf(const std::string& tree_file, const std::vector<LeafRegistrar>& more) {
  const std::vector<std::string> without = LeafCatalogue({}).all.registeredTypes();
  for (const std::string& type : LeafCatalogue(more).all.typesUsedIn(tree_file)) {
    if (!std::binary_search(without.begin(), without.end(), type)) return true;
  }
  return false;
}

planning::PlannerOptions defaultNavPlannerOptions() {
  planning::PlannerOptions options;
  options.algorithm = planning::Algorithm::kRrtConnect;
  options.collision = planning::CollisionCheck::kSegments;
  options.step = 0.2;
  options.max_iterations = 20000;
  options.goal_tolerance = 1e-3;
  options.smooth = true;
  options.smoothing_tries = 300;
  return options;
}

planning::PlannerOptions navPlannerOptions(const planning::Problem& world) {
  constexpr double kRoomDiagonal = 20;    // m: a room or a flat; larger is a building's floor
  constexpr double kAreaPerBatch = 100;   // m² planned with the default iterations
  constexpr int kMaxIterations = 200000;  // about 0.2 s of RRT-Connect in a large map
  planning::PlannerOptions options = defaultNavPlannerOptions();
  const planning::Bounds& b = world.bounds;
  const double width = b.x_max - b.x_min, height = b.y_max - b.y_min;
  const double diagonal = std::hypot(width, height);
  if (!(diagonal > kRoomDiagonal)) return options;
  options.step = std::max(options.step, diagonal / 100);
  const double batches = std::ceil(width * height / kAreaPerBatch);
  options.max_iterations = static_cast<int>(
      std::min<double>(kMaxIterations, options.max_iterations * std::max(1.0, batches)));
  return options;
}

NavLeafConfig inProcessNavConfig(const planning::Problem& world,
                                 const planning::PlannerOptions& options,
                                 InProcessPlanner::Mode mode) {
  InProcessPlanner::validate(world, options);  // before any tree is built
  NavLeafConfig config;
  config.planners = [world, options, mode] {
    return std::make_unique<InProcessPlanner>(world, options, mode);
  };
  config.known_world = std::make_shared<PathChecker>(world);
  return config;
}

NavBt::NavBt(const NavLeafConfig& config, std::uint32_t seed, const std::string& tree_file)
    : NavBt(config, seed, tree_file, tree_file, true) {}

NavBt::NavBt(const NavLeafConfig& config, std::uint32_t seed, const std::string& xml,
             const std::string& source)
    : NavBt(config, seed, xml, source, false) {}

NavBt::NavBt(const NavLeafConfig& config, std::uint32_t seed, const std::string& text,
             const std::string& source, bool from_file)
    : context_(seed),
      params_(config.params),
      board_(makeBoard()),
      goal_(&board_->declare<robot::Pose2D>("goal")),
      pose_(&board_->declare<robot::Pose2D>("pose")),
      predictor_(config.pose_latency, config.params.rate),
      latency_(config.params.rate),
      tree_(buildTree(config, context_, text, source, from_file, board_)) {
  context_.state_name = &kIdle;
  context_.params = &params_;
  context_.follower = config.follower;
}

void NavBt::setFollowerParams(const FollowerParams& params) {
  FollowerParams next = params;
  next.rate = context_.follower.rate;
  validate(next);
  context_.follower = next;
  ++context_.follower_version;
}

void NavBt::setRoombaParams(const behavior::RoombaParams& params) {
  behavior::retuneMotions(params_, params, context_);
}

void NavBt::setGoal(const robot::Pose2D& goal) {
  for (const auto& [field, value] : {std::pair<const char*, double>{"goal.x", goal.x},
                                     {"goal.y", goal.y},
                                     {"goal.theta", goal.theta}}) {
    if (!std::isfinite(value)) throw util::InvalidInput(field, "must be finite");
  }
  tree_.halt();
  goal_->set(goal);
  context_.outcome = GoalOutcome::kActive;
  context_.message.clear();
}

void NavBt::cancelGoal() {
  tree_.halt();
  goal_->clear();
  if (context_.outcome == GoalOutcome::kActive) context_.outcome = GoalOutcome::kNone;
}

robot::Velocity NavBt::tick(const robot::BumperState& bumper, const robot::Pose2D& pose) {
  context_.bumper = bumper;
  context_.speed_scale = LatencySpeedPolicy::scale(latency_.ticks());
  pose_->set(predictor_.predict(pose));
  context_.cmd = robot::Velocity{};
  const bt::Status status = tree_.tick();
  if (status != bt::Status::kRunning && context_.outcome == GoalOutcome::kActive && goal_->get()) {
    goal_->clear();
    if (status == bt::Status::kSuccess) {
      context_.outcome = GoalOutcome::kSucceeded;
    } else {
      const bt::Blackboard::EntryBase* entry = board_->find("error");
      const std::string* error =
          entry && entry->type == typeid(std::string) ? board_->get<std::string>("error") : nullptr;
      context_.outcome = GoalOutcome::kAborted;
      context_.message = error                            ? *error
                         : status == bt::Status::kSkipped ? "the navigation tree skipped the goal"
                                                          : "the navigation tree failed";
    }
  }
  idle_ = context_.outcome != GoalOutcome::kActive && status != bt::Status::kRunning &&
          context_.cmd.v == 0 && context_.cmd.w == 0;
  context_.previous_cmd = context_.cmd;
  predictor_.sent(context_.cmd);
  return context_.cmd;
}

}  // namespace roomba_rrt::navigation
