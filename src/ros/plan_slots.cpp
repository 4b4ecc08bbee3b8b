#include "plan_slots.h"

namespace roomba_rrt::planner_node {

PlanSlots::PlanSlots(int capacity) {
  for (int i = 0; i < capacity; ++i) slots_.push_back(std::make_unique<Slot>());
}

PlanSlots::Lease::~Lease() {
  if (slots_ != nullptr) slots_->release(slot_, generation_);
}

bool PlanSlots::Lease::stopRequested() const {
  return slots_ != nullptr &&
         slots_->slots_[slot_]->generation.load(std::memory_order_relaxed) != generation_;
}

void PlanSlots::release(int slot, std::uint64_t generation) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    Slot& s = *slots_[slot];
    if (s.generation.load() != generation) return;  // preempted: the slot is its new holder's
    s.busy = false;
  }
  freed_.notify_all();
}

PlanSlots::Lease PlanSlots::take(int i, bool ordinary) {
  Slot& s = *slots_[i];
  s.busy = true;
  s.ordinary = ordinary;
  s.started = Clock::now();
  return Lease(this, i, s.generation.fetch_add(1) + 1);
}

PlanSlots::Lease PlanSlots::takeFree(bool ordinary) {
  for (int i = 0; i < capacity(); ++i) {
    if (!slots_[i]->busy) return take(i, ordinary);
  }
  return Lease();
}

PlanSlots::Lease PlanSlots::acquireLong() {
  std::lock_guard<std::mutex> lock(mutex_);
  return ordinary_waiting_ > 0 ? Lease() : takeFree(false);
}

PlanSlots::Lease PlanSlots::acquireOrdinary(Clock::time_point deadline) {
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    if (Lease free = takeFree(true)) return free;
    // Every thread is taken: the oldest long plan's, at once (its lease sees the new generation
    // and stops); with none, wait for an ordinary plan to end.
    int oldest = -1;
    for (int i = 0; i < capacity(); ++i) {
      const Slot& s = *slots_[i];
      if (!s.ordinary && (oldest < 0 || s.started < slots_[oldest]->started)) oldest = i;
    }
    if (oldest >= 0) {
      preemptions_.fetch_add(1);
      return take(oldest, true);
    }
    ++ordinary_waiting_;
    const bool timed_out = freed_.wait_until(lock, deadline) == std::cv_status::timeout;
    --ordinary_waiting_;
    if (timed_out && Clock::now() >= deadline) return takeFree(true);
  }
}

}  // namespace roomba_rrt::planner_node
