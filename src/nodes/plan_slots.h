// How many plans the rrt_planner node runs at once: a request beyond the limit is turned away
// at once ("busy") instead of waiting in the spinner's queue behind long plans. ROS-free.
#pragma once

#include <atomic>

namespace roomba_rrt::planner_node {

class PlanSlots {
 public:
  explicit PlanSlots(int capacity) : capacity_(capacity) {}

  /// A slot held for as long as it lives; false (no slot) when all were taken.
  class Lease {
   public:
    Lease(Lease&& other) noexcept : slots_(other.slots_) { other.slots_ = nullptr; }
    Lease(const Lease&) = delete;
    Lease& operator=(const Lease&) = delete;
    Lease& operator=(Lease&&) = delete;
    ~Lease() {
      if (slots_ != nullptr) slots_->in_use_.fetch_sub(1);
    }
    explicit operator bool() const { return slots_ != nullptr; }

   private:
    friend class PlanSlots;
    explicit Lease(PlanSlots* slots) : slots_(slots) {}
    PlanSlots* slots_;
  };

  Lease tryAcquire() {
    int used = in_use_.load();
    do {
      if (used >= capacity_) return Lease(nullptr);
    } while (!in_use_.compare_exchange_weak(used, used + 1));
    return Lease(this);
  }
  int capacity() const { return capacity_; }

 private:
  const int capacity_;
  std::atomic<int> in_use_{0};
};

}  // namespace roomba_rrt::planner_node
