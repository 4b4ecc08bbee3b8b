// roomba_bt with the navigation tree through a real master: roomba_sim in the furnished room
// (config/roomba_world_furnished.yaml, simulated time faster than real time), rrt_planner on the
// same world behind ComputePath (the node's default ~planner "service").
//
// NavGoalTopic (nav_goal.test): a PoseStamped on /move_base_simple/goal, as rviz's 2D Nav Goal
// sends it, to a point behind the bench (between the bench and the wall: 6 cm of room for the
// robot's centre) gets the robot there within tolerance, the bumper never pressed.
//
// NavAction (nav_action.test): move_base's action: SUCCEEDED at the goal; a goal inside the sofa
// ABORTED at once with a message naming it, the robot standing still; a goal in an unknown frame
// or with NaN refused with a message; a second goal preempts the first; a cancel stops the robot
// within 0.1 s of robot time.
//
// NavTwoRobots (nav_two_robots.test, issue 13): two named robots in one roomba_sim, each with its
// own roomba_bt under its namespace (as `scripts/run --robots 2 nav` starts them), one shared
// rrt_planner: a goal to each robot's /<name>/move_base at the same time, and each robot reaches
// its own goal.
//
// NavMap (nav_map.test): a map world, roomba_sim publishing /map and rrt_planner (no world file)
// planning on it, roomba_bt asking for its plans in the planner's scenario map:
// ~make_plan between rooms (every edge checked against the map file here, not by the planner's
// checker; a pose every map cell), a goal in a wall relaxed only by the request's tolerance, and a
// goal in another room reached through the doorway without a bump.
//
// NavUnknown (nav_unknown.test, issue 43 item 4): roomba_sim keeps its map to itself, roomba_mapper
// builds /map, roomba_bt (~unknown, the navigation tree) plans on the map it builds from /scan:
// three goals across the furnished room reached without a bump, and a goal a million metres
// away refused naming it.
//
// NavKnownMap, CleanKnownMap (nav_known_map.test, clean_known_map.test, issue 43 items 3-5):
// the same with ~known_map, a stale map of the home (its walls, not its furniture): a 2D Nav
// Goal and an action goal in the apartment's other rooms reached through its doors without a
// bump; the furnished room cleaned from its walls' map; the map given served latched on
// /roomba_bt/known_map.
#include <actionlib/client/simple_action_client.h>
#include <geometry_msgs/PoseStamped.h>
#include <gtest/gtest.h>
#include <move_base_msgs/MoveBaseAction.h>
#include <nav_msgs/GetPlan.h>
#include <nav_msgs/OccupancyGrid.h>
#include <nav_msgs/Odometry.h>
#include <nav_msgs/Path.h>
#include <roomba_rrt/Bumper.h>
#include <ros/ros.h>
#include <ros/topic.h>
#include <std_msgs/Float32.h>
#include <std_msgs/String.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "roomba_rrt/geometry/map_file.h"
#include "roomba_rrt/geometry/occupancy_grid.h"

