#pragma once
// A deliberate violation for architecture_test: core includes render.
#include "render/x.hpp"
