// CollisionChecker is defined inline in its header: its tests run once or more per planner
// iteration, and an out-of-line call (which the shared library cannot inline) would cost as much
// as the test itself.
#include "roomba_rrt/planning/collision_checker.h"
