// Groot2 live monitoring over ZeroMQ (groot2_protocol.h): a request-reply server on one port (what
// a REP socket speaks, so Groot2's REQ socket talks to it), a PUB socket on the next (where
// BehaviorTree.CPP announces breakpoints; bound so that Groot2 finds it), answered on a thread of
// their own beside the tick loop.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "roomba_rrt/bt/groot2_protocol.h"

namespace roomba_rrt::bt::groot2 {

/// Serves one tree to Groot2 (or any client of the protocol) until destroyed.
///
/// The thread that ticks the tree calls publishStatus() after a tick whose statuses changed: it
/// swaps the new snapshot in under a mutex that the server thread holds only to copy the
/// snapshot out, so the tick loop never waits for a client, a socket or the network. The
/// blackboard belongs to that thread too: for a 'B' request the server asks for it
/// (blackboardWanted()) and waits up to 0.5 s for the tick thread to provideBlackboard().
class Server {
 public:
  /// Binds tcp://*:`port` (request-reply) and tcp://*:`port`+1 (PUB) and starts answering.
  /// `tree_xml` is the 'T' reply (treeXmlWithUids()). std::runtime_error naming the port when a
  /// socket cannot be bound (the port is taken), std::invalid_argument when `port` is not
  /// in 1..65534.
  Server(int port, std::string tree_xml, std::string initial_status, std::string tree_id = "");
  ~Server();
  Server(const Server&) = delete;
  Server& operator=(const Server&) = delete;

  /// Replaces the 'S' snapshot; `status` receives the previous buffer (reuse it, no allocation).
  void publishStatus(std::string& status);

  /// True while a 'B' request waits for the blackboard (one atomic load: check it every tick).
  bool blackboardWanted() const { return blackboard_wanted_.load(std::memory_order_relaxed); }
  /// Hands the blackboard to the waiting 'B' request.
  void provideBlackboard(BlackboardSnapshot snapshot);

  /// True when a request arrived less than 5 s ago (BehaviorTree.CPP's heartbeat).
  bool clientConnected() const;
  /// Requests answered so far (each with a reply or an error reply).
  long requests() const { return requests_.load(); }
  int port() const { return port_; }

 private:
  void serve();

  struct Sockets;
  int port_;
  ServerState state_;  ///< the status under status_mutex_; the rest is fixed
  mutable std::mutex status_mutex_;
  std::unique_ptr<Sockets> sockets_;
  std::atomic<bool> stop_{false};
  std::atomic<bool> blackboard_wanted_{false};
  std::mutex blackboard_mutex_;
  std::condition_variable blackboard_ready_;
  std::optional<BlackboardSnapshot> blackboard_;  ///< under blackboard_mutex_
  std::atomic<long> requests_{0};
  std::atomic<std::int64_t> last_request_ns_{0};  ///< steady clock, 0: never
  std::thread thread_;
};

}  // namespace roomba_rrt::bt::groot2
