// FreeSpaceSampler::sample is defined inline in its header: the planner calls it every
// iteration, and inline it costs no call (a shared library cannot inline its exported functions).
#include "roomba_rrt/planning/free_space_sampler.h"
