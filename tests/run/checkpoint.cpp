// Checkpoints (run/state_io.hpp, run/checkpoint_file.hpp): values come back bit for bit, a
// state read with another list of members is refused, a checkpoint file that is truncated,
// corrupted or of another format is refused with one line, a failed write (disk full, a
// directory that cannot be written) keeps the previous file; and the solvers continue to the bit:
// a drum saved after some steps, restored into a new one and stepped on equals the drum that
// was never stopped (which catches a member a step reads and checkpoint() forgot).
#include "core/error.hpp"
#include "core/threads.hpp"
#include "coupled/coupled_tumbler.hpp"
#include "kinematic/kinematic_tumbler.hpp"
#include "run/checkpoint_file.hpp"
#include "run/state_io.hpp"

#include <boost/test/unit_test.hpp>

#include <sys/resource.h>

#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

using namespace granseg;
namespace fs = std::filesystem;

BOOST_AUTO_TEST_SUITE(run_checkpoint_tests)

namespace {

/// Some members of each kind StateIO handles.
struct Sample {
    double x = 0;
    long n = 0;
    bool flag = false;
    StepBound bound = StepBound::cfl;
    std::vector<double> v;
    std::array<std::vector<double>, 3> a;
    std::string text;
    Eigen::VectorXd e;
    void checkpoint(StateIO& io) { io("x", x)("n", n)("flag", flag)("bound", bound)("v", v)("a", a)("text", text)("e", e); }
};

Sample filled() {
    Sample s;
    s.x = std::nextafter(0.1, 1.0), s.n = -42, s.flag = true, s.bound = StepBound::halved;
    s.v = {1.0 / 3.0, -0.0, std::numeric_limits<double>::denorm_min(), NAN};
    s.a[2] = {2.5};
    s.text = std::string("binary\0text", 11);
    s.e = Eigen::VectorXd::LinSpaced(5, 0.0, 1.0);
    return s;
}

std::string saved(Sample s) {
    StateIO io;
    s.checkpoint(io);
    return io.bytes();
}

std::string message_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

std::string file_text(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

Checkpoint example_checkpoint(double t) {
    Checkpoint c;
    c.kind = "tumbler", c.program = "0123456789abcdef", c.scene = "fedcba9876543210", c.t = t, c.steps = 7;
    c.blocks = {{"scene", "[run] t_end = 25\n"}, {"state", saved(filled())}};
    return c;
}

fs::path scratch(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("granseg_test_checkpoint_" + std::to_string(::getpid())) / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

}  // namespace

BOOST_AUTO_TEST_CASE(values_come_back_bit_for_bit) {
    const std::string bytes = saved(filled());
    Sample back;
    StateIO io(bytes, "test");
    back.checkpoint(io);
    io.expect_end();
    BOOST_TEST((saved(back) == bytes));  // NaN and -0 included: compared as bytes
    BOOST_TEST(back.v.size() == 4u);
    BOOST_TEST(std::signbit(back.v[1]));
    BOOST_TEST(back.text.size() == 11u);
}

BOOST_AUTO_TEST_CASE(another_list_of_members_is_refused) {
    const std::string bytes = saved(filled());
    struct Other {
        double x = 0, y = 0;
        void checkpoint(StateIO& io) { io("x", x)("y", y); }
    } other;
    StateIO io(bytes, "ck");
    BOOST_TEST(contains(message_of([&] { other.checkpoint(io); }), "ck: the state holds \"n\" where this program reads \"y\""));
    StateIO cut(bytes.substr(0, bytes.size() - 3), "ck");
    Sample s;
    BOOST_TEST(contains(message_of([&] { s.checkpoint(cut); }), "ends inside \"e\""));
    StateIO longer(bytes + saved(filled()), "ck");
    s.checkpoint(longer);
    BOOST_TEST(contains(message_of([&] { longer.expect_end(); }), "were not read"));
}

BOOST_AUTO_TEST_CASE(a_file_round_trips_and_a_damaged_one_is_refused) {
    const fs::path dir = scratch("file");
    const std::string path = (dir / "checkpoint.gsc").string();
    write_checkpoint(path, example_checkpoint(1.5));
    const Checkpoint c = read_checkpoint(path);
    BOOST_TEST(c.kind == "tumbler");
    BOOST_TEST(c.t == 1.5);
    BOOST_TEST(c.steps == 7);
    BOOST_TEST(!c.finished);
    BOOST_TEST((c.block("state", path) == saved(filled())));
    BOOST_TEST(!fs::exists(path + ".tmp." + std::to_string(::getpid())));

    const std::string whole = file_text(path);
    const auto refused = [&](const std::string& text) {
        const std::string damaged = (dir / "damaged.gsc").string();
        std::ofstream(damaged, std::ios::binary) << text;
        const std::string m = message_of([&] { read_checkpoint(damaged); });
        BOOST_TEST(m.find('\n') == std::string::npos);
        BOOST_TEST(contains(m, damaged + ": "));
        return m;
    };
    BOOST_TEST(contains(refused(whole.substr(0, whole.size() - 100)), "truncated: "));
    BOOST_TEST(contains(refused(whole.substr(0, 30)), "truncated inside its header"));
    std::string flipped = whole;
    flipped[flipped.size() - 40] ^= 0x10;  // one bit of a double of the state
    BOOST_TEST(contains(refused(flipped), "corrupted: its checksum does not match"));
    std::string later = whole;
    later.replace(later.find("t 1.5"), 5, "t 2.5");  // the header is covered by the checksum too
    BOOST_TEST(contains(refused(later), "corrupted"));
    std::string format = whole;
    format.replace(format.find("format 1"), 8, "format 9");
    BOOST_TEST(contains(refused(format), "checkpoint format 9, this granseg reads format 1"));
    BOOST_TEST(contains(refused("# t Phi\n0 0.5\n"), "not a granseg checkpoint"));
    BOOST_TEST(contains(message_of([&] { read_checkpoint((dir / "none.gsc").string()); }), "cannot open"));
}

BOOST_AUTO_TEST_CASE(a_failed_write_keeps_the_previous_checkpoint) {
    const fs::path dir = scratch("full");
    const std::string path = (dir / "checkpoint.gsc").string();
    write_checkpoint(path, example_checkpoint(1.0));
    const std::string before = file_text(path);
    // A full disk: the file size limit makes write() fail with EFBIG, as ENOSPC would.
    rlimit old{};
    getrlimit(RLIMIT_FSIZE, &old);
    const auto handler = std::signal(SIGXFSZ, SIG_IGN);
    rlimit small = old;
    small.rlim_cur = 4096;
    setrlimit(RLIMIT_FSIZE, &small);
    Checkpoint big = example_checkpoint(2.0);
    big.blocks.emplace_back("padding", std::string(100000, 'x'));
    const std::string m = message_of([&] { write_checkpoint(path, big); });
    setrlimit(RLIMIT_FSIZE, &old);
    std::signal(SIGXFSZ, handler);
    BOOST_TEST(contains(m, "cannot write the checkpoint " + path + ": File too large (the previous checkpoint there is kept)"));
    BOOST_TEST((file_text(path) == before));
    BOOST_TEST(read_checkpoint(path).t == 1.0);
    long left = 0;
    for (const auto& e : fs::directory_iterator(dir)) left += e.path().filename() != "checkpoint.gsc";
    BOOST_TEST(left == 0);  // no temporary file left behind
    // A directory that cannot be written (procfs refuses new files, also to root).
    const std::string m2 = message_of([&] { write_checkpoint("/proc/granseg_checkpoint/checkpoint.gsc", big); });
    BOOST_TEST(contains(m2, "cannot write the checkpoint /proc/granseg_checkpoint/checkpoint.gsc: cannot create the directory"));
    if (::geteuid() != 0) {  // permissions do not hold root back
        fs::permissions(dir, fs::perms::owner_read | fs::perms::owner_exec);
        const std::string m3 = message_of([&] { write_checkpoint(path, big); });
        fs::permissions(dir, fs::perms::owner_all);
        BOOST_TEST(contains(m3, "Permission denied (the previous checkpoint there is kept)"));
        BOOST_TEST((file_text(path) == before));
    }
    fs::remove_all(dir.parent_path());
}

namespace {

/// Saves `object`, restores it into `fresh`, and returns the bytes of both: equal if the restore
/// took every saved member (the timers, wall-clock seconds, come back as saved too).
template <class T>
std::string save(T& object) {
    StateIO io;
    object.checkpoint(io);
    return io.bytes();
}

template <class T>
void restore(T& object, const std::string& bytes) {
    StateIO io(bytes, "test");
    object.checkpoint(io);
    io.expect_end();
}

/// What the coupled drum's steps produce, without the wall-clock timers.
std::vector<std::vector<double>> observed(const CoupledTumbler& t) {
    const FlowSolver& f = t.flow();
    return {f.Phi(),
            f.Phi_before(),
            f.u(0),
            f.u(2),
            f.T(),
            f.mass_flux(0),
            f.mass_flux(2),
            t.phi(),
            t.tracer(),
            t.frozen().a[0],
            t.frozen().a[2],
            t.d_s(0),
            t.d_s(2),
            {f.time(), f.last_dt(), double(f.steps()), double(f.counters().newton), double(f.counters().krylov),
             double(f.counters().temperature_iterations), double(t.split_segregation_steps()),
             double(t.segregation_solver_steps()), t.largest_correction(), t.max_excess(), t.min_phi(), t.largest_bulk_clip()}};
}

/// A small segregating drum with a tracer: `before` steps, saved; then `after` steps of the
/// drum itself and of a new drum restored from the save, on `threads` threads after the save.
void continues_to_the_bit(CoupledTumblerSetup setup, int before, int after, int threads) {
    setup.tracer0 = [](double x, double z) { return x * x + z * z < 1e-4 ? 1.0 : 0.0; };
    CoupledTumbler run(setup);
    for (int n = 0; n < before; ++n) run.step();
    const std::string bytes = save(run);
    const auto b = [&] {
        const ThreadScope scope(threads);
        CoupledTumbler resumed(setup);
        restore(resumed, bytes);
        BOOST_TEST((save(resumed) == bytes));
        for (int n = 0; n < after; ++n) run.step(), resumed.step();
        return observed(resumed);
    }();
    const auto a = observed(run);
    long differ = 0;
    for (std::size_t i = 0; i < a.size(); ++i) differ += a[i] != b[i];  // vector ==: bit for bit but NaN
    BOOST_TEST(differ == 0);
}

}  // namespace

BOOST_AUTO_TEST_CASE(coupled_drum_continues_to_the_bit) {
    CoupledTumblerSetup setup;
    setup.drum.cells_per_diameter = 26;
    continues_to_the_bit(setup, 60, 60, 1);
    setup.flow.time_stepping = TimeStepping::explicit_waves;  // the split viscosity, donor-cell transport
    continues_to_the_bit(setup, 40, 40, 1);
}

BOOST_AUTO_TEST_CASE(coupled_drum_saved_on_one_thread_continues_on_two) {
    CoupledTumblerSetup setup;
    setup.drum.cells_per_diameter = 92;  // the smallest grid that runs on threads (test_threads.cpp)
    continues_to_the_bit(setup, 4, 4, 2);
}

BOOST_AUTO_TEST_CASE(kinematic_drum_continues_to_the_bit) {
    KinematicTumblerSetup setup;
    setup.cells_per_diameter = 30;
    KinematicTumbler run(setup);
    for (int n = 0; n < 30; ++n) run.step(run.time_step());
    const std::string bytes = save(run);
    KinematicTumbler resumed(setup);
    restore(resumed, bytes);
    for (int n = 0; n < 30; ++n) run.step(run.time_step()), resumed.step(resumed.time_step());
    BOOST_TEST((run.phi() == resumed.phi()));
    BOOST_TEST(run.time() == resumed.time());
    BOOST_TEST(run.cell_updates() == resumed.cell_updates());
    BOOST_TEST((save(run) == save(resumed)));
}

BOOST_AUTO_TEST_SUITE_END()
