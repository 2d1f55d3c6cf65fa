// The precompiled header of the tests (tests/CMakeLists.txt): what nearly every test includes,
// parsed once per build instead of once per test file. Only third-party and standard headers,
// so that a change to eyetrace's own headers does not rebuild it; each test still includes what
// it uses.
#pragma once
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <glm/glm.hpp>
