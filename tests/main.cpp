// Boost.Test entry point of the unit tests (`make test`). Each tests/test_*.cpp adds suites.
#define BOOST_TEST_MODULE granseg
#include <boost/test/unit_test.hpp>