namespace {

using Client = actionlib::SimpleActionClient<move_base_msgs::MoveBaseAction>;
using actionlib::SimpleClientGoalState;

constexpr double kXyTolerance = 0.05;  // the follower's default, m
constexpr double kWallTimeout = 40.0;  // s of wall time per goal (a loaded 2-core machine)
// s of wall time for the whole cleaning (about 360 s of robot time at 5x: 72 s when unloaded)
constexpr double kCleanWallTimeout = 240.0;

/// What the simulator says about the robot (a named robot's topics with `ns` = "/robot1").
class Robot {
 public:
  explicit Robot(const std::string& ns = "") {
    ros::NodeHandle nh;
    odom_sub_ = nh.subscribe(ns + "/odom", 100, &Robot::onOdom, this);
    bumper_sub_ = nh.subscribe(ns + "/bumper", 100, &Robot::onBumper, this);
    state_sub_ = nh.subscribe(ns + "/roomba_bt/state", 10, &Robot::onState, this);
  }
  std::string state() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return state_;
  }
  struct Sample {
    double x = std::numeric_limits<double>::quiet_NaN(), y = x, v = 0, w = 0;
    ros::Time stamp;
  };
  Sample latest() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return latest_;
  }
  bool everPressed() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return pressed_;
  }
  /// Times the bumper was pressed (a press lasting several messages counts once).
  int bumps() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return bumps_;
  }
  /// Robot time of the first /odom at or after `since` that shows the robot stopped (v = w = 0).
  ros::Time stoppedSince(const ros::Time& since) const {
    std::lock_guard<std::mutex> lock(mutex_);
    return since <= stopped_since_ ? stopped_since_ : ros::Time();
  }
  void watchStop() {
    std::lock_guard<std::mutex> lock(mutex_);
    stopped_since_ = ros::Time();
  }

 private:
  void onOdom(const nav_msgs::Odometry& msg) {
    std::lock_guard<std::mutex> lock(mutex_);
    latest_ = {msg.pose.pose.position.x, msg.pose.pose.position.y, msg.twist.twist.linear.x,
               msg.twist.twist.angular.z, msg.header.stamp};
    const bool stopped = latest_.v == 0 && latest_.w == 0;
    if (!stopped) stopped_since_ = ros::Time();
    if (stopped && stopped_since_.isZero()) stopped_since_ = msg.header.stamp;
  }
  void onState(const std_msgs::String& msg) {
    std::lock_guard<std::mutex> lock(mutex_);
    state_ = msg.data;
  }
  void onBumper(const roomba_rrt::Bumper& msg) {
    std::lock_guard<std::mutex> lock(mutex_);
    bumps_ += msg.pressed && !pressing_;
    pressing_ = msg.pressed;
    pressed_ = pressed_ || msg.pressed;
  }

  mutable std::mutex mutex_;
  Sample latest_;
  bool pressed_ = false, pressing_ = false;
  int bumps_ = 0;
  ros::Time stopped_since_;
  std::string state_;
  ros::Subscriber odom_sub_, bumper_sub_, state_sub_;
};

/// Waits (wall time) until `done` or the timeout; true when done.
bool waitFor(const std::function<bool()>& done, double wall_seconds) {
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(wall_seconds);
  while (ros::ok() && ros::WallTime::now() < deadline) {
    if (done()) return true;
    ros::WallDuration(0.005).sleep();
  }
  return done();
}

move_base_msgs::MoveBaseGoal goalAt(double x, double y, double yaw = 0,
                                    const std::string& frame = "map") {
  move_base_msgs::MoveBaseGoal goal;
  goal.target_pose.header.frame_id = frame;
  goal.target_pose.pose.position.x = x;
  goal.target_pose.pose.position.y = y;
  goal.target_pose.pose.orientation.z = std::sin(0.5 * yaw);
  goal.target_pose.pose.orientation.w = std::cos(0.5 * yaw);
  return goal;
}

double distanceTo(const Robot& robot, double x, double y) {
  const Robot::Sample s = robot.latest();
  return std::hypot(s.x - x, s.y - y);
}

/// The simulator runs, the action server is up.
class Nav : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    spinner_ = std::make_unique<ros::AsyncSpinner>(1);
    spinner_->start();
  }
  void SetUp() override {
    ASSERT_TRUE(waitFor([&] { return !std::isnan(robot_.latest().x); }, 30.0)) << "no /odom";
    client_ = std::make_unique<Client>("move_base", true);
    ASSERT_TRUE(client_->waitForServer(ros::Duration(30.0))) << "no move_base action server";
  }
  /// Sends a goal and waits (wall time) for its end.
  SimpleClientGoalState run(Client& client, const move_base_msgs::MoveBaseGoal& goal) {
    client.sendGoal(goal);
    waitFor([&] { return client.getState().isDone(); }, kWallTimeout);
    return client.getState();
  }
  /// Publishes a 2D Nav Goal as rviz does and waits (wall time) until the robot stands within
  /// `tolerance` of it, at least a second of robot time after `start` (which it returns); true
  /// when it did.
  bool navGoal(double x, double y, double yaw, double tolerance, ros::Time* start) {
    ros::NodeHandle nh;
    ros::Publisher pub = nh.advertise<geometry_msgs::PoseStamped>("/move_base_simple/goal", 1);
    if (!waitFor([&] { return pub.getNumSubscribers() > 0; }, 30.0)) return false;
    geometry_msgs::PoseStamped goal = goalAt(x, y, yaw).target_pose;
    goal.header.stamp = ros::Time::now();
    *start = ros::Time::now();
    pub.publish(goal);
    // Arrived: within tolerance and stopped (the follower turns to the heading, then stops).
    return waitFor(
        [&] {
          const Robot::Sample s = robot_.latest();
          return std::hypot(s.x - x, s.y - y) < tolerance && s.v == 0 && s.w == 0 &&
                 (s.stamp - *start).toSec() > 1.0;
        },
        kWallTimeout);
  }

  static std::unique_ptr<ros::AsyncSpinner> spinner_;
  Robot robot_;
  std::unique_ptr<Client> client_;
};
std::unique_ptr<ros::AsyncSpinner> Nav::spinner_;

