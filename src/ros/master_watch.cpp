#include "master_watch.h"

#include <ros/master.h>
#include <ros/ros.h>

#include <chrono>
#include <optional>

namespace roomba_rrt::nodes {
namespace {

/// The master's /run_id, or nothing when no master answers (never waits for one).
std::optional<std::string> masterRunId() {
  XmlRpc::XmlRpcValue request, response, payload;
  request[0] = ros::this_node::getName();
  request[1] = std::string("/run_id");
  if (!ros::master::execute("getParam", request, response, payload, false)) return std::nullopt;
  if (payload.getType() != XmlRpc::XmlRpcValue::TypeString) return std::nullopt;
  return static_cast<std::string>(payload);
}

}  // namespace

MasterWatch::MasterWatch(double period) : period_(period), thread_([this] { run(); }) {}

MasterWatch::~MasterWatch() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

void MasterWatch::run() {
  std::optional<std::string> first;
  std::unique_lock<std::mutex> lock(mutex_);
  while (!stop_) {
    lock.unlock();
    const std::optional<std::string> now = masterRunId();
    lock.lock();
    if (now && !first) first = now;
    if (now && first && *now != *first && !restarted_) {
      ROS_FATAL_STREAM(ros::this_node::getName()
                       << ": the ROS master restarted (run id " << *first << " -> " << *now
                       << "); this node's registrations are lost, so it exits with code "
                       << kMasterRestartedExitCode << " for scripts/run to restart it");
      restarted_ = true;
      ros::requestShutdown();
    }
    wake_.wait_for(lock, std::chrono::duration<double>(period_), [this] { return stop_; });
  }
}

}  // namespace roomba_rrt::nodes
