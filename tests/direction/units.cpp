// The units of S0 and B/c derived from eqs. (42), (45), (46) by a dimension check, not by hand:
// each quantity is a vector of exponents of metre and second, and the derived units must be the ones
// the code prints (kSegregationRateUnit, kLoadSharingOverDragUnit) and the pages state.
#include "direction/segregation_velocity.hpp"

#include <boost/test/unit_test.hpp>

#include <string>

namespace {

/// m^metre s^second, exponents in halves so that a square root stays exact.
struct Dimension {
    int metre2 = 0, second2 = 0;  // twice the exponents

    Dimension operator*(Dimension o) const { return {metre2 + o.metre2, second2 + o.second2}; }
    Dimension operator/(Dimension o) const { return {metre2 - o.metre2, second2 - o.second2}; }
};

Dimension sqrt_of(Dimension d) {
    BOOST_REQUIRE(d.metre2 % 2 == 0 && d.second2 % 2 == 0);  // a half-integer power would be no SI unit
    return {d.metre2 / 2, d.second2 / 2};
}

constexpr Dimension kOne{}, kMetre{2, 0}, kSecond{0, 2};

/// The unit as the code writes it: "s^2/m", "m/s^2", "s^2", "1/s".
std::string text_of(Dimension d) {
    auto power = [](const char* base, int twice) {
        const int e = twice / 2;
        return std::string(base) + (e == 1 ? "" : "^" + std::to_string(e));
    };
    std::string up, down;
    if (d.second2 > 0) up = power("s", d.second2);
    if (d.metre2 > 0) up = power("m", d.metre2) + (up.empty() ? "" : " " + up);
    if (d.metre2 < 0) down = power("m", -d.metre2);
    if (d.second2 < 0) down += (down.empty() ? "" : " ") + power("s", -d.second2);
    return (up.empty() ? "1" : up) + (down.empty() ? "" : "/" + down);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(direction_units_tests)

BOOST_AUTO_TEST_CASE(segregation_rate_and_load_sharing_get_their_units_from_the_equations) {
    const Dimension velocity = kMetre / kSecond, T = velocity * velocity, g = kMetre / (kSecond * kSecond),
                    gamma_dot = kOne / kSecond;
    // eq. (46): S^sl = -S0 sqrt(T) P g, P dimensionless  =>  S0 = [S^sl] / ([sqrt(T)] [g])
    const Dimension S0 = velocity / (sqrt_of(T) * g);
    // eq. (42): S^sl = -(B/c) gamma_dot P g  =>  B/c = [S^sl] / ([gamma_dot] [g])
    const Dimension B_over_c = velocity / (gamma_dot * g);
    // eq. (45): T = (3/2) (eta0/eps0) gamma_dot^2  =>  eps0/eta0 = [gamma_dot]^2 / [T]
    const Dimension eps0_over_eta0 = gamma_dot * gamma_dot / T;
    BOOST_TEST(text_of(S0) == granseg::kSegregationRateUnit);
    BOOST_TEST(text_of(B_over_c) == granseg::kLoadSharingOverDragUnit);
    BOOST_TEST(text_of(B_over_c * sqrt_of(eps0_over_eta0)) == text_of(S0));  // S0 = (B/c) sqrt((2/3) eps0/eta0), eq. (46)
    BOOST_TEST(text_of(g) == "m/s^2");                                       // the formatting itself, on known units
    BOOST_TEST(text_of(gamma_dot) == "1/s");
}

BOOST_AUTO_TEST_SUITE_END()
