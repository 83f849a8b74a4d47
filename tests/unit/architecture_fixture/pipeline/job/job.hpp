#pragma once
// The job (architecture_test fixture): storage below it is allowed.
#include "store/bad.hpp"
