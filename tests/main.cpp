// Boost.Test entry point of the unit tests (`make test`). Each tests/ROOM/SUBJECT.cpp (ROOM a folder of src/, or harness/ for
// the verification harness) adds one suite, ROOM_SUBJECT_tests (SUBJECT_tests where SUBJECT begins with ROOM).
#define BOOST_TEST_MODULE granseg
#include <boost/test/unit_test.hpp>
