// Master restarts: a ROS 1 node never re-registers with a new master, so after a restart its
// publications, subscriptions and services are unknown to the new master and new peers never
// connect to it. Every node of this package therefore watches the master's /run_id (roscore
// sets a new one at each start) and, when it changes, shuts down with kMasterRestartedExitCode;
// scripts/run restarts it, and the fresh process registers everything with the new master.
#pragma once

#include <atomic>
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>

namespace roomba_rrt::nodes {

/// The exit code of a node that stopped because the master restarted (EX_TEMPFAIL: "try again").
constexpr int kMasterRestartedExitCode = 75;

/// Polls the master's /run_id once a `period` (wall seconds) on its own thread, from after
/// ros::init until destruction. While the master is unreachable it keeps waiting (existing peer
/// connections keep working); when a master answers with a different run id it logs why and
/// calls ros::requestShutdown(), and exitCode() becomes kMasterRestartedExitCode.
class MasterWatch {
 public:
  explicit MasterWatch(double period = 1.0);
  ~MasterWatch();
  MasterWatch(const MasterWatch&) = delete;
  MasterWatch& operator=(const MasterWatch&) = delete;

  /// 0, or kMasterRestartedExitCode once the master restarted.
  int exitCode() const { return restarted_ ? kMasterRestartedExitCode : 0; }

 private:
  void run();

  double period_;
  std::atomic<bool> restarted_{false};
  bool stop_ = false;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::thread thread_;
};

}  // namespace roomba_rrt::nodes
