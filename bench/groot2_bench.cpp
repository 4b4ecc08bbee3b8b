// What Groot2 monitoring costs roomba_bt's tick loop: the lab tree ticked alone, and ticked with
// the monitor (TreeMonitor::update, the status snapshot swapped into the server when a status
// changed) while a client polls 'S' at 20 Hz over ZeroMQ, as Groot2 does; then the server
// thread's CPU per tick at roomba_bt's 60 Hz. Prints one table (--json: one JSON object, for
// scripts/bench).
//
//   cmake --build <build-dir> --target groot2_bench &&
//   <build-dir>/devel/lib/roomba_rrt/groot2_bench
#include <pthread.h>
#include <time.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <thread>
#include <vector>
#include <zmq.hpp>
#include <zmq_addon.hpp>

#include "roomba_rrt/behavior/roomba_bt.h"
#include "roomba_rrt/bt/groot2_server.h"

namespace {

using roomba_rrt::behavior::RoombaBt;
using roomba_rrt::behavior::RoombaParams;
namespace groot2 = roomba_rrt::bt::groot2;
using Clock = std::chrono::steady_clock;

constexpr int kPort = 17767;
constexpr double kTickRate = 60.0;  ///< roomba_bt's default rate

double cpuSeconds(clockid_t clock) {
  timespec t{};
  clock_gettime(clock, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

/// The bumper of tick `i`: a bump every 997 ticks, as behavior_bench's input.
roomba_rrt::robot::BumperState bumper(long i) {
  const bool pressed = i % 997 == 0 && (i / 997) % 3 != 0;
  return {pressed, pressed, pressed};
}

/// Polls 'S' every 50 ms until stopped; counts the replies; its thread's CPU seconds at the end.
struct Poller {
  Poller() : thread([this] { run(); }) {}
  ~Poller() { finish(); }
  void finish() {
    stop = true;
    if (thread.joinable()) thread.join();
  }
  void run() {
    zmq::context_t context;
    zmq::socket_t socket(context, zmq::socket_type::req);
    socket.set(zmq::sockopt::rcvtimeo, 2000);
    socket.set(zmq::sockopt::linger, 0);
    socket.connect("tcp://127.0.0.1:" + std::to_string(kPort));
    auto next = Clock::now();
    while (!stop) {
      socket.send(zmq::buffer(groot2::encodeRequestHeader({groot2::kProtocolId, 'S', 1})));
      zmq::multipart_t reply;
      if (reply.recv(socket)) ++replies;
      next += std::chrono::milliseconds(50);
      std::this_thread::sleep_until(next);
    }
    cpu = cpuSeconds(CLOCK_THREAD_CPUTIME_ID);
  }
  std::atomic<bool> stop{false};
  std::atomic<long> replies{0};
  std::atomic<double> cpu{0};
  std::thread thread;
};

/// Nanoseconds per tick over `ticks` ticks, with or without the monitor.
double nsPerTick(long ticks, roomba_rrt::bt::TreeMonitor* monitor, groot2::Server* server,
                 RoombaBt& roomba, long& changes) {
  std::string snapshot;
  const auto start = Clock::now();
  for (long i = 0; i < ticks; ++i) {
    roomba.tick(bumper(i));
    if (monitor && monitor->update()) {
      groot2::statusSnapshot(*monitor, snapshot);
      server->publishStatus(snapshot);
      ++changes;
    }
  }
  return std::chrono::duration<double, std::nano>(Clock::now() - start).count() /
         static_cast<double>(ticks);
}

}  // namespace

int main(int argc, char** argv) {
  const bool json = argc > 1 && std::strcmp(argv[1], "--json") == 0;
  RoombaBt roomba(RoombaParams{}, 1);
  roomba_rrt::bt::TreeMonitor monitor(roomba.tree().root());
  std::string status;
  groot2::statusSnapshot(monitor, status);
  groot2::Server server(kPort, roomba_rrt::bt::treeXmlWithUids(monitor, "Roomba", ""), status);

  // 1. The tick loop's own cost: tight loops, the client polling meanwhile.
  constexpr long kTicks = 2'000'000;
  long changes = 0;
  double bare = 0, watched = 0;
  {
    Poller poller;
    for (int round = 0; round < 3; ++round) {  // best of 3 rounds, alternating
      long ignored = 0;
      const double b = nsPerTick(kTicks, nullptr, nullptr, roomba, ignored);
      const double w = nsPerTick(kTicks, &monitor, &server, roomba, changes);
      bare = round == 0 ? b : std::min(bare, b);
      watched = round == 0 ? w : std::min(watched, w);
    }
  }

  // 2. Everything the server adds at 60 Hz with a client at 20 Hz: the process's CPU time minus
  // the tick thread's and the client thread's, per tick (the client's ZeroMQ I/O thread is
  // counted as the server's: an upper bound).
  constexpr double kSeconds = 5.0;
  const long ticks = static_cast<long>(kSeconds * kTickRate);
  double process = 0, tick_thread = 0, client = 0;
  long replies = 0;
  {
    Poller poller;
    const double process0 = cpuSeconds(CLOCK_PROCESS_CPUTIME_ID);
    const double thread0 = cpuSeconds(CLOCK_THREAD_CPUTIME_ID);
    auto next = Clock::now();
    std::string snapshot;
    for (long i = 0; i < ticks; ++i) {
      roomba.tick(bumper(i));
      if (monitor.update()) {
        groot2::statusSnapshot(monitor, snapshot);
        server.publishStatus(snapshot);
      }
      next += std::chrono::microseconds(static_cast<long>(1e6 / kTickRate));
      std::this_thread::sleep_until(next);
    }
    tick_thread = cpuSeconds(CLOCK_THREAD_CPUTIME_ID) - thread0;
    poller.finish();
    process = cpuSeconds(CLOCK_PROCESS_CPUTIME_ID) - process0;
    client = poller.cpu;
    replies = poller.replies;
  }
  const double tick_period_us = 1e6 / kTickRate;
  const double server_us_per_tick = (process - tick_thread - client) * 1e6 / ticks;

  if (json) {
    std::printf(
        "{\"nodes\": %zu, \"bare_ns\": %.2f, \"watched_ns\": %.2f, \"monitor_ns\": %.2f, "
        "\"server_us_per_tick\": %.2f, \"tick_period_us\": %.1f, \"replies\": %ld}\n",
        monitor.nodes().size(), bare, watched, watched - bare, server_us_per_tick, tick_period_us,
        replies);
    return 0;
  }
  std::printf("Groot2 monitoring of the lab tree (%zu nodes), client polling 'S' at 20 Hz\n",
              monitor.nodes().size());
  std::printf("%-52s %12s\n", "measure", "value");
  std::printf("%-52s %9.1f ns\n", "tick alone (tight loop)", bare);
  std::printf("%-52s %9.1f ns\n", "tick + monitor + snapshot swap (tight loop)", watched);
  std::printf("%-52s %9.1f ns\n", "monitor's cost per tick", watched - bare);
  std::printf("%-52s %9.4f %%\n", "  of a 60 Hz tick (16.7 ms)",
              100.0 * (watched - bare) * 1e-3 / tick_period_us);
  std::printf("%-52s %9.2f %%\n", "status changes per tick", 100.0 * changes / (3.0 * kTicks));
  std::printf("%-52s %9.2f us\n", "server thread CPU per tick at 60 Hz (upper bound)",
              server_us_per_tick);
  std::printf("%-52s %9.4f %%\n", "  of a 60 Hz tick (16.7 ms)",
              100.0 * server_us_per_tick / tick_period_us);
  std::printf("%-52s %9ld\n", "'S' replies in the 5 s at 60 Hz", replies);
  return 0;
}