TEST_F(Nav, nav_goal_behind_the_bench_is_reached_without_a_bump) {
  ros::Time start;
  const bool arrived = navGoal(3.0, 4.55, M_PI, kXyTolerance + 0.01, &start);
  const Robot::Sample s = robot_.latest();
  EXPECT_TRUE(arrived) << "the robot is at (" << s.x << ", " << s.y << ") after "
                       << (s.stamp - start).toSec() << " s of robot time";
  EXPECT_FALSE(robot_.everPressed()) << "the bumper was pressed on the way";
  std::printf("behind the bench: (%.3f, %.3f) after %.1f s of robot time\n", s.x, s.y,
              (s.stamp - start).toSec());
}

TEST_F(Nav, action_goal_succeeds_at_the_goal) {
  const SimpleClientGoalState state = run(*client_, goalAt(1.2, 2.0, M_PI_2));
  EXPECT_EQ(state, SimpleClientGoalState::SUCCEEDED) << state.getText();
  EXPECT_LT(distanceTo(robot_, 1.2, 2.0), kXyTolerance + 0.01);
  EXPECT_FALSE(robot_.everPressed());
  // ~state: the robot at its goal is Idle, not the last leaf.
  EXPECT_TRUE(waitFor([&] { return robot_.state() == "Idle"; }, 5.0)) << robot_.state();
}

TEST_F(Nav, goal_inside_the_sofa_is_aborted_with_a_message_and_the_robot_stays_still) {
  const Robot::Sample before = robot_.latest();
  const SimpleClientGoalState state = run(*client_, goalAt(0.8, 0.3));
  EXPECT_EQ(state, SimpleClientGoalState::ABORTED);
  EXPECT_NE(state.getText().find("inside furniture"), std::string::npos) << state.getText();
  ros::WallDuration(0.5).sleep();
  const Robot::Sample after = robot_.latest();
  EXPECT_LT(std::hypot(after.x - before.x, after.y - before.y), 1e-3);
  EXPECT_EQ(after.v, 0.0);
}

TEST_F(Nav, nan_goal_and_unknown_frame_are_refused_with_a_message) {
  SimpleClientGoalState state = run(*client_, goalAt(std::nan(""), 2.0));
  EXPECT_EQ(state, SimpleClientGoalState::ABORTED);
  EXPECT_NE(state.getText().find("position.x: not finite"), std::string::npos) << state.getText();
  state = run(*client_, goalAt(2.0, 2.0, 0, "no_such_frame"));
  EXPECT_EQ(state, SimpleClientGoalState::ABORTED);
  EXPECT_NE(state.getText().find("no_such_frame"), std::string::npos) << state.getText();
}

TEST_F(Nav, goal_in_the_odom_frame_is_transformed) {
  // roomba_sim's map -> odom is the identity: the same point, through tf2.
  const SimpleClientGoalState state = run(*client_, goalAt(3.2, 2.4, 0, "odom"));
  EXPECT_EQ(state, SimpleClientGoalState::SUCCEEDED) << state.getText();
  EXPECT_LT(distanceTo(robot_, 3.2, 2.4), kXyTolerance + 0.01);
}

TEST_F(Nav, a_second_goal_preempts_the_first) {
  Client second("move_base", true);
  ASSERT_TRUE(second.waitForServer(ros::Duration(30.0)));
  const Robot::Sample start = robot_.latest();
  client_->sendGoal(goalAt(5.0, 2.4));
  ASSERT_TRUE(waitFor([&] { return distanceTo(robot_, start.x, start.y) > 0.2; }, kWallTimeout))
      << "the first goal did not get the robot moving";
  const SimpleClientGoalState state = run(second, goalAt(2.0, 1.5));
  EXPECT_EQ(client_->getState(), SimpleClientGoalState::PREEMPTED);
  EXPECT_EQ(state, SimpleClientGoalState::SUCCEEDED) << state.getText();
  EXPECT_LT(distanceTo(robot_, 2.0, 1.5), kXyTolerance + 0.01);
}

