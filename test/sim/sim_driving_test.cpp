// Integration test through a real master: drives roomba_sim over /cmd_vel and checks what a user
// sees on /odom, /bumper and /clock. Runs with /use_sim_time true (real_time_factor 10,
// sim_driving.test) and in wall-clock time (sim_wall_clock.test).
#include <geometry_msgs/Twist.h>
#include <gtest/gtest.h>
#include <nav_msgs/Odometry.h>
#include <roomba_rrt/Bumper.h>
#include <ros/ros.h>
#include <std_srvs/Empty.h>

#include <cmath>
#include <functional>
#include <limits>

namespace {

constexpr double kContactX = 6.4 - 0.17;  // the right wall minus the robot's radius

class SimDriving : public ::testing::Test {
 protected:
  void SetUp() override {
    cmd_ = nh_.advertise<geometry_msgs::Twist>("/cmd_vel", 10);
    odom_sub_ = nh_.subscribe("/odom", 1000, &SimDriving::onOdom, this);
    bumper_sub_ = nh_.subscribe("/bumper", 1000, &SimDriving::onBumper, this);
    ASSERT_TRUE(ros::service::waitForService("/roomba_sim/reset", ros::Duration(20)));
    ASSERT_TRUE(waitUntil([&] { return odom_count_ > 0 && cmd_.getNumSubscribers() > 0; }, 20));
    resetSim();
  }

  void onOdom(const nav_msgs::Odometry& msg) {
    odom_ = msg;
    ++odom_count_;
    const auto& p = msg.pose.pose;
    all_finite_ = all_finite_ && std::isfinite(p.position.x) && std::isfinite(p.position.y) &&
                  std::isfinite(p.orientation.z) && std::isfinite(p.orientation.w) &&
                  std::isfinite(msg.twist.twist.linear.x) &&
                  std::isfinite(msg.twist.twist.angular.z);
  }
  void onBumper(const roomba_rrt::Bumper& msg) { bumper_ = msg; }

  /// Spins until `done` holds or `wall_seconds` of wall time pass.
  bool waitUntil(const std::function<bool()>& done, double wall_seconds) {
    const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(wall_seconds);
    while (ros::ok() && ros::WallTime::now() < deadline) {
      ros::spinOnce();
      if (done()) return true;
      ros::WallDuration(0.001).sleep();
    }
    return false;
  }

  /// Publishes (v, w) every 10 ms of wall time until `done` holds (or the wall timeout).
  bool driveUntil(double v, double w, const std::function<bool()>& done, double wall_seconds) {
    geometry_msgs::Twist twist;
    twist.linear.x = v;
    twist.angular.z = w;
    ros::WallTime next_publish;
    return waitUntil(
        [&] {
          if (ros::WallTime::now() >= next_publish) {
            cmd_.publish(twist);
            next_publish = ros::WallTime::now() + ros::WallDuration(0.01);
          }
          return done();
        },
        wall_seconds);
  }

  /// Drives for `sim_seconds` of ROS time.
  void driveFor(double v, double w, double sim_seconds) {
    const ros::Time end = ros::Time::now() + ros::Duration(sim_seconds);
    driveUntil(
        v, w, [&] { return ros::Time::now() >= end; }, 10 * sim_seconds + 5);
  }

  void resetSim() {
    std_srvs::Empty empty;
    ASSERT_TRUE(ros::service::call("/roomba_sim/reset", empty));
    ASSERT_TRUE(waitUntil([&] { return atInitialPose(); }, 5));
  }

  bool atInitialPose() const {
    const auto& p = odom_.pose.pose;
    return std::abs(p.position.x - 3.2) < 1e-9 && std::abs(p.position.y - 2.4) < 1e-9 &&
           std::abs(p.orientation.z) < 1e-9;
  }

  /// Drives until /odom shows the command taking effect. At real_time_factor 10 a fixed window of
  /// ROS time is tens of milliseconds of wall time, which a loaded machine may spend before the
  /// first command reaches the simulator (CI saw a zero twist after 0.3 s).
  void startDriving(double v, double w) {
    ASSERT_TRUE(driveUntil(
        v, w,
        [&] { return odom_.twist.twist.linear.x != 0.0 || odom_.twist.twist.angular.z != 0.0; },
        20));
  }

  void driveIntoTheRightWall() {
    ASSERT_TRUE(driveUntil(
        1.0, 0.0, [&] { return bool(bumper_.pressed); }, 20));
  }

