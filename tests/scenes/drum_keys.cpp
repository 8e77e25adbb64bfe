// The two drum kinds accept each other's names for the rotation rate and the fill
// (scenes/drum_keys.hpp): rotation_rate = rps, fill_fraction = fill_height / height; a file with
// both names of one thing fails naming the other.
#include "core/error.hpp"
#include "run/scene_file.hpp"
#include "scenes/flow_scenes.hpp"
#include "scenes/tumbler_kinematic.hpp"

#include <boost/test/unit_test.hpp>

#include <string>

using namespace granseg;

namespace {

const std::string kKinematic = "[time]\nend = 1\n[drum]\n";

bool fails_naming(const std::string& text, const std::string& key) {
    try {
        read_tumbler_kinematic(SceneFile::parse(kKinematic + text, "k.toml"));
    } catch (const InputError& e) {
        return std::string(e.what()).find("[drum] " + key + ":") != std::string::npos;
    }
    return false;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(scenes_drum_keys_tests)

BOOST_AUTO_TEST_CASE(the_kinematic_drum_reads_the_coupled_drums_names) {
    const auto own =
        read_tumbler_kinematic(SceneFile::parse(kKinematic + "rotation_rate = 0.2\nfill_fraction = 0.6\n", "k.toml"));
    const auto other = read_tumbler_kinematic(SceneFile::parse(kKinematic + "rps = 0.2\nfill_height = 0.06\n", "k.toml"));
    BOOST_TEST(other.setup.drum.rotation_rate == own.setup.drum.rotation_rate);
    BOOST_TEST(other.setup.drum.fill_fraction == own.setup.drum.fill_fraction, boost::test_tools::tolerance(1e-15));
    BOOST_TEST(fails_naming("rps = 0.2\nrotation_rate = 0.2\n", "rps"));
    BOOST_TEST(fails_naming("fill_height = 0.2\n", "fill_height"));  // out of range: above the diameter
    BOOST_TEST(fails_naming("rps = 0\n", "rps"));                    // no flow, named by the key the file uses
}

BOOST_AUTO_TEST_CASE(the_coupled_drum_reads_the_kinematic_drums_names) {
    const DrumSpec own = read_drum(SceneFile::parse("[drum]\nrps = 0.3\nfill_height = 0.05\n", "c.toml"));
    const DrumSpec other = read_drum(SceneFile::parse("[drum]\nrotation_rate = 0.3\nfill_fraction = 0.5\n", "c.toml"));
    BOOST_TEST(other.rps == own.rps);
    BOOST_TEST(other.fill_height == own.fill_height, boost::test_tools::tolerance(1e-15));
    BOOST_CHECK_THROW(read_drum(SceneFile::parse("[drum]\nfill_height = 0.05\nfill_fraction = 0.5\n", "c.toml")), InputError);
}

BOOST_AUTO_TEST_SUITE_END()
