#include "plan_slots.h"

namespace roomba_rrt::planner_node {

PlanSlots::PlanSlots(int capacity) {
  for (int i = 0; i < capacity; ++i) slots_.push_back(std::make_unique<Slot>());
}

PlanSlots::Lease::~Lease() {
  if (slots_ != nullptr) slots_->release(slot_);
}

bool PlanSlots::Lease::stopRequested() const {
  return slots_ != nullptr && slots_->slots_[slot_]->stop.load(std::memory_order_relaxed);
}

void PlanSlots::release(int slot) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    slots_[slot]->busy = false;
    slots_[slot]->stop = false;
  }
  freed_.notify_all();
}

int PlanSlots::takeFree(bool ordinary) {
  for (int i = 0; i < capacity(); ++i) {
    Slot& s = *slots_[i];
    if (s.busy) continue;
    s.busy = true;
    s.ordinary = ordinary;
    s.started = Clock::now();
    return i;
  }
  return -1;
}

PlanSlots::Lease PlanSlots::acquireLong() {
  std::lock_guard<std::mutex> lock(mutex_);
  const int slot = ordinary_waiting_ > 0 ? -1 : takeFree(false);
  return slot < 0 ? Lease() : Lease(this, slot);
}

PlanSlots::Lease PlanSlots::acquireOrdinary(Clock::time_point deadline) {
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    const int slot = takeFree(true);
    if (slot >= 0) return Lease(this, slot);
    // Every thread is taken: stop the oldest long plan not already stopping (it ends within about
    // a millisecond and frees its thread); with none, wait for an ordinary plan to end.
    int oldest = -1;
    for (int i = 0; i < capacity(); ++i) {
      const Slot& s = *slots_[i];
      if (!s.ordinary && !s.stop && (oldest < 0 || s.started < slots_[oldest]->started)) {
        oldest = i;
      }
    }
    if (oldest >= 0) {
      slots_[oldest]->stop = true;
      preemptions_.fetch_add(1);
    }
    ++ordinary_waiting_;
    const bool timed_out = freed_.wait_until(lock, deadline) == std::cv_status::timeout;
    --ordinary_waiting_;
    if (timed_out && Clock::now() >= deadline) {
      const int last = takeFree(true);
      return last < 0 ? Lease() : Lease(this, last);
    }
  }
}

}  // namespace roomba_rrt::planner_node
