// measured_costs_test.cpp: the sweeps' tables parse, cover every candidate
// quality: auto may try, and order it as measured.
#include "app/quality/measured_costs.h"

#include <stdexcept>

#include <gtest/gtest.h>

#include "app/quality/relief_quality.h"
#include "app/quality/thin_slab_quality.h"

namespace st::measured_costs {
namespace {

// Every search setting of every relief row has a time at every angle the
// sweep ran, so no scene can meet a candidate the table lacks.
TEST(MeasuredCosts, TheReliefSweepTimedEveryCandidate) {
    for (const char* row : {"relief", "two-layer", "occlusion", "absorption"})
        for (const ReliefSetting& s : relief_search_settings(row))
            for (double angle : {0.0, 30.0, 45.0, 52.5, 85.0, 89.0}) {
                const double ms = relief_search_ms(s, angle);
                EXPECT_GT(ms, 0) << row << " " << s.label() << " at " << angle;
            }
    for (const char* variant : {"vertex", "host", "fragment"})
        for (double quads : {1.0, 12.0, 1408.0, 1e6}) EXPECT_GT(thin_slab_variant_ms(variant, quads), 0) << variant;
    EXPECT_NE(provenance().find("shadertwin"), std::string::npos) << provenance();
    EXPECT_EQ(fingerprint().size(), 16u);
}

TEST(MeasuredCosts, ReliefTimesAreInterpolatedBetweenAngles) {
    const std::vector<ReliefRow> table = parse_relief_table(
        "# made by: a test\n"
        "angle_deg,linear_steps,min_linear_steps,binary_steps,secant,cpu_ms_median,other\n"
        "30,16,0,6,1,10,x\n60,16,0,6,1,40,x\n30,8,0,0,0,5,x\n");
    ReliefSetting s;
    s.linear_steps = 16, s.binary_steps = 6, s.secant = true;
    EXPECT_EQ(relief_search_ms(table, s, 30), 10);
    EXPECT_EQ(relief_search_ms(table, s, 45), 25);
    EXPECT_EQ(relief_search_ms(table, s, 10), 10);  // outside: the nearest angle's
    EXPECT_EQ(relief_search_ms(table, s, 80), 40);
    s.secant = false;
    EXPECT_THROW(relief_search_ms(table, s, 45), std::logic_error);
}

TEST(MeasuredCosts, ThinSlabTimesAreTheNearestMeshsAveragedOverPaths) {
    const std::vector<ThinSlabRow> table = parse_thin_slab_table(
        "light,columns,rows,variant,cpu_ms_median\n"
        "backlit,4,3,vertex,1\nfrontlit,4,3,vertex,3\nbacklit,44,32,vertex,10\nbacklit,44,32,fragment,20\n");
    EXPECT_EQ(thin_slab_variant_ms(table, "vertex", 12), 2);     // 4 x 3, two paths
    EXPECT_EQ(thin_slab_variant_ms(table, "vertex", 100), 2);    // nearer 12 than 1408 on a log scale
    EXPECT_EQ(thin_slab_variant_ms(table, "vertex", 200), 10);   // nearer 1408
    EXPECT_EQ(thin_slab_variant_ms(table, "fragment", 1), 20);   // its only mesh
    EXPECT_THROW(thin_slab_variant_ms(table, "host", 12), std::logic_error);
}

TEST(MeasuredCosts, MalformedTablesAreRefused) {
    EXPECT_THROW(parse_relief_table(""), std::invalid_argument);
    EXPECT_THROW(parse_relief_table("angle_deg,linear_steps\n30,16\n"), std::invalid_argument);
    EXPECT_THROW(parse_relief_table("angle_deg,linear_steps,min_linear_steps,binary_steps,secant,cpu_ms_median\n"
                                    "30,16,0,6,1,fast\n"),
                 std::invalid_argument);
    EXPECT_THROW(parse_thin_slab_table("light,columns,rows,variant,cpu_ms_median\nbacklit,4.5,3,vertex,1\n"),
                 std::invalid_argument);
    EXPECT_THROW(parse_thin_slab_table("light,columns,rows,variant,cpu_ms_median\nbacklit,4,3,vertex,nan\n"),
                 std::invalid_argument);
}

// The thin slab's variants are tried in the measured order, at any mesh.
TEST(MeasuredCosts, ThinSlabVariantsAreTriedCheapestFirst) {
    for (int quads : {1, 12, 88, 1408, 22528, 1000000}) {
        const auto order = thin_slab_cost_order(quads);
        ASSERT_EQ(order.size(), 3u);
        for (size_t i = 0; i < order.size(); ++i) {
            EXPECT_EQ(order[i].second, thin_slab_variant_ms(order[i].first, quads));
            if (i > 0) EXPECT_LE(order[i - 1].second, order[i].second);
        }
    }
}

}  // namespace
}  // namespace st::measured_costs
