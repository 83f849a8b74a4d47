#pragma once
// A deliberate violation for architecture_test: a reader of storage includes
// the job, a level above it.
#include "store/bad.hpp"
#include "job/job.hpp"
