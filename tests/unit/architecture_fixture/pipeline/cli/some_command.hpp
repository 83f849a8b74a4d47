#pragma once
// A command (architecture_test fixture): it may include anything below it.
#include "store/bad.hpp"
#include "job/job.hpp"