TEST_F(Nav, a_cancel_stops_the_robot_within_a_tenth_of_a_second) {
  const Robot::Sample start = robot_.latest();
  client_->sendGoal(goalAt(5.0, 2.4));
  ASSERT_TRUE(waitFor(
      [&] {
        const Robot::Sample s = robot_.latest();
        return std::hypot(s.x - start.x, s.y - start.y) > 0.3 && s.v > 0.1;
      },
      kWallTimeout))
      << "the goal did not get the robot driving";
  robot_.watchStop();
  const ros::Time canceled = ros::Time::now();
  client_->cancelGoal();
  ASSERT_TRUE(waitFor([&] { return client_->getState().isDone(); }, 10.0));
  EXPECT_EQ(client_->getState(), SimpleClientGoalState::PREEMPTED);
  ros::Time stopped;
  ASSERT_TRUE(waitFor([&] { return !(stopped = robot_.stoppedSince(canceled)).isZero(); }, 5.0))
      << "the robot did not stop";
  EXPECT_LE((stopped - canceled).toSec(), 0.1);
  std::printf("cancel: stopped %.3f s of robot time after the cancel\n",
              (stopped - canceled).toSec());
  // And stays stopped.
  ros::WallDuration(0.3).sleep();
  EXPECT_EQ(robot_.latest().v, 0.0);
}

TEST(NavTwoRobots, each_robot_reaches_its_own_goal) {
  ros::AsyncSpinner spinner(1);
  spinner.start();
  struct Task {
    std::string name;
    double x, y;  // its goal; config/roomba_world_two_robots.yaml: robot1 at (1.6, 2.4), robot2
  };              // at (4.8, 2.4): the two paths do not cross
  const Task tasks[] = {{"robot1", 1.0, 4.0}, {"robot2", 5.6, 0.8}};
  std::vector<std::unique_ptr<Robot>> robots;
  std::vector<std::unique_ptr<Client>> clients;
  for (const Task& task : tasks) {
    robots.push_back(std::make_unique<Robot>("/" + task.name));
    const Robot& robot = *robots.back();
    ASSERT_TRUE(waitFor([&] { return !std::isnan(robot.latest().x); }, 30.0))
        << "no /" << task.name << "/odom";
    clients.push_back(std::make_unique<Client>("/" + task.name + "/move_base", true));
    ASSERT_TRUE(clients.back()->waitForServer(ros::Duration(30.0)))
        << "no /" << task.name << "/move_base action server";
  }
  for (std::size_t i = 0; i < clients.size(); ++i) {
    clients[i]->sendGoal(goalAt(tasks[i].x, tasks[i].y));
  }
  const ros::Time start = ros::Time::now();
  waitFor(
      [&] {
        return std::all_of(clients.begin(), clients.end(),
                           [](const auto& c) { return c->getState().isDone(); });
      },
      kWallTimeout);
  std::printf("both goals done after %.1f s of robot time\n", (ros::Time::now() - start).toSec());
  for (std::size_t i = 0; i < clients.size(); ++i) {
    const Robot::Sample s = robots[i]->latest();
    EXPECT_EQ(clients[i]->getState(), SimpleClientGoalState::SUCCEEDED)
        << tasks[i].name << ": " << clients[i]->getState().getText();
    EXPECT_LT(std::hypot(s.x - tasks[i].x, s.y - tasks[i].y), kXyTolerance + 0.01)
        << tasks[i].name << " is at (" << s.x << ", " << s.y << ")";
    EXPECT_FALSE(robots[i]->everPressed()) << tasks[i].name << " bumped into something";
    std::printf("%s: at (%.3f, %.3f), its goal (%.1f, %.1f)\n", tasks[i].name.c_str(), s.x, s.y,
                tasks[i].x, tasks[i].y);
  }
}

