#pragma once
// A deliberate violation for architecture_test: storage includes a command.
#include "cli/some_command.hpp"
