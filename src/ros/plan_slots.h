// How many plans the rrt_planner node runs at once, and who gets a thread when all are taken.
// ROS-free.
//
// Fairness: turning a request away whenever every thread was busy let any client deny
// the service to all others with a handful of long plans (six unreachable plans at the request
// cap held every thread for two seconds). Requests now come in two kinds. An *ordinary* request
// asks for no more iterations than the node's ~ordinary_iterations (20 000 by default: a default
// request, and the navigation tree's): it takes a free thread, or else, at once, the thread of
// the oldest *long* plan, which is told to stop (its client hears "preempted") and winds down
// beside it, or else it waits for an ordinary plan to end, up to its own time budget. A *long*
// request takes a free thread or is answered "busy" at once; it never preempts. So an ordinary
// request starts planning as soon as its callback runs, whatever long plans others run: it does
// not wait for the preempted plan to notice (a plan looks about every millisecond of its own CPU
// time, far longer on a machine whose cores the long plans keep busy), and for that moment one
// plan more than the capacity runs. Long plans use whatever ordinary ones leave.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

namespace roomba_rrt::planner_node {

class PlanSlots {
 public:
  using Clock = std::chrono::steady_clock;

  explicit PlanSlots(int capacity);

  /// A thread held for as long as it lives (empty: none was had). A plan polls stopRequested()
  /// and ends early when it is preempted.
  class Lease {
   public:
    Lease() = default;
    Lease(Lease&& other) noexcept
        : slots_(other.slots_), slot_(other.slot_), generation_(other.generation_) {
      other.slots_ = nullptr;
    }
    Lease(const Lease&) = delete;
    Lease& operator=(const Lease&) = delete;
    Lease& operator=(Lease&&) = delete;
    ~Lease();
    explicit operator bool() const { return slots_ != nullptr; }
    /// True once an ordinary request took this (long) plan's thread.
    bool stopRequested() const;

   private:
    friend class PlanSlots;
    Lease(PlanSlots* slots, int slot, std::uint64_t generation)
        : slots_(slots), slot_(slot), generation_(generation) {}
    PlanSlots* slots_ = nullptr;
    int slot_ = -1;
    std::uint64_t generation_ = 0;  ///< the slot's holder while it equals the slot's generation
  };

  /// A thread for an ordinary plan: free, or a long plan's (taken at once; that plan is told to
  /// stop), or the first an ordinary plan frees before `deadline`; empty when none by then.
  Lease acquireOrdinary(Clock::time_point deadline);
  /// A thread for a long plan: a free one (none while an ordinary request waits), or empty at once.
  Lease acquireLong();

  int capacity() const { return static_cast<int>(slots_.size()); }
  /// Long plans preempted so far.
  long preemptions() const { return preemptions_.load(); }

 private:
  struct Slot {
    bool busy = false;
    bool ordinary = false;
    Clock::time_point started;
    /// Counts the slot's holders: a lease whose generation is no longer this one was preempted
    /// (its release leaves the slot to the new holder).
    std::atomic<std::uint64_t> generation{0};
  };
  /// Gives slot `i` to a new holder (under the lock).
  Lease take(int i, bool ordinary);
  /// Takes a free slot (under the lock); empty if none.
  Lease takeFree(bool ordinary);
  void release(int slot, std::uint64_t generation);

  std::vector<std::unique_ptr<Slot>> slots_;
  std::mutex mutex_;
  std::condition_variable freed_;
  int ordinary_waiting_ = 0;  ///< ordinary requests waiting: a long one gets no thread meanwhile
  std::atomic<long> preemptions_{0};
};

}  // namespace roomba_rrt::planner_node