/// A map world (nav_map.test): the map file (to check plans against, independently of the
/// planner) and a goal in another room, from the test's private parameters.
class NavMap : public Nav {
 protected:
  void SetUp() override {
    Nav::SetUp();
    ros::NodeHandle pnh("~");
    ASSERT_TRUE(pnh.getParam("map_file", map_file_));
    ASSERT_TRUE(pnh.getParam("goal_x", goal_x_));
    ASSERT_TRUE(pnh.getParam("goal_y", goal_y_));
    grid_ = roomba_rrt::geometry::loadMap(map_file_).grid;
    ASSERT_TRUE(ros::service::waitForService("/rrt_planner/make_plan", ros::Duration(30)));
  }
  /// A make_plan request from where the robot is (its start in `start_frame`) to (x, y).
  nav_msgs::GetPlan::Request planRequest(double x, double y, double tolerance,
                                         const std::string& start_frame = "map") {
    nav_msgs::GetPlan::Request request;
    const Robot::Sample s = robot_.latest();
    request.start.header.frame_id = start_frame;
    request.start.pose.position.x = s.x;
    request.start.pose.position.y = s.y;
    request.goal = goalAt(x, y).target_pose;
    request.tolerance = static_cast<float>(tolerance);
    return request;
  }
  nav_msgs::GetPlan::Response makePlan(const nav_msgs::GetPlan::Request& request) {
    nav_msgs::GetPlan srv;
    srv.request = request;
    EXPECT_TRUE(ros::service::call("/rrt_planner/make_plan", srv));
    return srv.response;
  }
  nav_msgs::GetPlan::Response makePlan(double x, double y, double tolerance,
                                       const std::string& start_frame = "map") {
    return makePlan(planRequest(x, y, tolerance, start_frame));
  }
  /// Every edge of the plan keeps the Roomba's radius from every blocked cell's square, and the
  /// poses are at most a map cell apart (navfn's spacing: local planners prune the plan to their
  /// window).
  void expectClear(const nav_msgs::Path& plan) {
    ASSERT_FALSE(plan.poses.empty());
    EXPECT_EQ(plan.header.frame_id, "map");
    for (std::size_t i = 1; i < plan.poses.size(); ++i) {
      const auto& a = plan.poses[i - 1].pose.position;
      const auto& b = plan.poses[i].pose.position;
      const roomba_rrt::geometry::Segment edge{{a.x, a.y}, {b.x, b.y}};
      EXPECT_FALSE(roomba_rrt::geometry::segmentMeetsBlocked(grid_, edge, kRoombaRadius))
          << "edge " << i << " (" << a.x << ", " << a.y << ") - (" << b.x << ", " << b.y << ")";
      // A cell as the planner has it: nav_msgs/OccupancyGrid's resolution is a float32
      // (0.1 f = 0.1000000015 m), and an edge between cell centres is an exact number of them.
      const double cell = static_cast<float>(grid_.resolution);
      ASSERT_LE(std::hypot(b.x - a.x, b.y - a.y), cell + 1e-9)
          << "poses " << i - 1 << " and " << i << " are more than a cell apart";
    }
  }

  static constexpr double kRoombaRadius = 0.17;
  std::string map_file_;
  double goal_x_ = 0, goal_y_ = 0;
  roomba_rrt::geometry::OccupancyGrid grid_;
};

TEST_F(NavMap, make_plan_between_rooms_keeps_the_radius_from_every_cell) {
  const nav_msgs::GetPlan::Response answer = makePlan(goal_x_, goal_y_, 0.0);
  expectClear(answer.plan);
  ASSERT_FALSE(answer.plan.poses.empty());
  const auto& last = answer.plan.poses.back().pose.position;
  EXPECT_LT(std::hypot(last.x - goal_x_, last.y - goal_y_), 1e-3);
  // The same from a start given in odom (the simulator's map -> odom, through tf2).
  expectClear(makePlan(goal_x_, goal_y_, 0.0, "odom").plan);
}

TEST_F(NavMap, make_plan_relaxes_a_goal_in_a_wall_by_its_tolerance_and_only_then) {
  // The first blocked cell right of the goal: its centre is in a wall.
  int i = grid_.column(goal_x_);
  const int j = grid_.row(goal_y_);
  while (!grid_.blocked(i, j)) ++i;
  const double wall_x = grid_.origin.x + (i + 0.5) * grid_.resolution;
  EXPECT_TRUE(makePlan(wall_x, goal_y_, 0.0).plan.poses.empty());
  const nav_msgs::Path relaxed = makePlan(wall_x, goal_y_, 1.0).plan;
  expectClear(relaxed);
  ASSERT_FALSE(relaxed.poses.empty());
  const auto& last = relaxed.poses.back().pose.position;
  EXPECT_LE(std::abs(last.x - wall_x), 1.0 + 1e-9);  // navfn's square of tolerance
  EXPECT_LE(std::abs(last.y - goal_y_), 1.0 + 1e-9);
}

