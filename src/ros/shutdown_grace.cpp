#include "shutdown_grace.h"

#include <csignal>

#include <chrono>
#include <cstdlib>
#include <thread>

#include <ros/ros.h>

namespace roomba_rrt::nodes {

void stopOnSigterm() {
  struct sigaction action {};
  action.sa_handler = [](int) { ros::requestShutdown(); };  // what roscpp's SIGINT handler does
  sigemptyset(&action.sa_mask);
  sigaction(SIGTERM, &action, nullptr);
}

void spinWithShutdownGrace(unsigned threads, const MasterWatch& watch, const std::string& node) {
  ros::AsyncSpinner spinner(threads);
  spinner.start();
  ros::waitForShutdown();
  // The spinner's destructor waits for its callbacks: give them kShutdownGrace.
  std::thread([code = watch.exitCode(), node] {
    std::this_thread::sleep_for(std::chrono::duration<double>(kShutdownGrace));
    ROS_WARN("%s: a request was still being served %.1f s after shutdown; exiting without it",
             node.c_str(), kShutdownGrace);
    std::_Exit(code);
  }).detach();
}

}  // namespace roomba_rrt::nodes
