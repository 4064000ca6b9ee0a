// SPDX-License-Identifier: GPL-2.0-or-later
// genhexkins mathematics (kernel/kins/kins_genhex_fp.c): kinematics.md section 6.
#include "kins_test_util.hpp"

namespace {

kins_genhex defaults()
{
    kins_genhex g{};
    kins_genhex_defaults(&g);
    return g;
}

struct Row {
    EmcPose w;
    double struts[6];
};
const Row rows[] = {
    {pose(0, 0, 20), {29.746680, 29.746680, 29.746715, 29.746363, 29.746363, 29.746715}},
    {pose(1, 2, 20, 5, -3, 10), {29.609853, 31.186948, 26.903655, 32.985476, 28.709495, 29.864053}},
    {pose(-2, 1, 25, 0, 4, -6), {32.813711, 33.766639, 33.878405, 32.165158, 35.835040, 31.934475}},
};

TEST(Genhexkins, InverseVectors)
{
    kins_genhex g = defaults();
    for (const Row& r : rows) {
        Joints j{};
        ASSERT_EQ(kins_genhex_inverse(&g, &r.w, j.data(), nullptr), 0);
        for (int i = 0; i < 6; ++i)
            EXPECT_NEAR(j[i], r.struts[i], 1e-6) << "strut " << i;
    }
}

TEST(Genhexkins, ForwardFromTheDefaultGuessConvergesQuickly)
{
    kins_genhex g = defaults();
    for (const Row& r : rows) {
        Joints j{};
        kins_genhex_inverse(&g, &r.w, j.data(), nullptr);  // exact lengths, not 6 decimals
        EmcPose w = pose(0, 0, 20);
        unsigned it = 0;
        ASSERT_EQ(kins_genhex_forward(&g, j.data(), &w, &it), 0);
        expect_pose_near(w, r.w, 1e-7);
        EXPECT_LE(it, 30u);
    }
}

TEST(Genhexkins, ForwardFailures)
{
    kins_genhex g = defaults();
    Joints j = joints({30, 30, 30, 0, 30, 30});
    EmcPose w = pose(0, 0, 20);
    unsigned it = 0;
    EXPECT_EQ(kins_genhex_forward(&g, j.data(), &w, &it), -1);  // a joint <= 0
    j = joints({29.7, 29.7, 29.7, 29.7, 29.7, 29.7});
    g.limit_iterations = 1;
    w = pose(1, 1, 25, 3, 3, 3);
    EXPECT_EQ(kins_genhex_forward(&g, j.data(), &w, &it), -5);
    g = defaults();
    g.max_error = 0.001;
    w = pose(1, 1, 25, 3, 3, 3);
    EXPECT_EQ(kins_genhex_forward(&g, j.data(), &w, &it), -2);
}

TEST(Genhexkins, RoundTripsOverRandomPosesWithOffsetsAndScrewLead)
{
    Lcg rng{8};
    for (double lead : {0.0, 5.0}) {
        kins_genhex g = defaults();
        g.screw_lead = lead;
        g.z_offset = 1.5;
        for (int n = 0; n < 100; ++n) {
            EmcPose w = pose(rng.uniform(-3, 3), rng.uniform(-3, 3), rng.uniform(18, 26),
                             rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-10, 10));
            Joints j{};
            double corr[6];
            kins_genhex_inverse(&g, &w, j.data(), corr);
            if (lead == 0.0) {
                for (double c : corr)
                    EXPECT_EQ(c, 0.0);
            }
            EmcPose back = pose(0, 0, 22);
            unsigned it = 0;
            ASSERT_EQ(kins_genhex_forward(&g, j.data(), &back, &it), 0) << n;
            expect_pose_near(back, w, 1e-6);
        }
    }
}

}  // namespace