TEST_F(NavMap, make_plan_takes_a_huge_but_finite_goal_orientation_as_its_heading) {
  // 1e300 in every component: (0.5, 0.5, 0.5, 0.5) scaled, a quarter turn. Squaring it overflows;
  // the plan's poses must still be finite and the last one face +y.
  nav_msgs::GetPlan::Request request = planRequest(goal_x_, goal_y_, 0.0);
  auto& q = request.goal.pose.orientation;
  q.x = q.y = q.z = q.w = 1e300;
  const nav_msgs::Path plan = makePlan(request).plan;
  expectClear(plan);
  ASSERT_FALSE(plan.poses.empty());
  for (const auto& pose : plan.poses) {
    const auto& o = pose.pose.orientation;
    ASSERT_TRUE(std::isfinite(o.x) && std::isfinite(o.y) && std::isfinite(o.z) &&
                std::isfinite(o.w));
  }
  const auto& last = plan.poses.back().pose.orientation;
  EXPECT_NEAR(2 * std::atan2(last.z, last.w), M_PI_2, 1e-9);
}

TEST_F(NavMap, a_goal_in_another_room_is_reached_through_the_doorway_without_a_bump) {
  EXPECT_EQ(run(*client_, goalAt(goal_x_, goal_y_)), SimpleClientGoalState::SUCCEEDED)
      << client_->getState().getText();
  EXPECT_LT(distanceTo(robot_, goal_x_, goal_y_), kXyTolerance + 0.01);
  EXPECT_FALSE(robot_.everPressed());
}

/// roomba_bt with the cleaning tree (clean.test): it cleans the furnished room and stops.
class Clean : public Nav {};

/// What a cleaning run over ROS showed: /roomba_sim/coverage and roomba_bt's ~coverage_path, from
/// the first plan (within `rows_timeout` s of wall time) until ~state reads Idle with nothing left
/// to drive (within `timeout` s).
struct Cleaned {
  bool planned = false, done = false;
  std::size_t planned_points = 0, points_left = 0;
  double coverage = 0;
};

Cleaned cleanUntilDone(const Robot& robot, double rows_timeout, double timeout) {
  ros::NodeHandle nh;
  std::mutex mutex;
  Cleaned out;
  ros::Subscriber coverage_sub = nh.subscribe<std_msgs::Float32>(
      "/roomba_sim/coverage", 10, [&](const std_msgs::Float32::ConstPtr& m) {
        std::lock_guard<std::mutex> lock(mutex);
        out.coverage = m->data;
      });
  ros::Subscriber rows_sub = nh.subscribe<nav_msgs::Path>("/roomba_bt/coverage_path", 10,
                                                          [&](const nav_msgs::Path::ConstPtr& m) {
                                                            std::lock_guard<std::mutex> lock(mutex);
                                                            if (!out.planned)
                                                              out.planned_points = m->poses.size();
                                                            out.points_left = m->poses.size();
                                                            out.planned = true;
                                                          });
  const auto locked = [&](auto&& f) {
    std::lock_guard<std::mutex> lock(mutex);
    return f();
  };
  if (!waitFor([&] { return locked([&] { return out.planned; }); }, rows_timeout)) {
    return locked([&] { return out; });
  }
  // Done: Idle and standing, with nothing left on ~coverage_path.
  waitFor([&] { return locked([&] { return robot.state() == "Idle" && out.points_left == 0; }); },
          timeout);
  return locked([&] {
    out.done = robot.state() == "Idle" && out.points_left == 0;
    std::printf(
        "cleaning: %s after %.0f s of robot time, coverage %.1f %%, %zu of %zu path "
        "points left, %d bumps\n",
        out.done ? "done" : "not done", ros::Time::now().toSec(), 100 * out.coverage,
        out.points_left, out.planned_points, robot.bumps());
    return out;
  });
}

/// It comes to rest (odometry is a step behind the command) and stays there, Idle.
void expectStandingStill(const Robot& robot) {
  const auto standing = [&] { return robot.latest().v == 0 && robot.latest().w == 0; };
  EXPECT_TRUE(waitFor(standing, 5.0)) << "v " << robot.latest().v << ", w " << robot.latest().w;
  ros::WallDuration(1.0).sleep();
  EXPECT_TRUE(standing()) << "moving again: v " << robot.latest().v;
  EXPECT_EQ(robot.state(), "Idle");
}

