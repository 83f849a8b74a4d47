#pragma once
// A deliberate violation for architecture_test: a folder with no level.
