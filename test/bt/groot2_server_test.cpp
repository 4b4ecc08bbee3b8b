// groot2::Server over real ZeroMQ sockets on localhost: a client as Groot2 is (REQ) gets the tree
// and the latest statuses, and bad requests get error replies without stopping the server.
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <random>
#include <thread>
#include <zmq.hpp>
#include <zmq_addon.hpp>

#include "roomba_rrt/bt/groot2_server.h"

namespace roomba_rrt::bt::groot2 {
namespace {

/// A TCP port that is free now, with the next one free too (the PUB socket's).
int freePortPair() {
  for (int attempt = 0; attempt < 50; ++attempt) {
    const int fd = socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_addr.s_addr = htonl(INADDR_ANY);
    socklen_t len = sizeof(addr);
    bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof(addr));
    getsockname(fd, reinterpret_cast<sockaddr*>(&addr), &len);
    const int port = ntohs(addr.sin_port);
    close(fd);
    const int next = socket(AF_INET, SOCK_STREAM, 0);
    addr.sin_port = htons(static_cast<std::uint16_t>(port + 1));
    const bool next_free = bind(next, reinterpret_cast<sockaddr*>(&addr), sizeof(addr)) == 0;
    close(next);
    if (next_free && port < 65534) return port;
  }
  throw std::runtime_error("no free port pair");
}

struct Client {
  explicit Client(int port) : socket(context, zmq::socket_type::req) {
    socket.set(zmq::sockopt::rcvtimeo, 5000);
    socket.set(zmq::sockopt::linger, 0);
    socket.connect("tcp://127.0.0.1:" + std::to_string(port));
  }
  std::vector<std::string> ask(const std::vector<std::string>& frames) {
    zmq::multipart_t request;
    for (const std::string& f : frames) request.addstr(f);
    request.send(socket);
    zmq::multipart_t answer;
    if (!answer.recv(socket)) throw std::runtime_error("no reply within 5 s");
    std::vector<std::string> out;
    for (const zmq::message_t& part : answer) out.push_back(part.to_string());
    return out;
  }
  zmq::context_t context;
  zmq::socket_t socket;
};

std::string header(char type) { return encodeRequestHeader({kProtocolId, type, 42}); }

TEST(Groot2Server, serves_the_tree_and_the_latest_status) {
  const int port = freePortPair();
  Server server(port, "<root/>", "old");
  Client client(port);
  auto frames = client.ask({header('T')});
  ASSERT_EQ(frames.size(), 2u);
  ASSERT_EQ(frames[0].size(), kReplyHeaderSize);
  EXPECT_EQ(frames[0].substr(0, 6), header('T'));
  EXPECT_EQ(frames[1], "<root/>");
  const std::string uuid = frames[0].substr(6);

  std::string status = "new";
  server.publishStatus(status);
  EXPECT_EQ(status, "old");  // the previous buffer comes back for reuse
  frames = client.ask({header('S')});
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_EQ(frames[0].substr(6), uuid);  // fixed while the server runs
  EXPECT_EQ(frames[1], "new");
  EXPECT_TRUE(server.clientConnected());
  EXPECT_EQ(server.requests(), 2);
}

TEST(Groot2Server, the_blackboard_comes_from_the_tick_thread) {
  const int port = freePortPair();
  Server server(port, "<root/>", "", "Main");
  Client client(port);
  // Nobody provides the blackboard: an error reply after the wait.
  EXPECT_EQ(client.ask({header('B'), "Main"})[0], "error");
  EXPECT_FALSE(server.blackboardWanted());
  std::atomic<bool> stop{false};
  std::thread ticks([&] {  // what roomba_bt's tick loop does after every tick
    Blackboard board;
    board.set<int>("count", 7);
    while (!stop) {
      if (server.blackboardWanted()) server.provideBlackboard(snapshotBlackboard(board));
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
  });
  const auto frames = client.ask({header('B'), "Main"});
  stop = true;
  ticks.join();
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_NE(frames[1].find("count"), std::string::npos);
}

TEST(Groot2Server, bad_requests_get_error_replies_and_the_server_keeps_serving) {
  const int port = freePortPair();
  Server server(port, "<root/>", "");
  Client client(port);
  EXPECT_EQ(client.ask({"xx"}), (std::vector<std::string>{"error", "wrong request header"}));
  EXPECT_EQ(client.ask({std::string(1 << 20, '\x02')}),
            (std::vector<std::string>{"error", "wrong request header"}));
  EXPECT_EQ(client.ask({header('Q')}),
            (std::vector<std::string>{"error", "Request not recognized"}));
  EXPECT_EQ(client.ask({header('T')}).size(), 2u);
}

TEST(Groot2Server, peers_that_are_no_zeromq_clients_do_not_cost_a_client_its_reply) {
  const int port = freePortPair();
  Server server(port, "<root/>", "");
  Client client(port);
  std::mt19937 random(46);
  // Random bytes on a raw TCP connection, closed at once, then a request (found by the rostest's
  // fuzzing: a REP socket lost most of those replies; REP's envelope is handled by hand now).
  for (int i = 0; i < 20; ++i) {
    const int fd = socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_port = htons(static_cast<std::uint16_t>(port));
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    ASSERT_EQ(connect(fd, reinterpret_cast<sockaddr*>(&addr), sizeof(addr)), 0);
    std::string garbage(4096, '\0');
    for (char& c : garbage) c = static_cast<char>(random() & 0xFF);
    ASSERT_EQ(write(fd, garbage.data(), garbage.size()), static_cast<ssize_t>(garbage.size()));
    close(fd);
    EXPECT_EQ(client.ask({header('T')}).size(), 2u) << "after garbage " << i;
  }
}

TEST(Groot2Server, a_port_in_use_is_an_error_naming_it) {
  const int port = freePortPair();
  Server first(port, "<root/>", "");
  try {
    Server second(port, "<root/>", "");
    FAIL() << "bound a port in use";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(std::to_string(port)), std::string::npos) << e.what();
  }
  EXPECT_THROW(Server(0, "", ""), std::invalid_argument);
  EXPECT_THROW(Server(65535, "", ""), std::invalid_argument);
}

}  // namespace
}  // namespace roomba_rrt::bt::groot2
