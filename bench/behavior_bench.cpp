// Nanoseconds per tick of the lab's Roomba behaviour: the BT (lab tree, root tick), the FSM and
// a hand-written switch with the same logic (bench/roomba_switch.h), on the same bumper input.
//
//   cmake --build <build-dir> --target behavior_bench &&
//   <build-dir>/devel/lib/roomba_rrt/behavior_bench
#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <vector>

#include "roomba_rrt/behavior/roomba_bt.h"
#include "roomba_rrt/behavior/roomba_fsm.h"
#include "roomba_rrt/behavior/roomba_tree.h"
#include "roomba_rrt/navigation/nav_bt.h"
#include "roomba_rrt/robot/unicycle.h"
#include "roomba_rrt/world/world.h"
#include "roomba_rrt/world/world_file.h"
#include "roomba_rrt/world_planning/room_problem.h"
#include "roomba_switch.h"

namespace {

using roomba_rrt::behavior::RoombaBt;
using roomba_rrt::behavior::RoombaFsm;
using roomba_rrt::behavior::RoombaParams;
using roomba_rrt::bench::RoombaSwitch;
namespace robot = roomba_rrt::robot;

/// A bumper input that exercises every transition: a bump every 997 ticks (during MoveForward
/// or MoveInSpiral), and some spirals that run to their end. 2^16 ticks, then it repeats.
const std::vector<robot::BumperState>& bumperInput() {
  static const std::vector<robot::BumperState> input = [] {
    std::vector<robot::BumperState> v(1 << 16);
    for (std::size_t i = 0; i < v.size(); ++i) {
      const bool pressed = i % 997 == 0 && (i / 997) % 3 != 0;
      v[i] = {pressed, pressed, pressed};
    }
    return v;
  }();
  return input;
}

template <class Behavior>
void tickLoop(benchmark::State& state, Behavior& behavior) {
  const std::vector<robot::BumperState>& input = bumperInput();
  const std::size_t mask = input.size() - 1;
  std::size_t i = 0;
  for (auto _ : state) {
    robot::Velocity cmd = behavior.tick(input[i++ & mask]);
    benchmark::DoNotOptimize(cmd);
  }
  state.SetItemsProcessed(state.iterations());
}

void BM_Switch(benchmark::State& state) {
  RoombaSwitch roomba(RoombaParams{}, 1);
  tickLoop(state, roomba);
}
BENCHMARK(BM_Switch);

void BM_Fsm(benchmark::State& state) {
  RoombaFsm roomba(RoombaParams{}, 1);
  tickLoop(state, roomba);
}
BENCHMARK(BM_Fsm);

void BM_BtLabTree(benchmark::State& state) {
  RoombaBt roomba(RoombaParams{}, 1);
  tickLoop(state, roomba);
}
BENCHMARK(BM_BtLabTree);

void BM_BtBuildFromXml(benchmark::State& state) {
  for (auto _ : state) {
    RoombaBt roomba(RoombaParams{}, 1);
    benchmark::DoNotOptimize(&roomba);
  }
}
BENCHMARK(BM_BtBuildFromXml)->Unit(benchmark::kMicrosecond);

/// The in-process planner with its planning left out of the timing: the benchmark ticks about a
/// million times faster than 60 Hz, so a worker thread's plan would arrive far too late (the
/// robot would have driven on for thousands of ticks); this plans inline with the clock paused.
class UntimedPlanner final : public roomba_rrt::navigation::PathPlanner {
 public:
  /// Pauses `state` while planning when `*timed` is true (inside the timed loop).
  UntimedPlanner(const roomba_rrt::planning::Problem& world, benchmark::State& state,
                 const bool& timed)
      : inner_(world, roomba_rrt::navigation::defaultNavPlannerOptions(),
               roomba_rrt::navigation::InProcessPlanner::Mode::kInline),
        state_(state),
        timed_(timed) {}
  void request(const roomba_rrt::planning::Point2& start,
               const roomba_rrt::planning::Point2& goal) override {
    if (timed_) state_.PauseTiming();
    inner_.request(start, goal);
    if (timed_) state_.ResumeTiming();
  }
  bool poll(roomba_rrt::navigation::PlanReply& reply) override { return inner_.poll(reply); }
  void cancel() override { inner_.cancel(); }

