#pragma once
// A render header (architecture_test fixture): core below it is allowed.
#include "core/bad.hpp"
