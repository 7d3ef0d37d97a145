#include "geometry/import/import_guard.h"

#include <gtest/gtest.h>

namespace bz::geo::detail {
namespace {

TEST(ImportGuard, RefusesOffCountsThatCannotFit) {
    EXPECT_TRUE(implausible_off_header("OFF\n353535235358 6 0\n", 309).has_value());
    EXPECT_TRUE(implausible_off_header("OFF 8 6000 0\n", 200).has_value());
    EXPECT_TRUE(implausible_off_header("# comment\nCOFF\n18446744073709551615 1 0", 100));
}

TEST(ImportGuard, AcceptsPlausibleOffAndOtherFormats) {
    EXPECT_FALSE(implausible_off_header("OFF\n8 6 0\n", 300).has_value());
    EXPECT_FALSE(implausible_off_header("OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", 40));
    EXPECT_FALSE(implausible_off_header("v 1 2 3\nf 1 2 3\n", 10).has_value());  // OBJ
    EXPECT_FALSE(implausible_off_header("OFF\nnot numbers\n", 10).has_value());
    EXPECT_FALSE(implausible_off_header("", 0).has_value());
}

}  // namespace
}  // namespace bz::geo::detail
