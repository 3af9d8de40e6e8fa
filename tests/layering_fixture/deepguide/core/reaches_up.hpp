#pragma once
// A fixture for the layering test: core reaching up into planning.
#include "deepguide/planning/planner.hpp"