TEST_F(Clean, the_cleaning_tree_covers_90_percent_of_the_floor_then_stands_still) {
  // The plan's rows are published as soon as it is made.
  const Cleaned cleaned = cleanUntilDone(robot_, 30.0, kCleanWallTimeout);
  ASSERT_TRUE(cleaned.planned) << "no plan on ~coverage_path";
  EXPECT_GT(cleaned.planned_points, 50u) << "the furnished room's plan has some 50 legs";
  ASSERT_TRUE(cleaned.done) << "still " << robot_.state() << " at coverage " << cleaned.coverage;
  EXPECT_GE(cleaned.coverage, 0.90);
  EXPECT_FALSE(robot_.everPressed());
  expectStandingStill(robot_);
}

/// How many cells of /map are known (free or occupied): in the first map and the latest.
class KnownCells {
 public:
  KnownCells() { sub_ = ros::NodeHandle().subscribe("/map", 10, &KnownCells::onMap, this); }
  std::size_t firstKnown() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return first_;
  }
  std::size_t known() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return latest_;
  }

 private:
  void onMap(const nav_msgs::OccupancyGrid::ConstPtr& m) {
    std::lock_guard<std::mutex> lock(mutex_);
    latest_ = static_cast<std::size_t>(
        std::count_if(m->data.begin(), m->data.end(), [](std::int8_t v) { return v >= 0; }));
    if (first_ == 0) first_ = latest_;
  }
  mutable std::mutex mutex_;
  std::size_t first_ = 0, latest_ = 0;
  ros::Subscriber sub_;
};

class CleanUnknown : public Nav {};

TEST_F(CleanUnknown, explores_maps_and_cleans_90_percent_of_a_room_it_has_never_seen) {
  // roomba_sim keeps its map to itself: the only /map is roomba_mapper's, and it grows.
  const KnownCells map;
  // Exploring first (about a minute of robot time in the furnished room), then the rows.
  const Cleaned cleaned = cleanUntilDone(robot_, kCleanWallTimeout, kCleanWallTimeout);
  ASSERT_TRUE(cleaned.planned) << "never done exploring: still " << robot_.state();
  ASSERT_TRUE(cleaned.done) << "still " << robot_.state() << " at coverage " << cleaned.coverage;
  EXPECT_GE(cleaned.coverage, 0.90);
  EXPECT_LE(robot_.bumps(), 2);
  // The first scan from the middle of the room sees most of it (about 10 000 cells); the rest
  // comes as the robot explores: the room's 6.4 m × 4.8 m (12 288 cells of 0.05 m), less the
  // furniture's 3 m², and its walls.
  EXPECT_GT(map.known(), map.firstKnown()) << "the map did not grow as the robot explored";
  EXPECT_GT(map.known(), 11000u);
  expectStandingStill(robot_);
  // It takes no goals: it says so.
  move_base_msgs::MoveBaseGoal goal;
  goal.target_pose.header.frame_id = "map";
  goal.target_pose.pose.position.x = 3.0;
  goal.target_pose.pose.position.y = 2.0;
  goal.target_pose.pose.orientation.w = 1;
  EXPECT_EQ(run(*client_, goal), SimpleClientGoalState::ABORTED);
  EXPECT_NE(client_->getState().getText().find("~unknown"), std::string::npos)
      << client_->getState().getText();
}

class CleanByTouch : public Nav {};

TEST_F(CleanByTouch, cleans_90_percent_of_a_room_it_has_never_seen_with_no_lidar) {
  ros::NodeHandle nh;
  std::mutex mutex;
  double coverage = 0;
  ros::Subscriber coverage_sub = nh.subscribe<std_msgs::Float32>(
      "/roomba_sim/coverage", 10, [&](const std_msgs::Float32::ConstPtr& m) {
        std::lock_guard<std::mutex> lock(mutex);
        coverage = m->data;
      });
  // The furnished room's online boustrophedon is done in about 470 s of robot time.
  ASSERT_TRUE(waitFor([&] { return robot_.state() == "Idle"; }, kCleanWallTimeout))
      << "still " << robot_.state();
  ros::Duration(0.5).sleep();  // the last coverage
  std::lock_guard<std::mutex> lock(mutex);
  std::printf("cleaning by touch: coverage %.1f %%, %d bumps\n", 100 * coverage, robot_.bumps());
  EXPECT_GE(coverage, 0.90);
  EXPECT_LE(robot_.bumps(), 20);
  expectStandingStill(robot_);
}

