// option_domain_test.cpp: numeric option domains (app/option_domain.h): what
// parses as a number of each kind, how a bound prints, and the refusals.
#include "app/option_domain.h"

#include <cmath>
#include <string>

#include <gtest/gtest.h>

namespace st {

TEST(OptionDomain, RealsAreWholeStrings) {
    EXPECT_EQ(option_real("1.5"), 1.5);
    EXPECT_EQ(option_real("-0"), 0.0);
    EXPECT_TRUE(option_real("1e-320").has_value());  // a denormal is a number; domains decide
    EXPECT_TRUE(std::isnan(*option_real("nan")));
    for (const char* bad : {"", " 1", "1 ", "1x", "1,5", "--1"}) EXPECT_FALSE(option_real(bad).has_value()) << bad;
}

TEST(OptionDomain, IntegersAreWholeDecimalStrings) {
    EXPECT_EQ(option_integer("2048"), 2048);
    EXPECT_EQ(option_integer("-0"), 0);
    EXPECT_EQ(option_integer("9223372036854775807"), 9223372036854775807LL);
    for (const char* bad : {"", "1.5", "1e6", "9223372036854775808", "-9223372036854775809", "0x10", " 1", "inf", "nan"})
        EXPECT_FALSE(option_integer(bad).has_value()) << bad;
}

TEST(OptionDomain, BoundsPrintShort) {
    EXPECT_EQ(domain_number(1e9), "1e9");
    EXPECT_EQ(domain_number(1e-12), "1e-12");
    EXPECT_EQ(domain_number(1e-9), "1e-9");
    EXPECT_EQ(domain_number(0.01), "0.01");
    EXPECT_EQ(domain_number(100), "100");
    EXPECT_EQ(domain_number(1e7), "10000000");
}

TEST(OptionDomain, RefusalsNameTheDomain) {
    const OptionDomain d = reals_in(0.0, 1e9, "per mm");
    EXPECT_EQ(d.text, "[0, 1e9] per mm");
    std::string v = "2e9";
    EXPECT_EQ(d.check()(v), "'2e9' is outside its domain, [0, 1e9] per mm");
    for (std::string in : {"0", "-0", "1e-320", "1e9"}) EXPECT_EQ(d.check()(in), "") << in;
    for (std::string out : {"-1", "inf", "nan", "1e308", "-1e-320"}) EXPECT_NE(d.check()(out), "") << out;
    std::string empty;
    EXPECT_EQ(d.check()(empty), "an empty value is not a number; its domain is [0, 1e9] per mm");
    const OptionDomain n = integers_in(1, 256);
    for (std::string out : {"0", "257", "1.5", "2147483648"}) EXPECT_NE(n.check()(out), "") << out;
    std::string one = "1";
    EXPECT_EQ(n.check()(one), "");
}

}  // namespace st
