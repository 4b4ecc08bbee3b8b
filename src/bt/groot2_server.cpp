#include "roomba_rrt/bt/groot2_server.h"

#include <stdexcept>
#include <vector>
#include <zmq.hpp>
#include <zmq_addon.hpp>

namespace roomba_rrt::bt::groot2 {
namespace {

constexpr std::chrono::seconds kHeartbeat{5};  ///< BehaviorTree.CPP's max_heartbeat_delay
constexpr int kPollMs = 100;                   ///< how soon the thread sees that it must stop
/// Frames above this size close the client's connection (ZMQ_MAXMSGSIZE): a bound on memory that
/// leaves room for any real request (6 bytes, a blackboard list).
constexpr std::int64_t kMaxFrameBytes = 16 << 20;

std::int64_t nowNs() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

}  // namespace

struct Server::Sockets {
  zmq::context_t context;
  /// REP's wire protocol, handled by hand (see serve()).
  zmq::socket_t server{context, zmq::socket_type::router};
  zmq::socket_t publisher{context, zmq::socket_type::pub};
};

Server::Server(int port, std::string tree_xml, std::string initial_status, std::string tree_id)
    : port_(port), sockets_(std::make_unique<Sockets>()) {
  state_.tree_id = std::move(tree_id);
  if (port < 1 || port > 65534) {
    throw std::invalid_argument(
        "Groot2 port must be in 1..65534 (the PUB socket takes port+1), got " +
        std::to_string(port));
  }
  state_.uuid = randomUuid();
  state_.tree_xml = std::move(tree_xml);
  state_.status = std::move(initial_status);
  for (zmq::socket_t* s : {&sockets_->server, &sockets_->publisher}) {
    s->set(zmq::sockopt::linger, 0);
    s->set(zmq::sockopt::sndtimeo, 1000);
  }
  sockets_->server.set(zmq::sockopt::rcvtimeo, kPollMs);
  sockets_->server.set(zmq::sockopt::maxmsgsize, kMaxFrameBytes);
  const auto bind = [](zmq::socket_t& socket, int p) {
    try {
      socket.bind("tcp://*:" + std::to_string(p));
    } catch (const zmq::error_t& e) {
      throw std::runtime_error("Groot2 server: cannot bind tcp port " + std::to_string(p) + ": " +
                               e.what());
    }
  };
  bind(sockets_->server, port);
  bind(sockets_->publisher, port + 1);
  thread_ = std::thread([this] { serve(); });
}

Server::~Server() {
  stop_ = true;
  blackboard_ready_.notify_all();
  sockets_->context.shutdown();  // wakes a blocked recv at once
  if (thread_.joinable()) thread_.join();
  sockets_->server.close();
  sockets_->publisher.close();
}

void Server::provideBlackboard(BlackboardSnapshot snapshot) {
  {
    const std::lock_guard<std::mutex> lock(blackboard_mutex_);
    blackboard_ = std::move(snapshot);
    blackboard_wanted_ = false;
  }
  blackboard_ready_.notify_one();
}

void Server::publishStatus(std::string& status) {
  const std::lock_guard<std::mutex> lock(status_mutex_);
  state_.status.swap(status);
}

bool Server::clientConnected() const {
  const std::int64_t last = last_request_ns_.load();
  return last != 0 &&
         nowNs() - last < std::chrono::duration_cast<std::chrono::nanoseconds>(kHeartbeat).count();
}

void Server::serve() {
  ServerState snapshot;  // the fixed parts, and a copy of the status per 'S'
  snapshot.uuid = state_.uuid;
  snapshot.tree_xml = state_.tree_xml;
  snapshot.tree_id = state_.tree_id;
  zmq::socket_t& socket = sockets_->server;
  while (!stop_) {
    zmq::multipart_t request;
    try {
      if (!request.recv(socket)) continue;  // timeout: look at stop_ again
    } catch (const zmq::error_t&) {
      break;  // the context was shut down
    }
    // A REQ client's request arrives as [its identity, "", frames...]; the reply goes back with
    // the same envelope. REP would do this itself, but a peer that is no ZeroMQ client (bytes
    // that parse as a legacy ZMTP 1.0 message without the empty delimiter) makes a REP socket
    // read the next client's request as that envelope, and that client never gets its reply.
    // Here such a message is dropped on its own.
    std::size_t delimiter = 1;
    while (delimiter < request.size() && request[delimiter].size() != 0) ++delimiter;
    if (delimiter >= request.size() || delimiter > 32) continue;
    last_request_ns_ = nowNs();
    zmq::multipart_t answer;
    for (std::size_t i = 0; i <= delimiter; ++i)
      answer.add(zmq::message_t(request[i].data(), request[i].size()));
    std::vector<std::string> frames;
    frames.reserve(request.size() - delimiter - 1);
    for (std::size_t i = delimiter + 1; i < request.size(); ++i)
      frames.push_back(request[i].to_string());
    const char type = !frames.empty() && frames[0].size() == kRequestHeaderSize ? frames[0][1] : 0;
    if (type == kStatus) {
      const std::lock_guard<std::mutex> lock(status_mutex_);
      snapshot.status = state_.status;
    }
    snapshot.blackboard.reset();
    if (type == kBlackboard && frames.size() == 2) {
      std::unique_lock<std::mutex> lock(blackboard_mutex_);
      blackboard_.reset();
      blackboard_wanted_ = true;
      blackboard_ready_.wait_for(lock, std::chrono::milliseconds(500),
                                 [this] { return blackboard_.has_value() || stop_; });
      blackboard_wanted_ = false;
      snapshot.blackboard = std::move(blackboard_);
      blackboard_.reset();
    }
    for (const std::string& frame : reply(frames, snapshot)) answer.addstr(frame);
    ++requests_;
    try {
      answer.send(socket);
    } catch (const zmq::error_t&) {
      if (stop_) break;  // the context was shut down; else that client is gone: serve the next
    }
  }
}

}  // namespace roomba_rrt::bt::groot2
