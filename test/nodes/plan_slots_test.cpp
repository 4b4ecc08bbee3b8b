// Who gets a planning thread when all are taken (plan_slots.h): a free one at once; an ordinary
// request otherwise takes the oldest long plan's thread at once (that plan is asked to stop) or
// waits for an ordinary one to end; a long request never waits and never preempts.
#include "../../src/ros/plan_slots.h"

#include <gtest/gtest.h>

#include <chrono>
#include <future>
#include <thread>

namespace roomba_rrt::planner_node {
namespace {

using std::chrono::milliseconds;
using Clock = PlanSlots::Clock;

/// A long plan: holds its thread until asked to stop (at most 5 s); true when it was asked.
std::future<bool> longPlan(PlanSlots& slots) {
  auto future = std::async(std::launch::async, [&slots] {
    PlanSlots::Lease lease = slots.acquireLong();
    if (!lease) return false;
    const auto give_up = Clock::now() + std::chrono::seconds(5);
    while (!lease.stopRequested() && Clock::now() < give_up) {
      std::this_thread::sleep_for(milliseconds(1));
    }
    return lease.stopRequested();
  });
  std::this_thread::sleep_for(milliseconds(20));  // it has its thread by now
  return future;
}

TEST(PlanSlots, a_free_thread_is_had_at_once_and_a_long_request_never_waits) {
  PlanSlots slots(2);
  PlanSlots::Lease a = slots.acquireLong();
  PlanSlots::Lease b = slots.acquireOrdinary(Clock::now());
  EXPECT_TRUE(a);
  EXPECT_TRUE(b);
  const auto t0 = Clock::now();
  EXPECT_FALSE(slots.acquireLong());  // busy at once
  EXPECT_LT(Clock::now() - t0, milliseconds(50));
  EXPECT_FALSE(a.stopRequested());
  EXPECT_EQ(slots.preemptions(), 0);
}

TEST(PlanSlots, an_ordinary_request_takes_the_oldest_long_plans_thread) {
  PlanSlots slots(2);
  std::future<bool> first = longPlan(slots);
  std::future<bool> second = longPlan(slots);
  PlanSlots::Lease ordinary = slots.acquireOrdinary(Clock::now() + std::chrono::seconds(2));
  EXPECT_TRUE(ordinary);
  EXPECT_TRUE(first.get()) << "the oldest long plan was not asked to stop";
  EXPECT_EQ(second.wait_for(milliseconds(0)), std::future_status::timeout)
      << "the younger long plan was stopped too";
  EXPECT_EQ(slots.preemptions(), 1);
  EXPECT_FALSE(ordinary.stopRequested());
  PlanSlots::Lease another = slots.acquireOrdinary(Clock::now() + std::chrono::seconds(2));
  EXPECT_TRUE(another);  // the second long plan goes next
  EXPECT_TRUE(second.get());
}

TEST(PlanSlots, an_ordinary_request_does_not_wait_for_the_preempted_plan_to_stop) {
  PlanSlots slots(1);
  auto held = std::make_unique<PlanSlots::Lease>(slots.acquireLong());  // never looks at stop
  ASSERT_TRUE(*held);
  // No time to wait at all: the thread is handed over at once.
  PlanSlots::Lease ordinary = slots.acquireOrdinary(Clock::now());
  ASSERT_TRUE(ordinary);
  EXPECT_TRUE(held->stopRequested());
  EXPECT_FALSE(ordinary.stopRequested());
  EXPECT_EQ(slots.preemptions(), 1);
  // The preempted plan ending late gives back nothing: the thread is the ordinary plan's.
  held.reset();
  EXPECT_FALSE(slots.acquireLong());
  EXPECT_FALSE(slots.acquireOrdinary(Clock::now()));
  EXPECT_FALSE(ordinary.stopRequested());
}

TEST(PlanSlots, ordinary_plans_are_never_preempted_a_newcomer_waits_for_one_to_end) {
  PlanSlots slots(1);
  auto held = std::make_unique<PlanSlots::Lease>(slots.acquireOrdinary(Clock::now()));
  std::thread release([&held] {
    std::this_thread::sleep_for(milliseconds(50));
    held.reset();
  });
  EXPECT_TRUE(slots.acquireOrdinary(Clock::now() + std::chrono::seconds(2)));  // waited for it
  release.join();
  EXPECT_EQ(slots.preemptions(), 0);
  PlanSlots::Lease busy = slots.acquireOrdinary(Clock::now());
  EXPECT_TRUE(busy);
  EXPECT_FALSE(slots.acquireOrdinary(Clock::now() + milliseconds(30)));  // its budget ran out
}

}  // namespace
}  // namespace roomba_rrt::planner_node