  ros::NodeHandle nh_;
  ros::Publisher cmd_;
  ros::Subscriber odom_sub_, bumper_sub_;
  nav_msgs::Odometry odom_;
  roomba_rrt::Bumper bumper_;
  long odom_count_ = 0;
  bool all_finite_ = true;
};

TEST_F(SimDriving, driving_straight_presses_the_bumper_at_the_wall_and_stops_exactly_at_contact) {
  driveIntoTheRightWall();
  waitUntil([] { return false; }, 0.05);  // the /odom published with that bumper
  EXPECT_NEAR(odom_.pose.pose.position.x, kContactX, 1e-9);
  EXPECT_NEAR(odom_.pose.pose.position.y, 2.4, 1e-9);
  EXPECT_TRUE(bumper_.left && bumper_.right) << "a head-on hit closes both switches";
}

TEST_F(SimDriving, pushing_on_does_not_move_the_robot_and_keeps_the_bumper_pressed) {
  driveIntoTheRightWall();
  bool always_pressed = true;
  const ros::Time end = ros::Time::now() + ros::Duration(1.0);
  driveUntil(
      1.0, 0.0,
      [&] {
        always_pressed = always_pressed && bumper_.pressed;
        return ros::Time::now() >= end;
      },
      20);
  EXPECT_TRUE(always_pressed);
  EXPECT_NEAR(odom_.pose.pose.position.x, kContactX, 1e-9);
}

TEST_F(SimDriving, backing_off_releases_the_bumper) {
  driveIntoTheRightWall();
  const ros::Time start = ros::Time::now();
  ASSERT_TRUE(driveUntil(
      -0.1, 0.0, [&] { return !bumper_.pressed; }, 10));
  EXPECT_LT((ros::Time::now() - start).toSec(), 0.5) << "released within a few steps";
  // /odom and /bumper travel on separate connections: the /odom published with that bumper may
  // arrive just after it (seen under load in wall-clock mode).
  waitUntil([] { return false; }, 0.05);
  EXPECT_LT(odom_.pose.pose.position.x, kContactX);
}

TEST_F(SimDriving, simulated_clock_runs_at_least_8_times_the_wall_clock) {
  bool use_sim_time = false;
  ros::param::get("/use_sim_time", use_sim_time);
  if (!use_sim_time) GTEST_SKIP() << "wall-clock mode";
  double factor = 0;
  ASSERT_TRUE(ros::param::get("/roomba_sim/real_time_factor", factor));
  const ros::Time sim_start = ros::Time::now();
  const ros::WallTime wall_start = ros::WallTime::now();
  waitUntil([] { return false; }, 2.0);
  const double ratio =
      (ros::Time::now() - sim_start).toSec() / (ros::WallTime::now() - wall_start).toSec();
  EXPECT_GE(ratio, 0.8 * factor);
}

TEST_F(SimDriving, nan_command_is_rejected_and_odometry_stays_finite) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  driveFor(nan, nan, 0.5);
  driveFor(std::numeric_limits<double>::infinity(), 0.0, 0.5);
  EXPECT_TRUE(all_finite_);
  EXPECT_TRUE(atInitialPose()) << "a rejected command does not move the robot";
}

TEST_F(SimDriving, huge_command_drives_at_the_speed_limits) {
  startDriving(1e6, -1e6);  // then at the limits, never faster, for 0.3 s
  bool never_faster = true;
  const ros::Time end = ros::Time::now() + ros::Duration(0.3);
  driveUntil(
      1e6, -1e6,
      [&] {
        never_faster = never_faster && odom_.twist.twist.linear.x <= 1.0 &&
                       odom_.twist.twist.angular.z >= -2.0;
        return ros::Time::now() >= end;
      },
      20);
  EXPECT_TRUE(never_faster);
  EXPECT_EQ(odom_.twist.twist.linear.x, 1.0);
  EXPECT_EQ(odom_.twist.twist.angular.z, -2.0);
}

TEST_F(SimDriving, robot_stops_when_commands_stop_arriving) {
  startDriving(0.5, 0.0);
  driveFor(0.5, 0.0, 0.3);
  const ros::Time end = ros::Time::now() + ros::Duration(1.0);  // twice the 0.5 s timeout
  ASSERT_TRUE(waitUntil([&] { return ros::Time::now() >= end; }, 20));
  const double x = odom_.pose.pose.position.x;
  EXPECT_EQ(odom_.twist.twist.linear.x, 0.0);
  const ros::Time later = ros::Time::now() + ros::Duration(0.5);
  waitUntil([&] { return ros::Time::now() >= later; }, 20);
  EXPECT_EQ(odom_.pose.pose.position.x, x);
}

TEST_F(SimDriving, reset_restores_the_initial_pose) {
  startDriving(0.6, 1.0);
  driveFor(0.6, 1.0, 1.0);
  EXPECT_FALSE(atInitialPose());
  resetSim();  // asserts the initial pose on /odom
  EXPECT_FALSE(bumper_.pressed);
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "sim_driving_test");
  ros::NodeHandle nh;  // keeps the node alive across tests
  return RUN_ALL_TESTS();
}