class NavUnknown : public Nav {};

TEST_F(NavUnknown, goals_across_a_room_it_has_never_seen_are_reached_without_a_bump) {
  // roomba_sim keeps its map to itself: roomba_bt plans on the map it builds from /scan.
  const KnownCells map;
  // Behind the round table, then the far corners: paths through what the first scan did not see.
  // A goal the built map's 5 cm cells put too near an obstacle may be moved by up to 0.1 m.
  for (const auto& [x, y] : {std::pair{1.38, 4.40}, std::pair{5.87, 4.37}, std::pair{5.04, 0.31}}) {
    const SimpleClientGoalState state = run(*client_, goalAt(x, y));
    EXPECT_EQ(state, SimpleClientGoalState::SUCCEEDED)
        << "(" << x << ", " << y << "): " << state.getText();
    EXPECT_LT(distanceTo(robot_, x, y), kXyTolerance + 0.1 + 0.01) << "(" << x << ", " << y << ")";
  }
  EXPECT_EQ(robot_.bumps(), 0);
  EXPECT_TRUE(waitFor([&] { return robot_.state() == "Idle"; }, 5.0)) << robot_.state();
  EXPECT_GT(map.known(), map.firstKnown()) << "the map did not grow as the robot drove";
  // A goal far beyond anything the map could hold is refused, naming it.
  const SimpleClientGoalState far = run(*client_, goalAt(1e6, 2.0));
  EXPECT_EQ(far, SimpleClientGoalState::ABORTED);
  EXPECT_NE(far.getText().find("goal"), std::string::npos) << far.getText();
  EXPECT_NE(far.getText().find("beyond the map"), std::string::npos) << far.getText();
}

/// The map roomba_bt serves on ~known_map (latched): what it was given, as map_server serves it.
nav_msgs::OccupancyGrid::ConstPtr knownMapServed() {
  return ros::topic::waitForMessage<nav_msgs::OccupancyGrid>("/roomba_bt/known_map",
                                                             ros::Duration(30.0));
}

class NavKnownMap : public Nav {};

TEST_F(NavKnownMap, goals_in_the_apartments_other_rooms_are_reached_through_its_doors) {
  const nav_msgs::OccupancyGrid::ConstPtr known = knownMapServed();
  ASSERT_TRUE(known) << "nothing latched on /roomba_bt/known_map";
  EXPECT_EQ(known->header.frame_id, "map");
  EXPECT_EQ(known->info.width, 210u);  // config/maps/apartment_walls.pgm: 10.5 m x 7.5 m
  EXPECT_EQ(known->info.height, 150u);
  // A 2D Nav Goal in the bedroom, behind the living room's wall (through the door at x = 1.05).
  ros::Time start;
  const bool arrived = navGoal(2.0, -2.0, 0, kXyTolerance + 0.1 + 0.01, &start);
  EXPECT_TRUE(arrived) << "at " << robot_.latest().x << ", " << robot_.latest().y;
  // The kitchen, through the living room's other door, as an action goal.
  const SimpleClientGoalState state = run(*client_, goalAt(-3.5, 2.0));
  EXPECT_EQ(state, SimpleClientGoalState::SUCCEEDED) << state.getText();
  EXPECT_LT(distanceTo(robot_, -3.5, 2.0), kXyTolerance + 0.1 + 0.01);
  EXPECT_EQ(robot_.bumps(), 0);
}

class CleanKnownMap : public Nav {};

TEST_F(CleanKnownMap, cleans_the_furnished_room_from_the_map_of_its_walls) {
  const nav_msgs::OccupancyGrid::ConstPtr known = knownMapServed();
  ASSERT_TRUE(known) << "nothing latched on /roomba_bt/known_map";
  EXPECT_EQ(known->info.width, 132u);  // config/maps/furnished_walls.pgm
  // No exploring: the rows come at once, across the whole known floor.
  const Cleaned cleaned = cleanUntilDone(robot_, 30.0, kCleanWallTimeout);
  ASSERT_TRUE(cleaned.planned) << "no plan on ~coverage_path";
  EXPECT_GT(cleaned.planned_points, 50u);
  ASSERT_TRUE(cleaned.done) << "still " << robot_.state() << " at coverage " << cleaned.coverage;
  EXPECT_GE(cleaned.coverage, 0.90);
  EXPECT_LE(robot_.bumps(), 2);
  expectStandingStill(robot_);
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "nav_rostest");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
