// Output files (run/output.hpp): data tables name their columns first, and a file is written
// whole or not at all.
#include "run/output.hpp"
#include "core/error.hpp"

#include <boost/test/unit_test.hpp>

#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

using namespace granseg;

BOOST_AUTO_TEST_SUITE(run_output_tests)

BOOST_AUTO_TEST_CASE(data_table_names_its_columns_first) {
    DataTable t;
    t.comment("source: test");
    t.row({{"z", 0.5}, {"phi", 0.25}});
    BOOST_TEST(t.str() == "# z phi\n# source: test\n0.5 0.25\n");
    BOOST_CHECK_THROW(t.row({{"z", 1.0}}), InvariantError);                 // a column missing
    BOOST_CHECK_THROW(t.row({{"phi", 0.25}, {"z", 0.5}}), InvariantError);  // columns swapped
    TableRow r{{"z", 1.0}};
    t.row(r.add("phi", 0.5));
    BOOST_TEST(t.rows() == 2u);
}

BOOST_AUTO_TEST_CASE(atomic_write_creates_directories_and_leaves_no_temporary) {
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / ("granseg_core_" + std::to_string(::getpid()));
    write_file_atomically((dir / "a" / "b.dat").string(), "x\n");
    std::ifstream in(dir / "a" / "b.dat");
    std::string line;
    std::getline(in, line);
    BOOST_TEST(line == "x");
    int files = 0;
    for (const auto& e : fs::directory_iterator(dir / "a")) files += e.is_regular_file();
    BOOST_TEST(files == 1);
    fs::remove_all(dir);
}

BOOST_AUTO_TEST_SUITE_END()
