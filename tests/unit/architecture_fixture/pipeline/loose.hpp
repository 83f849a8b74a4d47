#pragma once
// A deliberate violation for architecture_test: a source outside every folder.
