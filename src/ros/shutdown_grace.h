// How a node that serves long requests (a plan of seconds or minutes, which nothing can
// interrupt from outside) stops: callbacks on threads of their own, and at shutdown a running
// callback gets a short grace before the process exits without it, so Ctrl-C is never held up.
#pragma once

#include <string>

#include "master_watch.h"

namespace roomba_rrt::nodes {

/// Makes SIGTERM (what `timeout`, systemd and roslaunch's escalation send) stop the node as
/// SIGINT (Ctrl-C) does, through ros::requestShutdown(): the same cleanup (the parameters the
/// node wrote removed from the master), where the default action would end the process at once
/// with exit code 143. Call right after ros::init().
void stopOnSigterm();

/// Seconds a running callback may delay the exit after shutdown.
constexpr double kShutdownGrace = 0.5;

/// Serves the node's callbacks on `threads` threads until shutdown (Ctrl-C, rosnode kill, the
/// master's restart seen by `watch`). A callback still running kShutdownGrace seconds later is
/// left: the process exits with `watch`'s exit code, after a warning naming `node`. Returns
/// once every callback has ended within the grace.
void spinWithShutdownGrace(unsigned threads, const MasterWatch& watch, const std::string& node);

}  // namespace roomba_rrt::nodes
