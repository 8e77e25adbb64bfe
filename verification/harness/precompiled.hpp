// The headers most verification programs include, compiled once into a precompiled header (the
// Makefile: VERIFY_PCH) that every verify_*.cpp is compiled with, in front of its own includes.
// Only a build accelerator: each program still includes what it uses and compiles without it.
// (No include guard: it is only ever the first thing of a unit, and GCC warns about #pragma once in
// a header compiled on its own.)

#include "closures/closures.hpp"
#include "flow/flow_solver.hpp"
#include "harness/check_table.hpp"
#include "harness/flow_reference.hpp"
#include "harness/program.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <functional>
#include <random>
#include <sstream>
#include <string>
#include <vector>