 private:
  roomba_rrt::navigation::InProcessPlanner inner_;
  benchmark::State& state_;
  const bool& timed_;
};

/// A navigation-tree tick while following a 4.7 m path across the furnished room
/// (config/roomba_nav_tree.xml, replanning every 2 s; IsPathValid checks the path against all
/// furniture twice a second), back and forth between its two ends. Planning is excluded
/// (UntimedPlanner). The robot's pose comes from the exact unicycle step (about 20 ns of the
/// time); each new goal is set and planned outside the timing.
void BM_NavTreeFollowing(benchmark::State& state) {
  using namespace roomba_rrt::navigation;
  roomba_rrt::planning::Problem room = roomba_rrt::world_planning::roomProblem(
      roomba_rrt::world::loadWorld(ROOMBA_RRT_CONFIG_DIR "/roomba_world_furnished.yaml"));
  room.clearance = kDefaultClearance;
  NavLeafConfig config = inProcessNavConfig(room);
  bool timed = false;
  config.planners = [&room, &state, &timed] {
    return std::make_unique<UntimedPlanner>(room, state, timed);
  };
  NavBt nav(config, 1, ROOMBA_RRT_CONFIG_DIR "/roomba_nav_tree.xml");
  const robot::Pose2D ends[2] = {{0.5, 2.4, 0.0}, {5.2, 2.4, M_PI}};
  int leg = 0;  // heading for ends[leg]
  robot::Pose2D pose = ends[0];
  // The next leg's goal, ticked until the robot follows its plan; false (the benchmark skipped,
  // saying why) when it never does. The robot drives, it is never moved by hand: a path
  // planned for one place is never followed from another.
  const auto next_leg = [&] {
    timed = false;
    leg = 1 - leg;
    nav.setGoal(ends[leg]);
    int tick = 0;
    do {
      nav.tick({}, pose);  // the first tick after setGoal runs ComputePath
    } while (++tick < 600 && nav.stateName() != "FollowPath");
    timed = true;
    if (nav.stateName() == "FollowPath") return true;
    state.SkipWithError(("no path to follow: " + nav.stateName() + ", " + nav.message()).c_str());
    return false;
  };
  if (!next_leg()) return;
  long following = 0;
  for (auto _ : state) {
    const robot::Velocity cmd = nav.tick({}, pose);
    pose = robot::integrateArc(pose, cmd, 1.0 / 60.0);
    following += nav.stateName() == "FollowPath";
    if (nav.outcome() != GoalOutcome::kActive || std::abs(pose.x - ends[leg].x) < 0.6) {
      state.PauseTiming();
      const bool planned = next_leg();
      state.ResumeTiming();
      if (!planned) break;
    }
  }
  state.counters["following_pct"] = 100.0 * following / static_cast<double>(state.iterations());
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_NavTreeFollowing);

/// The switch must be the FSM's logic, or the comparison means nothing: 10 minutes of ticks.
bool switchAgreesWithFsm() {
  RoombaSwitch baseline(RoombaParams{}, 1);
  RoombaFsm fsm(RoombaParams{}, 1);
  const std::vector<robot::BumperState>& input = bumperInput();
  for (std::size_t i = 0; i < 36000; ++i) {
    const robot::Velocity a = baseline.tick(input[i]), b = fsm.tick(input[i]);
    if (a.v != b.v || a.w != b.w || baseline.state() != fsm.state()) {
      std::fprintf(stderr, "behavior_bench: the switch and the FSM differ at tick %zu\n", i);
      return false;
    }
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  if (!switchAgreesWithFsm()) return 1;
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
